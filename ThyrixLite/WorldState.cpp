/// @file WorldState.cpp
/// @brief The binary form of a world state.
#include <ThyrixLite/WorldState.h>

#include <array>
#include <istream>
#include <ostream>
#include <stdexcept>

namespace thyrix {
namespace {

constexpr std::array<char, 8> magic{'T', 'H', 'Y', 'R', 'I', 'X', 'W', 'S'};
// Bounds a corrupt length can ask for before the stream runs out (read in pieces).
constexpr std::size_t readPiece = std::size_t{1} << 16;

std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const char byte : bytes) {
    hash ^= static_cast<unsigned char>(byte);
    hash *= 1099511628211ull;
  }
  return hash;
}

// Little-endian, whatever the machine's order: a state written on one machine reads on another.
void putWord(std::string& out, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
}

std::uint64_t wordAt(const std::string& bytes, std::size_t at) {
  std::uint64_t value = 0;
  for (int i = 0; i < 8; ++i)
    value |= std::uint64_t{static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)])}
             << (8 * i);
  return value;
}

/// Reads @p count bytes, piece by piece (a corrupt count allocates no more than the stream has).
std::string readBytes(std::istream& in, std::uint64_t count, const char* what) {
  std::string bytes;
  while (bytes.size() < count) {
    const std::size_t piece =
        static_cast<std::size_t>(std::min<std::uint64_t>(readPiece, count - bytes.size()));
    const std::size_t at = bytes.size();
    bytes.resize(at + piece);
    in.read(bytes.data() + at, static_cast<std::streamsize>(piece));
    if (in.gcount() != static_cast<std::streamsize>(piece))
      throw std::runtime_error(std::string("WorldState.read: the stream is truncated in the ") +
                               what);
  }
  return bytes;
}

/// Reads the payload's words from position @p at, checking each against its end.
class PayloadReader {
 public:
  explicit PayloadReader(const std::string& bytes) : bytes_(bytes) {}
  std::uint64_t word(const char* what) {
    if (bytes_.size() - at_ < 8)
      throw std::runtime_error(std::string("WorldState.read: the payload ends in ") + what);
    const std::uint64_t value = wordAt(bytes_, at_);
    at_ += 8;
    return value;
  }
  std::string text(std::uint64_t length, const char* what) {
    if (bytes_.size() - at_ < length)
      throw std::runtime_error(std::string("WorldState.read: the payload ends in ") + what);
    std::string value = bytes_.substr(at_, static_cast<std::size_t>(length));
    at_ += static_cast<std::size_t>(length);
    return value;
  }
  [[nodiscard]] bool atEnd() const { return at_ == bytes_.size(); }
  [[nodiscard]] std::size_t wordsLeft() const { return (bytes_.size() - at_) / 8; }

 private:
  const std::string& bytes_;
  std::size_t at_ = 0;
};

}  // namespace

std::string WorldState::payload() const {
  std::string bytes;
  putWord(bytes, makeUp_.size());
  bytes += makeUp_;
  putWord(bytes, sections_.size());
  for (const StateRecord& section : sections_) {
    putWord(bytes, section.words().size());
    for (const std::uint64_t word : section.words()) putWord(bytes, word);
  }
  return bytes;
}

std::uint64_t WorldState::hash() const { return fnv1a(payload()); }

void WorldState::write(std::ostream& out) const {
  const std::string body = payload();
  std::string header(magic.begin(), magic.end());
  putWord(header, formatVersion);
  putWord(header, sizeof(real));
  putWord(header, body.size());
  std::string checksum;
  putWord(checksum, fnv1a(body));
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  out.write(body.data(), static_cast<std::streamsize>(body.size()));
  out.write(checksum.data(), static_cast<std::streamsize>(checksum.size()));
  if (!out) throw std::runtime_error("WorldState.write: the stream failed");
}

WorldState WorldState::read(std::istream& in) {
  const std::string header = readBytes(in, magic.size() + 24, "header");
  if (!std::equal(magic.begin(), magic.end(), header.begin()))
    throw std::runtime_error("WorldState.read: the stream is not a world state (no magic word)");
  const std::uint64_t version = wordAt(header, magic.size());
  if (version != formatVersion)
    throw std::runtime_error("WorldState.read: format version " + std::to_string(version) +
                             ", this build reads version " + std::to_string(formatVersion));
  const std::uint64_t realSize = wordAt(header, magic.size() + 8);
  if (realSize != sizeof(real))
    throw std::runtime_error("WorldState.read: saved with " + std::to_string(8 * realSize) +
                             "-bit reals, this build has " + std::to_string(8 * sizeof(real)));
  const std::uint64_t length = wordAt(header, magic.size() + 16);
  const std::string body = readBytes(in, length, "payload");
  const std::uint64_t checksum = wordAt(readBytes(in, 8, "checksum"), 0);
  if (checksum != fnv1a(body))
    throw std::runtime_error("WorldState.read: the checksum does not match (corrupt payload)");
  // (A payload that passes the checksum but is malformed was written by another program.)
  PayloadReader reader(body);
  WorldState state;
  state.makeUp_ = reader.text(reader.word("make-up length"), "make-up");
  const std::uint64_t sections = reader.word("section count");
  if (sections > reader.wordsLeft())
    throw std::runtime_error("WorldState.read: the payload ends in its sections");
  state.sections_.reserve(static_cast<std::size_t>(sections));
  for (std::uint64_t k = 0; k < sections; ++k) {
    const std::uint64_t count = reader.word("section length");
    if (count > reader.wordsLeft())
      throw std::runtime_error("WorldState.read: the payload ends in section " + std::to_string(k));
    std::vector<std::uint64_t> words(static_cast<std::size_t>(count));
    for (std::uint64_t& word : words) word = reader.word("a section");
    state.sections_.push_back(StateRecord::fromWords(std::move(words)));
  }
  if (!reader.atEnd())
    throw std::runtime_error("WorldState.read: the payload has bytes after its sections");
  return state;
}

}  // namespace thyrix
