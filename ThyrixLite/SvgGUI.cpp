#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/SvgGUI.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace thyrix {
namespace {

// Outlines and hairlines are one pixel wide whatever the zoom, as on a screen.
constexpr double hairline = 1;
constexpr double borderLineWidth = 2;
// The solid side of a border is shaded at this fraction of the border colour's opacity: enough
// to tell which side is solid without hiding what lies there.
constexpr double borderStripOpacity = 0.35;

bool isFinite(real value) { return std::isfinite(value); }
bool isFinite(Vector2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Locale-independent: std::to_chars never consults a locale. Three decimals of a pixel are far
// below what any renderer resolves; trailing zeros are dropped to keep files small.
void appendNumber(std::string& out, double value) {
  char buffer[64];
  std::to_chars_result result;
  if (std::fabs(value) < 1e15) {
    result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, 3);
    while (result.ptr[-1] == '0') --result.ptr;
    if (result.ptr[-1] == '.') --result.ptr;
  } else {
    result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific, 6);
  }
  const std::string_view text(buffer, static_cast<std::size_t>(result.ptr - buffer));
  out += text == "-0" ? std::string_view("0") : text;
}

// ` name="value"` for a number.
void appendAttribute(std::string& out, std::string_view name, double value) {
  out += ' ';
  out += name;
  out += "=\"";
  appendNumber(out, value);
  out += '"';
}

// ` name="value"` for text that needs no escaping.
void appendAttribute(std::string& out, std::string_view name, std::string_view value) {
  out += ' ';
  out += name;
  out += "=\"";
  out += value;
  out += '"';
}

// ` fill="rgb(r,g,b)"` (or stroke), plus ` fill-opacity="a"` when the colour, dimmed by
// @p opacity, is translucent.
void appendPaint(std::string& out, std::string_view name, Color color, double opacity = 1) {
  out += ' ';
  out += name;
  out += "=\"rgb(";
  out += std::to_string(color.red);
  out += ',';
  out += std::to_string(color.green);
  out += ',';
  out += std::to_string(color.blue);
  out += ")\"";
  const double alpha = opacity * color.alpha / 255.0;
  if (alpha < 1) {
    out += ' ';
    out += name;
    out += R"(-opacity=")";
    appendNumber(out, alpha);
    out += '"';
  }
}

void appendPoint(std::string& out, double x, double y) {
  appendNumber(out, x);
  out += ',';
  appendNumber(out, y);
}

// Character data and attribute values: the five characters XML gives a meaning, escaped; the
// control characters XML 1.0 forbids even as references, dropped; bytes that are not UTF-8,
// replaced by U+FFFD. Whatever the input, the document stays well-formed.
void appendEscaped(std::string& out, std::string_view text) {
  static constexpr std::string_view replacement = "\xEF\xBF\xBD";
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  std::size_t i = 0;
  while (i < text.size()) {
    const unsigned char c = byte(i);
    if (c < 0x80) {
      switch (c) {
        case '&':
          out += "&amp;";
          break;
        case '<':
          out += "&lt;";
          break;
        case '>':
          out += "&gt;";
          break;
        case '"':
          out += "&quot;";
          break;
        case '\'':
          out += "&apos;";
          break;
        case '\t':
        case '\n':
        case '\r':
          out += static_cast<char>(c);
          break;
        default:
          if (c >= 0x20) out += static_cast<char>(c);
      }
      ++i;
      continue;
    }
    // A multi-byte sequence: its length and the range of its second byte exclude overlong
    // forms, surrogates and code points beyond U+10FFFF (RFC 3629, table 3-7 of Unicode).
    std::size_t length = 0;
    unsigned char secondLow = 0x80;
    unsigned char secondHigh = 0xBF;
    if (c >= 0xC2 && c <= 0xDF) {
      length = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
      length = 3;
      if (c == 0xE0) secondLow = 0xA0;
      if (c == 0xED) secondHigh = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      length = 4;
      if (c == 0xF0) secondLow = 0x90;
      if (c == 0xF4) secondHigh = 0x8F;
    }
    bool valid = length > 0 && i + length <= text.size();
    for (std::size_t k = 1; valid && k < length; ++k) {
      const unsigned char low = k == 1 ? secondLow : 0x80;
      const unsigned char high = k == 1 ? secondHigh : 0xBF;
      valid = byte(i + k) >= low && byte(i + k) <= high;
    }
    // U+FFFE and U+FFFF are not XML characters.
    if (valid && length == 3 && c == 0xEF && byte(i + 1) == 0xBF && byte(i + 2) >= 0xBE)
      valid = false;
    if (valid) {
      out += text.substr(i, length);
      i += length;
    } else {
      out += replacement;
      ++i;
    }
  }
}

