#include "ProgressLine.h"

#include <cmath>

#ifdef _WIN32
#include <io.h>
#define THYRIX_ISATTY(fd) _isatty(fd)
#define THYRIX_FILENO(f) _fileno(f)
#else
#include <unistd.h>
#define THYRIX_ISATTY(fd) isatty(fd)
#define THYRIX_FILENO(f) fileno(f)
#endif

namespace thyrix {

std::string progressText(const Progress& p) {
  const long left = std::isfinite(p.secondsLeft) && p.secondsLeft > 0
                        ? static_cast<long>(std::lround(p.secondsLeft))
                        : 0;
  char text[200];
  std::snprintf(text, sizeof text,
                "gen %llu/%llu  best %.6g  mean %.6g  best so far %.6g  %.0f evals/s  "
                "left %ld:%02ld",
                static_cast<unsigned long long>(p.generation),
                static_cast<unsigned long long>(p.generations), p.best, p.mean, p.bestSoFar,
                p.evaluationsPerSecond, left / 60, left % 60);
  return text;
}

ProgressLine::ProgressLine(std::FILE* out)
    : out_(out), terminal_(THYRIX_ISATTY(THYRIX_FILENO(out)) != 0) {}

ProgressLine::~ProgressLine() {
  if (open_) std::fputc('\n', out_);
  std::fflush(out_);
}

void ProgressLine::update(const Progress& progress) {
  const std::string text = progressText(progress);
  if (terminal_) {
    std::fprintf(out_, "\r%s\x1b[K", text.c_str());
    open_ = true;
  } else {
    std::fprintf(out_, "%s\n", text.c_str());
  }
  std::fflush(out_);
}

}  // namespace thyrix
