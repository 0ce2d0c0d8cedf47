#pragma once
/// @file ProgressLine.h
/// @brief A run's progress on a terminal, redrawn in place, or as plain lines in a log.

#include <cstdint>
#include <cstdio>
#include <string>

namespace thyrix {

/// What a progress line shows.
struct Progress {
  std::uint64_t generation = 0;     ///< generations done
  std::uint64_t generations = 0;    ///< generations the run will do
  double best = 0;                  ///< best fitness of the last generation
  double mean = 0;                  ///< mean fitness of the last generation
  double bestSoFar = 0;             ///< best fitness of the run so far
  double evaluationsPerSecond = 0;  ///< episodes a second in the last generation
  double secondsLeft = 0;           ///< estimated time to the end (s)
};

/// The text of a progress line, e.g.
/// `gen 12/100  best 3.25  mean 1.07  best so far 3.31  812 evals/s  left 0:41`.
[[nodiscard]] std::string progressText(const Progress& progress);

/// Shows progress on @p out: when it is a terminal the line is redrawn in place (a carriage
/// return and an erase-line escape), else each update is a plain line of its own, so a log
/// file stays readable.
class ProgressLine {
 public:
  /// Writes to @p out (e.g. stdout), a terminal or not as isatty() says.
  explicit ProgressLine(std::FILE* out);
  /// Writes to @p out, as a terminal if @p terminal.
  ProgressLine(std::FILE* out, bool terminal) : out_(out), terminal_(terminal) {}
  /// Ends a line redrawn in place.
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// Shows @p progress.
  void update(const Progress& progress);
  /// Whether the line is redrawn in place.
  [[nodiscard]] bool terminal() const { return terminal_; }

 private:
  std::FILE* out_;
  bool terminal_;
  bool open_ = false;  // a line redrawn in place has no newline yet
};

}  // namespace thyrix
