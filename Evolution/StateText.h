#pragma once
/// @file StateText.h
/// @brief The text form of saved states (checkpoints): one `key values...` line per field,
/// floating-point values in hexadecimal so that a state is restored bit for bit.

#include <Tools/MTRandom.h>

#include <cstdint>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace thyrix {

/// Writes `key values...` lines. Doubles are written as C hexadecimal floats (exact, and
/// independent of the locale); integers and words as they are.
class StateWriter {
 public:
  /// Writes to @p out, which must outlive the writer.
  explicit StateWriter(std::ostream& out) : out_(out) {}
  /// `key value`
  void integer(std::string_view key, std::uint64_t value);
  /// `key word` (a word has no white space)
  void word(std::string_view key, std::string_view value);
  /// `key count v0 v1 ...`
  void doubles(std::string_view key, std::span<const double> values);

 private:
  std::ostream& out_;
};

/// Reads what StateWriter wrote, field by field in the same order; every mismatch throws
/// std::runtime_error saying where (`<what>, line N: ...`) and what was expected.
class StateReader {
 public:
  /// Reads from @p in; @p what names the source in messages (e.g. "checkpoint out/checkpoint").
  StateReader(std::istream& in, std::string what) : in_(in), what_(std::move(what)) {}
  /// The value of the next line, which must be `key value` with a whole number <= @p most.
  std::uint64_t integer(std::string_view key, std::uint64_t most = UINT64_MAX);
  /// The value of the next line, which must be `key word`.
  std::string word(std::string_view key);
  /// The values of the next line, which must be `key count v0 v1 ...` with @p count values,
  /// all finite.
  std::vector<double> doubles(std::string_view key, std::size_t count);
  /// The random stream's state that MTRandom::State::write() put next, and the input moved to
  /// the next line, for what follows the state in a larger file.
  MTRandom::State randomStream();
  /// Throws unless the input has nothing left but white space.
  void end();
  /// Throws std::runtime_error with @p problem, prefixed by the source and line.
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  std::vector<std::string_view> fields(std::string_view key, std::size_t count);

  std::istream& in_;
  std::string what_;
  std::string line_;
  std::size_t lineNumber_ = 0;
};

}  // namespace thyrix
