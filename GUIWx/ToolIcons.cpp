#include <GUIWx/ToolIcons.h>

#include <wx/image.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace thyrix {
namespace {

constexpr double pi = 3.14159265358979323846;

struct Point {
  double x;
  double y;
};
struct Rgb {
  unsigned char r;
  unsigned char g;
  unsigned char b;
};
// A filled polygon in a 24 x 24 design grid, painted over the layers before it.
struct Layer {
  std::vector<Point> polygon;
  Rgb colour;
};

constexpr Rgb dark{60, 60, 60};
constexpr Rgb green{40, 160, 70};
constexpr Rgb red{210, 40, 40};
constexpr Rgb orange{235, 130, 20};
constexpr Rgb blue{50, 100, 210};
constexpr Rgb cyan{30, 160, 190};
constexpr Rgb white{255, 255, 255};

bool inside(const std::vector<Point>& polygon, double x, double y) {
  bool in = false;  // even-odd rule
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Point a = polygon[i];
    const Point b = polygon[j];
    if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

std::vector<Point> rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A regular polygon close to a circle.
std::vector<Point> disc(double cx, double cy, double r, int sides = 32) {
  std::vector<Point> p;
  for (int k = 0; k < sides; ++k) {
    const double t = 2 * pi * k / sides;
    p.push_back({cx + r * std::cos(t), cy + r * std::sin(t)});
  }
  return p;
}

// A thick line from a to b, @p w wide.
std::vector<Point> bar(Point a, Point b, double w) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double length = std::hypot(dx, dy);
  const double nx = -dy / length * w / 2;
  const double ny = dx / length * w / 2;
  return {{a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny}};
}

// An arc band of radius r and width w from angle t0 to t1 (radians, y down).
std::vector<Point> arc(double cx, double cy, double r, double w, double t0, double t1) {
  std::vector<Point> p;
  const int n = 24;
  for (int k = 0; k <= n; ++k) {
    const double t = t0 + (t1 - t0) * k / n;
    p.push_back({cx + (r + w / 2) * std::cos(t), cy + (r + w / 2) * std::sin(t)});
  }
  for (int k = n; k >= 0; --k) {
    const double t = t0 + (t1 - t0) * k / n;
    p.push_back({cx + (r - w / 2) * std::cos(t), cy + (r - w / 2) * std::sin(t)});
  }
  return p;
}

std::vector<Layer> design(ToolIcon icon) {
  switch (icon) {
    case ToolIcon::Run:
      return {{{{7, 4}, {20, 12}, {7, 20}}, green}};
    case ToolIcon::Step:
      return {{{{5, 4}, {16, 12}, {5, 20}}, green}, {rectangle(17, 4, 20, 20), dark}};
    case ToolIcon::Reset: {
      const double t0 = -0.25 * pi;
      const double t1 = 1.45 * pi;
      const Point tip{12 + 7 * std::cos(t0), 12 + 7 * std::sin(t0)};
      return {{arc(12, 12, 7, 3, t0 + 0.3, t1), blue},
              {{{tip.x - 5, tip.y - 1}, {tip.x + 3, tip.y - 3}, {tip.x + 1, tip.y + 5}}, blue}};
    }
    case ToolIcon::Fit:
      return {{rectangle(3, 3, 10, 5), dark},
              {rectangle(3, 3, 5, 10), dark},
              {rectangle(14, 3, 21, 5), dark},
              {rectangle(19, 3, 21, 10), dark},
              {rectangle(3, 19, 10, 21), dark},
              {rectangle(3, 14, 5, 21), dark},
              {rectangle(14, 19, 21, 21), dark},
              {rectangle(19, 14, 21, 21), dark},
              {disc(12, 12, 4), blue}};
    case ToolIcon::Contacts:
      return {{disc(12, 12, 9), blue},
              {bar({7, 7}, {17, 17}, 2.5), red},
              {bar({7, 17}, {17, 7}, 2.5), red}};
    case ToolIcon::Forces:
      return {{bar({4, 20}, {15, 9}, 3), orange}, {{{20, 4}, {18, 15}, {9, 6}}, orange}};
    case ToolIcon::Tactile: {
      std::vector<Layer> layers{{disc(12, 12, 9), blue}};
      for (int k = 0; k < 8; ++k) {
        const double t = 2 * pi * k / 8;
        layers.push_back(
            {disc(12 + 6 * std::cos(t), 12 + 6 * std::sin(t), 1.7, 12), k < 3 ? red : white});
      }
      return layers;
    }
    case ToolIcon::Rays: {
      std::vector<Layer> layers{{disc(5, 19, 4), blue}};
      for (int k = 0; k < 4; ++k) {
        const double t = -pi / 2 + 0.12 + 0.42 * k;
        layers.push_back({bar({5, 19}, {5 + 17 * std::cos(t), 19 + 17 * std::sin(t)}, 1.6), cyan});
      }
      return layers;
    }
    case ToolIcon::Screenshot:
      return {{rectangle(2, 7, 22, 20), dark},
              {rectangle(8, 4, 16, 8), dark},
              {disc(12, 13.5, 5), white},
              {disc(12, 13.5, 3), blue}};
  }
  return {};
}

}  // namespace

wxBitmap toolIcon(ToolIcon icon, int size) {
  const std::vector<Layer> layers = design(icon);
  wxImage image(size, size);
  image.InitAlpha();
  // 4 x 4 samples per pixel: each layer covers a fraction of them; the colour is the average
  // of the covered samples' top layers, the opacity the fraction covered by any layer.
  constexpr int samples = 4;
  const double unit = 24.0 / size;
  for (int py = 0; py < size; ++py) {
    for (int px = 0; px < size; ++px) {
      double r = 0;
      double g = 0;
      double b = 0;
      int covered = 0;
      for (int sy = 0; sy < samples; ++sy) {
        for (int sx = 0; sx < samples; ++sx) {
          const double x = (px + (sx + 0.5) / samples) * unit;
          const double y = (py + (sy + 0.5) / samples) * unit;
          for (std::size_t k = layers.size(); k-- > 0;) {  // the top layer first
            const Layer& layer = layers[k];
            if (inside(layer.polygon, x, y)) {
              r += layer.colour.r;
              g += layer.colour.g;
              b += layer.colour.b;
              ++covered;
              break;
            }
          }
        }
      }
      const auto channel = [covered](double sum) {
        return static_cast<unsigned char>(covered > 0 ? std::lround(sum / covered) : 0);
      };
      image.SetRGB(px, py, channel(r), channel(g), channel(b));
      image.SetAlpha(
          px, py, static_cast<unsigned char>(std::lround(255.0 * covered / (samples * samples))));
    }
  }
  return {image};
}

}  // namespace thyrix
