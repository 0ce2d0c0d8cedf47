#include "FitnessPlot.h"

#include <ThyrixLite/SvgGUI.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

namespace thyrix {

namespace {

constexpr double width = 640, height = 400;
constexpr double left = 80, right = 20, top = 40, bottom = 50;

std::string number(double x, int precision = 6) {
  char buffer[40];
  if (std::abs(x) < 1e-12) x = 0;  // a tick at 0 computed as -1e-17 reads "0"
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, precision);
  return std::string(buffer, result.ptr);
}

// About five round ticks (1, 2 or 5 times a power of ten) covering [low, high].
std::vector<double> ticks(double low, double high) {
  const double raw = (high - low) / 5;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double factor : {2.0, 5.0, 10.0})
    if (raw > step) step = power * factor;
  std::vector<double> out;
  for (double t = std::ceil(low / step) * step; t <= high + step * 1e-9; t += step)
    out.push_back(t);
  return out;
}

}  // namespace

std::string fitnessPlotSvg(std::span<const GenerationRecord> records, std::string_view title) {
  double xLow = 0, xHigh = 1, yLow = 0, yHigh = 1;
  if (!records.empty()) {
    xLow = static_cast<double>(records.front().generation);
    xHigh = static_cast<double>(records.back().generation);
    yLow = yHigh = records.front().best;
    for (const GenerationRecord& r : records)
      for (double y : {r.best, r.mean})
        if (std::isfinite(y)) {
          yLow = std::min(yLow, y);
          yHigh = std::max(yHigh, y);
        }
    if (xHigh <= xLow) xHigh = xLow + 1;
    if (yHigh <= yLow) {
      const double pad = std::max(std::abs(yLow) * 0.1, 1e-9);
      yLow -= pad;
      yHigh += pad;
    }
  }
  const double plotW = width - left - right, plotH = height - top - bottom;
  const auto px = [&](double x) { return left + (x - xLow) / (xHigh - xLow) * plotW; };
  const auto py = [&](double y) { return top + (yHigh - y) / (yHigh - yLow) * plotH; };

  std::string s =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"640\" height=\"400\" "
      "viewBox=\"0 0 640 400\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<rect width=\"640\" height=\"400\" fill=\"white\"/>\n";
  s += "<text x=\"320\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" +
       SvgGUI::escaped(title) + "</text>\n";
  s += "<rect x=\"" + number(left) + "\" y=\"" + number(top) + "\" width=\"" + number(plotW) +
       "\" height=\"" + number(plotH) + "\" fill=\"none\" stroke=\"black\"/>\n";
  for (double t : ticks(xLow, xHigh)) {
    const std::string x = number(px(t));
    s += "<line x1=\"" + x + "\" y1=\"" + number(top + plotH) + "\" x2=\"" + x + "\" y2=\"" +
         number(top + plotH + 5) + "\" stroke=\"black\"/>\n";
    s += "<text x=\"" + x + "\" y=\"" + number(top + plotH + 18) + "\" text-anchor=\"middle\">" +
         number(t) + "</text>\n";
  }
  for (double t : ticks(yLow, yHigh)) {
    const std::string y = number(py(t));
    s += "<line x1=\"" + number(left - 5) + "\" y1=\"" + y + "\" x2=\"" + number(left + plotW) +
         "\" y2=\"" + y + "\" stroke=\"#dddddd\"/>\n";
    s += "<text x=\"" + number(left - 8) + "\" y=\"" + number(py(t) + 4) +
         "\" text-anchor=\"end\">" + number(t) + "</text>\n";
  }
  s += "<text x=\"" + number(left + plotW / 2) + "\" y=\"" + number(height - 10) +
       "\" text-anchor=\"middle\">generation</text>\n";
  s += "<text x=\"16\" y=\"" + number(top + plotH / 2) +
       "\" text-anchor=\"middle\" transform=\"rotate(-90 16 " + number(top + plotH / 2) +
       ")\">fitness</text>\n";
  const auto series = [&](double GenerationRecord::*field, const char* name, const char* color,
                          double legendY) {
    std::string points;
    for (const GenerationRecord& r : records) {
      const double y = r.*field;
      if (!std::isfinite(y)) continue;
      if (!points.empty()) points += ' ';
      points += number(px(static_cast<double>(r.generation))) + ',' + number(py(y));
    }
    s += "<polyline class=\"" + std::string(name) + "\" points=\"" + points +
         "\" fill=\"none\" stroke=\"" + color + "\" stroke-width=\"2\"/>\n";
    const std::string ly = number(legendY);
    s += "<line x1=\"" + number(left + 10) + "\" y1=\"" + ly + "\" x2=\"" + number(left + 30) +
         "\" y2=\"" + ly + "\" stroke=\"" + color + "\" stroke-width=\"2\"/>\n";
    s += "<text x=\"" + number(left + 36) + "\" y=\"" + number(legendY + 4) + "\">" + name +
         "</text>\n";
  };
  series(&GenerationRecord::best, "best", "#1f77b4", top + 14);
  series(&GenerationRecord::mean, "mean", "#ff7f0e", top + 30);
  s += "</svg>\n";
  return s;
}

}  // namespace thyrix
