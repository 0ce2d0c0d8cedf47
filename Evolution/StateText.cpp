#include "StateText.h"

#include <charconv>
#include <cmath>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <utility>

namespace thyrix {

namespace {

// Appends the parts in order (GCC 12 warns falsely on chains of std::string operator+).
template <class... Parts>
std::string concat(const Parts&... parts) {
  std::string out;
  (out.append(std::string_view(parts)), ...);
  return out;
}

}  // namespace

void StateWriter::integer(std::string_view key, std::uint64_t value) {
  out_ << key << ' ' << value << '\n';
}

void StateWriter::word(std::string_view key, std::string_view value) {
  out_ << key << ' ' << value << '\n';
}

void StateWriter::doubles(std::string_view key, std::span<const double> values) {
  out_ << key << ' ' << values.size();
  char buffer[64];
  for (double x : values) {
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::hex);
    out_ << ' ' << std::string_view(buffer, static_cast<std::size_t>(result.ptr - buffer));
  }
  out_ << '\n';
}

void StateReader::fail(const std::string& problem) const {
  throw std::runtime_error(concat(what_, ", line ", std::to_string(lineNumber_), ": ", problem));
}

std::vector<std::string_view> StateReader::fields(std::string_view key, std::size_t count) {
  ++lineNumber_;
  if (!std::getline(in_, line_)) fail(concat("ends early: expected '", key, "' (truncated file?)"));
  std::vector<std::string_view> words;
  std::string_view rest = line_;
  while (!rest.empty()) {
    const std::size_t start = rest.find_first_not_of(" \t\r");
    if (start == std::string_view::npos) break;
    rest.remove_prefix(start);
    const std::size_t stop = std::min(rest.find_first_of(" \t\r"), rest.size());
    words.push_back(rest.substr(0, stop));
    rest.remove_prefix(stop);
  }
  if (words.empty() || words[0] != key)
    fail(concat("expected '", key, "', found '",
                std::string(words.empty() ? std::string_view() : words[0]), "'"));
  if (words.size() != count + 1)
    fail(concat("'", key, "' needs ", std::to_string(count), " value(s), found ",
                std::to_string(words.size() - 1)));
  words.erase(words.begin());
  return words;
}

std::uint64_t StateReader::integer(std::string_view key, std::uint64_t most) {
  const std::string_view text = fields(key, 1)[0];
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value > most)
    fail(
        concat("'", key, "' needs a whole number <= ", std::to_string(most), ", not '", text, "'"));
  return value;
}

std::string StateReader::word(std::string_view key) { return std::string(fields(key, 1)[0]); }

std::vector<double> StateReader::doubles(std::string_view key, std::size_t count) {
  ++lineNumber_;
  if (!std::getline(in_, line_)) fail(concat("ends early: expected '", key, "' (truncated file?)"));
  // The count is checked before the values are read, so a corrupt count cannot allocate.
  const std::string expected = concat(key, " ", std::to_string(count));
  if (line_.compare(0, expected.size(), expected) != 0 ||
      (line_.size() > expected.size() && line_[expected.size()] != ' '))
    fail(concat("expected '", expected, " ...', found '", line_.substr(0, 40), "'"));
  std::vector<double> values;
  values.reserve(count);
  std::string_view rest = std::string_view(line_).substr(expected.size());
  while (!rest.empty()) {
    const std::size_t start = rest.find_first_not_of(" \t\r");
    if (start == std::string_view::npos) break;
    rest.remove_prefix(start);
    const std::size_t stop = std::min(rest.find_first_of(" \t\r"), rest.size());
    const std::string_view text = rest.substr(0, stop);
    rest.remove_prefix(stop);
    double x = 0;
    const auto [end, error] =
        std::from_chars(text.data(), text.data() + text.size(), x, std::chars_format::hex);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(x))
      fail(concat("'", key, "' has a value that is not a finite number: '", text, "'"));
    values.push_back(x);
  }
  if (values.size() != count)
    fail(concat("'", key, "' needs ", std::to_string(count), " values, found ",
                std::to_string(values.size())));
  return values;
}

void StateReader::end() {
  std::string rest;
  while (std::getline(in_, rest)) {
    ++lineNumber_;
    if (rest.find_first_not_of(" \t\r") != std::string::npos)
      fail(concat("unexpected text after the end: '", rest.substr(0, 40), "'"));
  }
}

MTRandom::State StateReader::randomStream() {
  MTRandom::State random;
  try {
    random = MTRandom::State::read(in_);
  } catch (const std::exception& error) {
    fail(std::string("random stream: ") + error.what());
  }
  in_ >> std::ws;
  return random;
}

}  // namespace thyrix