// Sutherland-Hodgman step: keeps the part of the convex polygon @p in where
// `a x + b y <= c`.
std::vector<Vector2> clipToHalfPlane(const std::vector<Vector2>& in, double a, double b, double c) {
  std::vector<Vector2> out;
  const auto side = [&](Vector2 p) { return a * p.x + b * p.y - c; };
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Vector2 p = in[i];
    const Vector2 q = in[(i + 1) % in.size()];
    const double sp = side(p);
    const double sq = side(q);
    if (sp <= 0) out.push_back(p);
    if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
      const double t = sp / (sp - sq);
      out.push_back(
          {static_cast<real>(p.x + t * (q.x - p.x)), static_cast<real>(p.y + t * (q.y - p.y))});
    }
  }
  return out;
}

}  // namespace

SvgGUI::SvgGUI(Vector2 lower, Vector2 upper, int widthPixels)
    : lower_(lower), upper_(upper), width_(widthPixels) {
  requireFinite(lower, "SvgGUI.lower");
  requireFinite(upper, "SvgGUI.upper");
  if (!(upper.x > lower.x) || !(upper.y > lower.y))
    throw InvalidArgument("SvgGUI.upper", "must lie above and to the right of SvgGUI.lower");
  if (widthPixels <= 0)
    throw InvalidArgument("SvgGUI.widthPixels",
                          "must be positive (got " + std::to_string(widthPixels) + ")");
  scale_ = widthPixels / (static_cast<double>(upper.x) - lower.x);
  const double height = std::round((static_cast<double>(upper.y) - lower.y) * scale_);
  if (!(height < 1e9))
    throw InvalidArgument("SvgGUI.upper", "gives a picture taller than 1e9 pixels");
  height_ = std::max(1, static_cast<int>(height));
}

SvgGUI::Pixel SvgGUI::pixel(Vector2 p) const {
  return {(static_cast<double>(p.x) - lower_.x) * scale_,
          (static_cast<double>(upper_.y) - p.y) * scale_};
}

Vector2 SvgGUI::toPixels(Vector2 p) const {
  const Pixel q = pixel(p);
  return {static_cast<real>(q.x), static_cast<real>(q.y)};
}

void SvgGUI::setFontSize(double pixels) {
  if (pixels > 0 && std::isfinite(pixels)) fontSize_ = pixels;
}

void SvgGUI::setBorderStripPixels(double pixels) {
  if (pixels >= 0 && std::isfinite(pixels)) borderStrip_ = pixels;
}

void SvgGUI::drawCircle(Vector2 centre, real radius, real angle, Color fill, Color outline) {
  if (!isFinite(centre) || !isFinite(radius) || !isFinite(angle)) return;
  const Pixel c = pixel(centre);
  const double r = std::max(0.0, static_cast<double>(radius)) * scale_;
  body_ += R"(<circle class="circle")";
  appendAttribute(body_, "cx", c.x);
  appendAttribute(body_, "cy", c.y);
  appendAttribute(body_, "r", r);
  appendPaint(body_, "fill", fill);
  appendPaint(body_, "stroke", outline);
  appendAttribute(body_, "stroke-width", hairline);
  body_ += "/>\n";
  // The orientation mark: a radius at the body's angle (counter-clockwise in the world, so
  // clockwise on the y-down page).
  body_ += R"(<line class="orientation")";
  appendAttribute(body_, "x1", c.x);
  appendAttribute(body_, "y1", c.y);
  appendAttribute(body_, "x2", c.x + r * std::cos(static_cast<double>(angle)));
  appendAttribute(body_, "y2", c.y - r * std::sin(static_cast<double>(angle)));
  appendPaint(body_, "stroke", outline);
  appendAttribute(body_, "stroke-width", hairline);
  body_ += "/>\n";
}

