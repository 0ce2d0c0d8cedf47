#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/SvgAnimation.h>
#include <ThyrixLite/World.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace thyrix {

namespace {

// Nine significant digits: key times and durations exact enough, and short.
void appendNumber(std::string& out, double value) {
  char buffer[32];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 9);
  out.append(buffer, result.ptr);
}

}  // namespace

SvgAnimation::SvgAnimation(Vector2 lower, Vector2 upper, int widthPixels, double frameSeconds)
    : gui_(lower, upper, widthPixels), lower_(lower), upper_(upper), frameSeconds_(frameSeconds) {
  if (!(frameSeconds > 0) || !std::isfinite(frameSeconds))
    throw InvalidArgument("SvgAnimation.frameSeconds", "must be positive and finite");
}

void SvgAnimation::addFrame(const World& world, const DrawOptions& options,
                            std::string_view caption) {
  gui_.clear();
  drawWorld(world, gui_, options);
  if (!caption.empty()) {
    const real margin = (upper_.x - lower_.x) * real(0.02);
    gui_.drawText({lower_.x + margin, upper_.y - 2 * margin}, caption, colors::black);
  }
  frames_.push_back(gui_.elements());
}

std::string SvgAnimation::svg() const {
  SvgGUI empty = gui_;
  empty.clear();
  std::string document = empty.svg();
  const std::string end = "</svg>\n";
  document.resize(document.size() - end.size());
  const std::size_t n = frames_.size();
  std::string duration;
  appendNumber(duration, frameSeconds_ * static_cast<double>(n));
  for (std::size_t i = 0; i < n; ++i) {
    document += i == 0 ? "<g class=\"frame\">\n" : "<g class=\"frame\" visibility=\"hidden\">\n";
    if (n > 1) {
      // Discrete: each value holds from its key time to the next, so frame i shows during
      // [i / n, (i + 1) / n) of the loop.
      std::string values, times = "0";
      const double from = static_cast<double>(i) / static_cast<double>(n);
      const double to = static_cast<double>(i + 1) / static_cast<double>(n);
      if (i == 0) {
        values = "visible;hidden";
        times += ';';
        appendNumber(times, to);
      } else if (i + 1 == n) {
        values = "hidden;visible";
        times += ';';
        appendNumber(times, from);
      } else {
        values = "hidden;visible;hidden";
        times += ';';
        appendNumber(times, from);
        times += ';';
        appendNumber(times, to);
      }
      document += "<animate attributeName=\"visibility\" calcMode=\"discrete\" dur=\"" + duration +
                  "s\" repeatCount=\"indefinite\" values=\"" + values + "\" keyTimes=\"" + times +
                  "\"/>\n";
    }
    document += frames_[i];
    document += "</g>\n";
  }
  document += end;
  return document;
}

void SvgAnimation::save(const std::string& path) const {
  const std::string document = svg();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("SvgAnimation.save: cannot open '" + path + "'");
  out.write(document.data(), static_cast<std::streamsize>(document.size()));
  out.close();
  if (!out) throw std::runtime_error("SvgAnimation.save: cannot write '" + path + "'");
}

}  // namespace thyrix