void SvgGUI::drawCapsule(Vector2 a, Vector2 b, real radius, Color fill, Color outline) {
  if (!isFinite(a) || !isFinite(b) || !isFinite(radius)) return;
  const Pixel pa = pixel(a);
  const Pixel pb = pixel(b);
  const double r = std::max(0.0, static_cast<double>(radius)) * scale_;
  // Unit axis from a to b on the page and its normal; any axis will do for coincident ends
  // (the path is then a circle).
  double dx = pb.x - pa.x;
  double dy = pb.y - pa.y;
  const double length = std::hypot(dx, dy);
  if (length > 0) {
    dx /= length;
    dy /= length;
  } else {
    dx = 1;
    dy = 0;
  }
  const double nx = -dy * r;
  const double ny = dx * r;
  // Side a+n to b+n, half-turn around b's far side to b-n, back to a-n, half-turn around a.
  // The normal is the axis turned by +90 degrees in page angles (x right, y down), so both
  // half-turns run towards decreasing page angle: sweep-flag 0.
  body_ += R"(<path class="capsule" d="M)";
  appendPoint(body_, pa.x + nx, pa.y + ny);
  body_ += " L";
  appendPoint(body_, pb.x + nx, pb.y + ny);
  body_ += " A";
  appendPoint(body_, r, r);
  body_ += " 0 0 0 ";
  appendPoint(body_, pb.x - nx, pb.y - ny);
  body_ += " L";
  appendPoint(body_, pa.x - nx, pa.y - ny);
  body_ += " A";
  appendPoint(body_, r, r);
  body_ += " 0 0 0 ";
  appendPoint(body_, pa.x + nx, pa.y + ny);
  body_ += " Z\"";
  appendPaint(body_, "fill", fill);
  appendPaint(body_, "stroke", outline);
  appendAttribute(body_, "stroke-width", hairline);
  body_ += "/>\n";
}

void SvgGUI::drawLine(Vector2 a, Vector2 b, Color color, real width) {
  if (!isFinite(a) || !isFinite(b)) return;
  const Pixel pa = pixel(a);
  const Pixel pb = pixel(b);
  const double pixels = width > 0 && isFinite(width) ? width * scale_ : hairline;
  body_ += R"(<line class="line")";
  appendAttribute(body_, "x1", pa.x);
  appendAttribute(body_, "y1", pa.y);
  appendAttribute(body_, "x2", pb.x);
  appendAttribute(body_, "y2", pb.y);
  appendPaint(body_, "stroke", color);
  appendAttribute(body_, "stroke-width", pixels);
  appendAttribute(body_, "stroke-linecap", "round");
  body_ += "/>\n";
}

void SvgGUI::drawPolygon(std::span<const Vector2> vertices, Color fill, Color outline) {
  if (vertices.empty()) return;
  for (const Vector2 v : vertices)
    if (!isFinite(v)) return;
  body_ += R"(<polygon class="polygon" points=")";
  bool first = true;
  for (const Vector2 v : vertices) {
    if (!first) body_ += ' ';
    first = false;
    const Pixel p = pixel(v);
    appendPoint(body_, p.x, p.y);
  }
  body_ += '"';
  appendPaint(body_, "fill", fill);
  appendPaint(body_, "stroke", outline);
  appendAttribute(body_, "stroke-width", hairline);
  body_ += "/>\n";
}

void SvgGUI::drawText(Vector2 position, std::string_view text, Color color) {
  if (!isFinite(position)) return;
  const Pixel p = pixel(position);
  body_ += R"(<text class="text")";
  appendAttribute(body_, "x", p.x);
  appendAttribute(body_, "y", p.y);
  appendAttribute(body_, "font-family", "sans-serif");
  appendAttribute(body_, "font-size", fontSize_);
  appendPaint(body_, "fill", color);
  body_ += '>';
  appendEscaped(body_, text);
  body_ += "</text>\n";
}

void SvgGUI::drawBorder(Vector2 point, Vector2 normal, Color color) {
  if (!isFinite(point) || !isFinite(normal)) return;
  // Work on the page: the map is a uniform scale and a flip of y, so the page normal is the
  // world normal with y negated.
  const Pixel p = pixel(point);
  const double length = std::hypot(static_cast<double>(normal.x), static_cast<double>(normal.y));
  if (!(length > 0)) return;
  const double nx = normal.x / length;
  const double ny = -normal.y / length;
  const double offset = nx * p.x + ny * p.y;  // the line is n . x = offset on the page
  const double w = width_;
  const double h = height_;

  // The solid side within the strip's reach: the page rectangle where
  // offset - strip <= n . x <= offset.
  if (borderStrip_ > 0) {
    std::vector<Vector2> strip{{0, 0},
                               {static_cast<real>(w), 0},
                               {static_cast<real>(w), static_cast<real>(h)},
                               {0, static_cast<real>(h)}};
    strip = clipToHalfPlane(strip, nx, ny, offset);
    strip = clipToHalfPlane(strip, -nx, -ny, borderStrip_ - offset);
    if (strip.size() >= 3) {
      body_ += R"(<polygon class="border-solid" points=")";
      for (std::size_t i = 0; i < strip.size(); ++i) {
        if (i > 0) body_ += ' ';
        appendPoint(body_, strip[i].x, strip[i].y);
      }
      body_ += '"';
      appendPaint(body_, "fill", color, borderStripOpacity);
      appendAttribute(body_, "stroke", "none");
      body_ += "/>\n";
    }
  }

  // The visible segment: the line p + s t, t along it, clipped to the page (Liang-Barsky).
  const double tx = -ny;
  const double ty = nx;
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool outside = false;  // parallel to a side of the page and beyond it
  const auto clip = [&](double origin, double direction, double limit) {
    if (direction == 0) {
      outside = outside || origin < 0 || origin > limit;
      return;
    }
    const double s0 = (0 - origin) / direction;
    const double s1 = (limit - origin) / direction;
    low = std::max(low, std::min(s0, s1));
    high = std::min(high, std::max(s0, s1));
  };
  clip(p.x, tx, w);
  clip(p.y, ty, h);
  if (outside || !(low < high)) return;
  body_ += R"(<line class="border")";
  appendAttribute(body_, "x1", p.x + low * tx);
  appendAttribute(body_, "y1", p.y + low * ty);
  appendAttribute(body_, "x2", p.x + high * tx);
  appendAttribute(body_, "y2", p.y + high * ty);
  appendPaint(body_, "stroke", color);
  appendAttribute(body_, "stroke-width", borderLineWidth);
  body_ += "/>\n";
}

std::string SvgGUI::svg() const {
  std::string out;
  out.reserve(body_.size() + 400);
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
  out += R"(<svg xmlns="http://www.w3.org/2000/svg" version="1.1")";
  appendAttribute(out, "width", width_);
  appendAttribute(out, "height", height_);
  out += R"( viewBox="0 0 )";
  out += std::to_string(width_);
  out += ' ';
  out += std::to_string(height_);
  out += "\">\n";
  out += R"(<rect class="background" x="0" y="0")";
  appendAttribute(out, "width", width_);
  appendAttribute(out, "height", height_);
  appendPaint(out, "fill", background_);
  out += "/>\n";
  out += body_;
  out += "</svg>\n";
  return out;
}

void SvgGUI::save(const std::string& path) const {
  const std::string document = svg();
  const auto failure = [&](const char* what, int error) {
    return std::runtime_error("SvgGUI.save: cannot " + std::string(what) + " '" + path +
                              "': " + std::generic_category().message(error));
  };
  // C stdio rather than iostreams: errno then says why a failure happened. The file is closed
  // on every path below by hand, not by a guard, so that a failed final flush is reported.
  // NOLINTNEXTLINE(cppcoreguidelines-owning-memory)
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) throw failure("open", errno);
  const std::size_t written = std::fwrite(document.data(), 1, document.size(), file);
  const int writeError = errno;
  // NOLINTNEXTLINE(cppcoreguidelines-owning-memory)
  if (std::fclose(file) != 0) throw failure("close", errno);
  if (written != document.size()) throw failure("write", writeError);
}

void SvgGUI::clear() { body_.clear(); }

std::string SvgGUI::escaped(std::string_view text) {
  std::string out;
  appendEscaped(out, text);
  return out;
}

}  // namespace thyrix
