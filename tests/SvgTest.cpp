// Drawing without a GUI library: SvgGUI writes well-formed SVG with the world mapped to pixels
// as computed by hand (uniform scale, y flipped), escapes text, writes opacity, saves to a file;
// drawWorld adds contact marks and forces only when asked; worldBounds boxes the objects.

#include "TestTolerances.h"

#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/SvgGUI.h>
#include <ThyrixLite/WorldDrawing.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <clocale>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <locale>
#include <map>
#include <memory>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace thyrix {
namespace {

// ---------------------------------------------------------------------------------------------
// A small XML checker, independent of SvgGUI: it accepts only well-formed documents (one root,
// balanced and properly nested tags, quoted attributes without duplicates, no raw '<' in
// values, '&' only in the predefined or numeric references) and returns their elements.

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;  // values with references decoded
  std::string text;                               // character data directly inside, decoded
  int depth = 0;                                  // 0 for the root
};

struct ParsedXml {
  std::string error;  // empty when well-formed
  std::vector<Element> elements;
};

bool isNameStart(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == ':';
}
bool isNameChar(char c) {
  return isNameStart(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
}
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

class XmlChecker {
 public:
  explicit XmlChecker(std::string_view text) : s_(text) {}

  ParsedXml run() {
    ParsedXml result;
    try {
      parseDocument(result.elements);
    } catch (const std::runtime_error& e) {
      result.error = std::string(e.what()) + " at offset " + std::to_string(i_);
    }
    return result;
  }

 private:
  [[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what); }
  [[nodiscard]] bool startsWith(std::string_view prefix) const {
    return s_.substr(i_, prefix.size()) == prefix;
  }
  void skipSpace() {
    while (i_ < s_.size() && isSpace(s_[i_])) ++i_;
  }
  std::string name() {
    if (i_ >= s_.size() || !isNameStart(s_[i_])) fail("expected a name");
    const std::size_t start = i_;
    while (i_ < s_.size() && isNameChar(s_[i_])) ++i_;
    return std::string(s_.substr(start, i_ - start));
  }
  // Decodes a reference starting at '&'.
  std::string reference() {
    const std::size_t end = s_.find(';', i_);
    if (end == std::string_view::npos || end - i_ > 10) fail("unterminated '&'");
    const std::string_view ref = s_.substr(i_ + 1, end - i_ - 1);
    i_ = end + 1;
    if (ref == "amp") return "&";
    if (ref == "lt") return "<";
    if (ref == "gt") return ">";
    if (ref == "quot") return "\"";
    if (ref == "apos") return "'";
    if (ref.size() >= 2 && ref[0] == '#') {
      for (char c : ref.substr(ref[1] == 'x' ? 2 : 1))
        if (!std::isxdigit(static_cast<unsigned char>(c))) fail("bad character reference");
      return "?";
    }
    fail("unknown entity '&" + std::string(ref) + ";'");
  }
  std::string characterData(char stop) {
    std::string out;
    while (i_ < s_.size() && s_[i_] != stop) {
      if (s_[i_] == '&') {
        out += reference();
      } else {
        if (s_[i_] == '<') fail("raw '<' in a value");
        out += s_[i_++];
      }
    }
    return out;
  }

  void parseDocument(std::vector<Element>& elements) {
    if (startsWith("<?xml")) {
      const std::size_t end = s_.find("?>");
      if (end == std::string_view::npos) fail("unterminated XML declaration");
      i_ = end + 2;
    }
    skipSpace();
    if (!startsWith("<")) fail("no root element");
    parseElement(elements, 0);
    skipSpace();
    if (i_ != s_.size()) fail("content after the root element");
  }

  // Recursive descent: the depth is that of the document under test, two levels here.
  void parseElement(std::vector<Element>& elements, int depth) {  // NOLINT(misc-no-recursion)
    ++i_;                                                         // '<'
    const std::size_t index = elements.size();
    elements.push_back({name(), {}, {}, depth});
    for (;;) {
      const std::size_t before = i_;
      skipSpace();
      if (startsWith("/>")) {
        i_ += 2;
        return;
      }
      if (startsWith(">")) {
        ++i_;
        break;
      }
      if (i_ == before) fail("attributes must be separated by white space");
      const std::string attribute = name();
      skipSpace();
      if (!startsWith("=")) fail("attribute '" + attribute + "' has no value");
      ++i_;
      skipSpace();
      if (i_ >= s_.size() || (s_[i_] != '"' && s_[i_] != '\'')) fail("unquoted attribute");
      const char quote = s_[i_++];
      std::string value = characterData(quote);
      if (i_ >= s_.size()) fail("unterminated attribute value");
      ++i_;
      if (!elements[index].attributes.emplace(attribute, std::move(value)).second)
        fail("duplicate attribute '" + attribute + "'");
    }
    for (;;) {
      const std::string text = characterData('<');
      elements[index].text += text;
      if (i_ >= s_.size()) fail("element '" + elements[index].name + "' is not closed");
      if (startsWith("</")) {
        i_ += 2;
        const std::string closing = name();
        if (closing != elements[index].name)
          fail("'" + elements[index].name + "' closed by '" + closing + "'");
        skipSpace();
        if (!startsWith(">")) fail("bad closing tag");
        ++i_;
        return;
      }
      parseElement(elements, depth + 1);
    }
  }

  std::string_view s_;
  std::size_t i_ = 0;
};

ParsedXml parseXml(std::string_view text) { return XmlChecker(text).run(); }

std::vector<const Element*> withClass(const ParsedXml& xml, const std::string& cls) {
  std::vector<const Element*> found;
  for (const Element& e : xml.elements) {
    const auto it = e.attributes.find("class");
    if (it != e.attributes.end() && it->second == cls) found.push_back(&e);
  }
  return found;
}

double number(const Element& e, const std::string& attribute) {
  const auto it = e.attributes.find(attribute);
  if (it == e.attributes.end()) {
    ADD_FAILURE() << e.name << " has no attribute " << attribute;
    return std::nan("");
  }
  return std::stod(it->second);
}

// The numbers of a path's d or a polygon's points, in order.
std::vector<double> numbers(const std::string& text) {
  std::string spaced = text;
  for (char& c : spaced)
    if (std::isalpha(static_cast<unsigned char>(c)) || c == ',') c = ' ';
  std::istringstream in(spaced);
  std::vector<double> out;
  for (double v; in >> v;) out.push_back(v);
  return out;
}

// Pixel coordinates are written to 1e-3 px; positions after a step move by round-off only.
constexpr double pixelTolerance = 2e-3;

// ---------------------------------------------------------------------------------------------
// The scene. View [0, 10] x [0, 5] at 200 pixels wide: 20 pixels per metre, 100 pixels high,
// pixel = (20 x, 20 (5 - y)).
//  - a floor through (0, 1), normal up: the line y = 1, at pixel y 80 from x 0 to 200, solid
//    below (pixel y 80 to 88 for the 8-pixel strip);
//  - a circle of radius 0.5 at (2, 1.5), turned by 90 degrees: centre (40, 70), radius 10,
//    orientation mark up to (40, 60); it rests on the floor: one contact;
//  - a capsule l = 1, R = 0.5 at (6, 1.5), flat: end caps at (5, 1.5) and (7, 1.5), i.e.
//    (100, 70) and (140, 70), radius 10; it lies on the floor: two contacts.
// Both are pushed down by 1 N for one step, so the contacts carry force and nothing moves.

const Vector2 viewLower{0, 0};
const Vector2 viewUpper{10, 5};
constexpr int viewWidth = 200;

struct Scene {
  Simulator simulator;
  Circle* circle = nullptr;
  CappedRectangle* capsule = nullptr;

  Scene() {
    simulator.registerObject(std::make_unique<Border>(Vector2{0, 1}, Vector2{0, 1}));
    circle = &simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
    circle->r = {2, real(1.5)};
    circle->alpha = real(1.5707963267948966);
    capsule =
        &simulator.registerObject(std::make_unique<CappedRectangle>(real(1), real(0.5), real(1)));
    capsule->r = {6, real(1.5)};
    circle->externalForce = {0, -1};
    capsule->externalForce = {0, -1};
    simulator.advanceTime();
  }
};

TEST(SvgGUI, EmptyPictureHasDeclarationRootAndBackground) {
  const SvgGUI gui(viewLower, viewUpper, viewWidth);
  EXPECT_EQ(gui.widthPixels(), 200);
  EXPECT_EQ(gui.heightPixels(), 100);
  EXPECT_DOUBLE_EQ(gui.scale(), 20);
  const std::string svg = gui.svg();
  EXPECT_EQ(svg.rfind("<?xml version=\"1.0\"", 0), 0u);
  const ParsedXml xml = parseXml(svg);
  ASSERT_EQ(xml.error, "");
  ASSERT_EQ(xml.elements.size(), 2u);
  const Element& root = xml.elements[0];
  EXPECT_EQ(root.name, "svg");
  EXPECT_EQ(root.attributes.at("xmlns"), "http://www.w3.org/2000/svg");
  EXPECT_EQ(root.attributes.at("version"), "1.1");
  EXPECT_EQ(root.attributes.at("width"), "200");
  EXPECT_EQ(root.attributes.at("height"), "100");
  EXPECT_EQ(root.attributes.at("viewBox"), "0 0 200 100");
  const Element& background = xml.elements[1];
  EXPECT_EQ(background.name, "rect");
  EXPECT_EQ(background.attributes.at("width"), "200");
  EXPECT_EQ(background.attributes.at("height"), "100");
  EXPECT_EQ(background.attributes.at("fill"), "rgb(255,255,255)");
}

TEST(SvgGUI, WorldMapsToPixelsWithOneScaleAndYUp) {
  // [-1, 3] x [2, 3.5] at 80 pixels: 20 pixels per metre, 30 pixels high.
  const SvgGUI gui({-1, 2}, {3, real(3.5)}, 80);
  EXPECT_EQ(gui.heightPixels(), 30);
  const Vector2 lowerLeft = gui.toPixels({-1, 2});
  const Vector2 upperRight = gui.toPixels({3, real(3.5)});
  const Vector2 inside = gui.toPixels({0, 3});
  EXPECT_NEAR(lowerLeft.x, 0, test::tight);
  EXPECT_NEAR(lowerLeft.y, 30, test::tight);
  EXPECT_NEAR(upperRight.x, 80, test::tight);
  EXPECT_NEAR(upperRight.y, 0, test::tight);
  EXPECT_NEAR(inside.x, 20, test::tight);
  EXPECT_NEAR(inside.y, 10, test::tight);
  // A rectangle whose height is not a whole number of pixels rounds it, keeping one scale.
  const SvgGUI odd({0, 0}, {3, 1}, 100);
  EXPECT_EQ(odd.heightPixels(), 33);
  EXPECT_NEAR(odd.scale(), 100.0 / 3, 1e-6);
}

TEST(SvgGUI, SceneIsWellFormedWithOneElementPerObjectWhereComputedByHand) {
  Scene scene;
  SvgGUI gui(viewLower, viewUpper, viewWidth);
  drawWorld(scene.simulator, gui);
  const ParsedXml xml = parseXml(gui.svg());
  ASSERT_EQ(xml.error, "");

  // Every drawn element sits directly under the root.
  for (std::size_t i = 1; i < xml.elements.size(); ++i) EXPECT_EQ(xml.elements[i].depth, 1);

  const auto circles = withClass(xml, "circle");
  ASSERT_EQ(circles.size(), 1u);
  EXPECT_EQ(circles[0]->name, "circle");
  EXPECT_NEAR(number(*circles[0], "cx"), 40, pixelTolerance);
  EXPECT_NEAR(number(*circles[0], "cy"), 70, pixelTolerance);
  EXPECT_NEAR(number(*circles[0], "r"), 10, pixelTolerance);
  EXPECT_EQ(circles[0]->attributes.at("fill"), "rgb(40,90,220)");  // colors::object
  EXPECT_EQ(circles[0]->attributes.at("stroke"), "rgb(0,0,0)");
  const auto marks = withClass(xml, "orientation");
  ASSERT_EQ(marks.size(), 1u);
  EXPECT_NEAR(number(*marks[0], "x1"), 40, pixelTolerance);
  EXPECT_NEAR(number(*marks[0], "y1"), 70, pixelTolerance);
  EXPECT_NEAR(number(*marks[0], "x2"), 40, pixelTolerance);  // turned by 90 degrees: up
  EXPECT_NEAR(number(*marks[0], "y2"), 60, pixelTolerance);

  const auto capsules = withClass(xml, "capsule");
  ASSERT_EQ(capsules.size(), 1u);
  EXPECT_EQ(capsules[0]->name, "path");
  // M a+n L b+n A r r 0 0 0 b-n L a-n A r r 0 0 0 a+n Z, with a = (100, 70), b = (140, 70),
  // n = r times the page axis (1, 0) turned by +90 page degrees = (0, 10).
  const std::vector<double> expected{100, 80,  140, 80, 10, 10, 0, 0, 0,   140,
                                     60,  100, 60,  10, 10, 0,  0, 0, 100, 80};
  const std::vector<double> d = numbers(capsules[0]->attributes.at("d"));
  ASSERT_EQ(d.size(), expected.size()) << capsules[0]->attributes.at("d");
  for (std::size_t i = 0; i < d.size(); ++i) EXPECT_NEAR(d[i], expected[i], pixelTolerance) << i;

  const auto borders = withClass(xml, "border");
  ASSERT_EQ(borders.size(), 1u);
  EXPECT_EQ(borders[0]->name, "line");
  EXPECT_EQ(borders[0]->attributes.at("stroke"), "rgb(64,64,64)");  // colors::fixedObject
  const double x1 = number(*borders[0], "x1");
  const double x2 = number(*borders[0], "x2");
  EXPECT_NEAR(std::min(x1, x2), 0, pixelTolerance);
  EXPECT_NEAR(std::max(x1, x2), 200, pixelTolerance);
  EXPECT_NEAR(number(*borders[0], "y1"), 80, pixelTolerance);
  EXPECT_NEAR(number(*borders[0], "y2"), 80, pixelTolerance);
  // The strip is on the solid side, below the floor: pixel y from 80 to 88, full width.
  const auto strips = withClass(xml, "border-solid");
  ASSERT_EQ(strips.size(), 1u);
  const std::vector<double> points = numbers(strips[0]->attributes.at("points"));
  ASSERT_GE(points.size(), 6u);
  double minX = 1e9, maxX = -1e9, minY = 1e9, maxY = -1e9;
  for (std::size_t i = 0; i + 1 < points.size(); i += 2) {
    minX = std::min(minX, points[i]);
    maxX = std::max(maxX, points[i]);
    minY = std::min(minY, points[i + 1]);
    maxY = std::max(maxY, points[i + 1]);
  }
  EXPECT_NEAR(minX, 0, pixelTolerance);
  EXPECT_NEAR(maxX, 200, pixelTolerance);
  EXPECT_NEAR(minY, 80, pixelTolerance);
  EXPECT_NEAR(maxY, 88, pixelTolerance);
  EXPECT_TRUE(strips[0]->attributes.count("fill-opacity"));

  // Nothing else: root, background, and the five elements above.
  EXPECT_EQ(xml.elements.size(), 7u);
}

TEST(SvgGUI, BorderIsClippedToTheViewAndShadedOnItsSolidSide) {
  // The diagonal y = x, solid below it (normal (-1, 1)), in the view [0, 10] x [0, 5]: visible
  // from (0, 0) to (5, 5), i.e. pixels (0, 100) to (100, 0).
  SvgGUI gui(viewLower, viewUpper, viewWidth);
  gui.drawBorder({2, 2}, {-1, 1}, colors::black);
  // A border whose line misses the view: not drawn, whichever side the view is on.
  gui.drawBorder({0, -5}, {0, 1}, colors::black);
  gui.drawBorder({0, 20}, {0, 1}, colors::black);
  const ParsedXml xml = parseXml(gui.svg());
  ASSERT_EQ(xml.error, "");
  const auto lines = withClass(xml, "border");
  ASSERT_EQ(lines.size(), 1u);
  double ax = number(*lines[0], "x1"), ay = number(*lines[0], "y1");
  double bx = number(*lines[0], "x2"), by = number(*lines[0], "y2");
  if (ax > bx) {
    std::swap(ax, bx);
    std::swap(ay, by);
  }
  EXPECT_NEAR(ax, 0, pixelTolerance);
  EXPECT_NEAR(ay, 100, pixelTolerance);
  EXPECT_NEAR(bx, 100, pixelTolerance);
  EXPECT_NEAR(by, 0, pixelTolerance);
  // Every corner of the strip is in the picture, on the solid side (world y <= x, i.e. page
  // x + y >= 100), and within 8 pixels of the line (distance (x + y - 100) / sqrt 2).
  const auto strips = withClass(xml, "border-solid");
  ASSERT_EQ(strips.size(), 1u);
  const std::vector<double> points = numbers(strips[0]->attributes.at("points"));
  ASSERT_GE(points.size(), 6u);
  for (std::size_t i = 0; i + 1 < points.size(); i += 2) {
    const double x = points[i], y = points[i + 1];
    EXPECT_GE(x, -pixelTolerance);
    EXPECT_LE(x, 200 + pixelTolerance);
    EXPECT_GE(y, -pixelTolerance);
    EXPECT_LE(y, 100 + pixelTolerance);
    const double behind = (x + y - 100) / std::sqrt(2.0);
    EXPECT_GE(behind, -pixelTolerance);
    EXPECT_LE(behind, 8 + pixelTolerance);
  }
}

TEST(SvgGUI, TextIsEscaped) {
  SvgGUI gui(viewLower, viewUpper, viewWidth);
  const std::string text = "a<b & \"c\" 'd' > e";
  gui.drawText({1, 1}, text, colors::black);
  // Control characters XML forbids are dropped; a stray byte that is not UTF-8 becomes U+FFFD;
  // valid UTF-8 (an e with acute accent) passes.
  gui.drawText({1, 2}, std::string("x\x01y\xFFz\xC3\xA9"), colors::black);
  const std::string svg = gui.svg();
  EXPECT_NE(svg.find(">a&lt;b &amp; &quot;c&quot; &apos;d&apos; &gt; e</text>"), std::string::npos)
      << svg;
  const ParsedXml xml = parseXml(svg);
  ASSERT_EQ(xml.error, "");
  const auto texts = withClass(xml, "text");
  ASSERT_EQ(texts.size(), 2u);
  EXPECT_EQ(texts[0]->text, text);
  EXPECT_NEAR(number(*texts[0], "x"), 20, pixelTolerance);
  EXPECT_NEAR(number(*texts[0], "y"), 80, pixelTolerance);
  EXPECT_EQ(texts[1]->text, "xy\xEF\xBF\xBDz\xC3\xA9");
}

TEST(SvgGUI, TranslucentColourHasAnOpacityAttribute) {
  SvgGUI gui(viewLower, viewUpper, viewWidth);
  gui.drawCircle({1, 1}, 1, 0, Color{10, 20, 30, 51}, Color{1, 2, 3, 255});
  gui.drawLine({0, 0}, {1, 1}, Color{200, 100, 0, 0});
  const ParsedXml xml = parseXml(gui.svg());
  ASSERT_EQ(xml.error, "");
  const Element& circle = *withClass(xml, "circle").at(0);
  EXPECT_EQ(circle.attributes.at("fill"), "rgb(10,20,30)");
  EXPECT_EQ(circle.attributes.at("fill-opacity"), "0.2");  // 51 / 255
  EXPECT_EQ(circle.attributes.at("stroke"), "rgb(1,2,3)");
  EXPECT_EQ(circle.attributes.count("stroke-opacity"), 0u);  // opaque: no attribute
  const Element& line = *withClass(xml, "line").at(0);
  EXPECT_EQ(line.attributes.at("stroke-opacity"), "0");
}

TEST(SvgGUI, LineWidthIsInMetresAndZeroIsAHairline) {
  SvgGUI gui(viewLower, viewUpper, viewWidth);
  gui.drawLine({1, 1}, {2, 1}, colors::black, real(0.25));
  gui.drawLine({1, 1}, {2, 1}, colors::black);
  const ParsedXml xml = parseXml(gui.svg());
  ASSERT_EQ(xml.error, "");
  const auto lines = withClass(xml, "line");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NEAR(number(*lines[0], "stroke-width"), 5, pixelTolerance);  // 0.25 m at 20 px/m
  EXPECT_NEAR(number(*lines[1], "stroke-width"), 1, pixelTolerance);
}

TEST(SvgGUI, PolygonVerticesAreTransformed) {
  SvgGUI gui(viewLower, viewUpper, viewWidth);
  const Vector2 triangle[] = {{1, 1}, {3, 1}, {2, 4}};
  gui.drawPolygon(triangle, colors::green, colors::black);
  const ParsedXml xml = parseXml(gui.svg());
  ASSERT_EQ(xml.error, "");
  const auto polygons = withClass(xml, "polygon");
  ASSERT_EQ(polygons.size(), 1u);
  const std::vector<double> expected{20, 80, 60, 80, 40, 20};
  const std::vector<double> points = numbers(polygons[0]->attributes.at("points"));
  ASSERT_EQ(points.size(), expected.size());
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_NEAR(points[i], expected[i], 1e-9);
}

TEST(SvgGUI, NumbersAreShortAndIgnoreTheLocale) {
  // A global locale with a decimal comma must not leak into the document. Not every system has
  // one installed; the format is checked either way.
  const std::locale previous = std::locale::global(std::locale::classic());
  for (const char* name : {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "fr_FR.utf8"}) {
    try {
      std::locale::global(std::locale(name));
      break;
    } catch (const std::runtime_error&) {
    }
  }
  SvgGUI gui({0, 0}, {3, 3}, 100);  // 100/3 pixels per metre
  gui.drawCircle({real(0.5), real(1.5)}, real(0.015), 0, colors::red, colors::black);
  const std::string svg = gui.svg();
  std::locale::global(previous);
  EXPECT_NE(svg.find("cx=\"16.667\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("cy=\"50\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("r=\"0.5\""), std::string::npos) << svg;
}

TEST(SvgGUI, NonFiniteCoordinatesDrawNothing) {
  SvgGUI gui(viewLower, viewUpper, viewWidth);
  const real nan = std::numeric_limits<real>::quiet_NaN();
  gui.drawCircle({nan, 1}, 1, 0, colors::red, colors::black);
  gui.drawLine({0, 0}, {std::numeric_limits<real>::infinity(), 1}, colors::red);
  gui.drawBorder({0, 0}, {0, 0}, colors::red);
  const ParsedXml xml = parseXml(gui.svg());
  ASSERT_EQ(xml.error, "");
  EXPECT_EQ(xml.elements.size(), 2u);  // the root and the background
}

TEST(SvgGUI, SaveWritesTheDocumentAndThrowsOnAnImpossiblePath) {
  Scene scene;
  SvgGUI gui(viewLower, viewUpper, viewWidth);
  drawWorld(scene.simulator, gui, {.contacts = true, .contactForces = true});
  const std::filesystem::path directory = ::testing::TempDir();
  const std::filesystem::path path = directory / "SvgTest_SaveWritesTheDocument.svg";
  gui.save(path.string());
  std::ifstream in(path, std::ios::binary);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  std::filesystem::remove(path);
  EXPECT_EQ(written, gui.svg());

  const std::string impossible = (directory / "SvgTest no such directory" / "x.svg").string();
  try {
    gui.save(impossible);
    ADD_FAILURE() << "save to " << impossible << " did not throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(impossible), std::string::npos) << e.what();
  }
}

TEST(SvgGUI, ClearErasesTheDrawing) {
  SvgGUI gui(viewLower, viewUpper, viewWidth);
  const std::string empty = gui.svg();
  gui.drawCircle({1, 1}, 1, 0, colors::red, colors::black);
  EXPECT_NE(gui.svg(), empty);
  gui.clear();
  EXPECT_EQ(gui.svg(), empty);
}

TEST(SvgGUI, BadViewIsRefusedNamingTheField) {
  const auto field = [](auto&& make) -> std::string {
    try {
      make();
    } catch (const InvalidArgument& e) {
      return e.field();
    }
    return "<no exception>";
  };
  EXPECT_EQ(field([] { SvgGUI({0, 0}, {1, 1}, 0); }), "SvgGUI.widthPixels");
  EXPECT_EQ(field([] { SvgGUI({0, 0}, {0, 1}, 10); }), "SvgGUI.upper");
  EXPECT_EQ(field([] { SvgGUI({0, 2}, {1, 1}, 10); }), "SvgGUI.upper");
  EXPECT_EQ(field([] {
              SvgGUI({std::numeric_limits<real>::quiet_NaN(), 0}, {1, 1}, 10);
            }),
            "SvgGUI.lower");
}

// ---------------------------------------------------------------------------------------------
// drawWorld, seen through a GUI that records the calls.

struct RecordedLine {
  Vector2 a, b;
  Color color;
  real width;
};

class RecordingGUI : public GUI {
 public:
  int circles = 0, capsules = 0, polygons = 0, texts = 0, borders = 0;
  std::vector<RecordedLine> lines;

  void drawCircle(Vector2, real, real, Color, Color) override { ++circles; }
  void drawCapsule(Vector2, Vector2, real, Color, Color) override { ++capsules; }
  void drawLine(Vector2 a, Vector2 b, Color color, real width) override {
    lines.push_back({a, b, color, width});
  }
  void drawPolygon(std::span<const Vector2>, Color, Color) override { ++polygons; }
  void drawText(Vector2, std::string_view, Color) override { ++texts; }
  void drawBorder(Vector2, Vector2, Color) override { ++borders; }

  [[nodiscard]] std::size_t linesOf(Color color) const {
    std::size_t count = 0;
    for (const RecordedLine& line : lines) count += line.color == color;
    return count;
  }
};

TEST(WorldDrawing, ObjectsAloneByDefault) {
  Scene scene;
  ASSERT_EQ(scene.simulator.contacts.size(), 3u);  // circle on floor; capsule flat on floor
  RecordingGUI gui;
  drawWorld(scene.simulator, gui);
  EXPECT_EQ(gui.borders, 1);
  EXPECT_EQ(gui.circles, 1);
  EXPECT_EQ(gui.capsules, 1);
  EXPECT_TRUE(gui.lines.empty());
  // Options that draw nothing in this version leave the picture as it was.
  RecordingGUI sensors;
  drawWorld(scene.simulator, sensors, {.tactile = true, .visualRays = true});
  EXPECT_TRUE(sensors.lines.empty());
  EXPECT_EQ(sensors.polygons, 0);
}

TEST(WorldDrawing, ContactsAddACrossAndANormalEach) {
  Scene scene;
  const std::size_t contacts = scene.simulator.contacts.size();
  ASSERT_EQ(contacts, 3u);
  RecordingGUI gui;
  drawWorld(scene.simulator, gui, {.contacts = true});
  EXPECT_EQ(gui.linesOf(colors::contact), 3 * contacts);  // two strokes of a cross, a normal
  EXPECT_EQ(gui.linesOf(colors::contactForce), 0u);
  // The cross is centred on the contact point, which lies on the floor (y = 1).
  for (std::size_t i = 0; i < contacts; ++i) {
    const GlobalContactInfo& contact = scene.simulator.contacts[i];
    EXPECT_NEAR(contact.point.y, 1, test::loose);
    const RecordedLine& stroke = gui.lines[3 * i];
    EXPECT_NEAR((stroke.a.x + stroke.b.x) / 2, contact.point.x, test::tight);
    EXPECT_NEAR((stroke.a.y + stroke.b.y) / 2, contact.point.y, test::tight);
    const RecordedLine& normal = gui.lines[3 * i + 2];
    EXPECT_EQ(normal.a, contact.point);
    EXPECT_NEAR(cross(normal.b - normal.a, contact.normal), 0, test::tight);
    EXPECT_GT(dot(normal.b - normal.a, contact.normal), 0);
  }
}

TEST(WorldDrawing, ContactForcesAreLinesOfForceTimesScale) {
  Scene scene;
  RecordingGUI gui;
  drawWorld(scene.simulator, gui, {.contactForces = true, .forceScale = real(0.5)});
  EXPECT_EQ(gui.linesOf(colors::contact), 0u);
  ASSERT_EQ(gui.linesOf(colors::contactForce), 3u);
  // Each body is pushed down by 1 N and held by the floor: its contact forces sum to 1 N.
  real total = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const GlobalContactInfo& contact = scene.simulator.contacts[i];
    const RecordedLine& line = gui.lines[i];
    EXPECT_EQ(line.a, contact.point);
    EXPECT_NEAR(distance(line.a, line.b), contact.force * real(0.5), test::tight);
    EXPECT_NEAR(line.b.x - line.a.x, 0, test::tight);  // along the floor's normal, up
    EXPECT_GT(line.b.y - line.a.y, 0);
    total += distance(line.a, line.b);
  }
  EXPECT_NEAR(total, 2 * real(0.5), test::loose);
}

TEST(WorldDrawing, SvgOfContactsCountsTheMarks) {
  Scene scene;
  const auto strokesIn = [](const std::string& svg, const char* colour) {
    const ParsedXml xml = parseXml(svg);
    EXPECT_EQ(xml.error, "");
    std::size_t count = 0;
    for (const Element* line : withClass(xml, "line"))
      count += line->attributes.at("stroke") == colour;
    return count;
  };
  SvgGUI plain(viewLower, viewUpper, viewWidth);
  drawWorld(scene.simulator, plain);
  EXPECT_EQ(strokesIn(plain.svg(), "rgb(220,40,40)"), 0u);
  EXPECT_EQ(strokesIn(plain.svg(), "rgb(245,140,30)"), 0u);
  SvgGUI marked(viewLower, viewUpper, viewWidth);
  drawWorld(scene.simulator, marked, {.contacts = true, .contactForces = true});
  EXPECT_EQ(strokesIn(marked.svg(), "rgb(220,40,40)"), 9u);   // colors::contact
  EXPECT_EQ(strokesIn(marked.svg(), "rgb(245,140,30)"), 3u);  // colors::contactForce
}

TEST(WorldDrawing, WorldBoundsPadTheObjectsBoxesAndSkipBorders) {
  Simulator simulator;
  BoundingBox box = worldBounds(simulator);
  EXPECT_EQ(box.lower, (Vector2{0, 0}));
  EXPECT_EQ(box.upper, (Vector2{10, 10}));
  simulator.registerObject(std::make_unique<Border>(Vector2{0, -3}, Vector2{0, 1}));
  box = worldBounds(simulator);  // a border alone has no extent
  EXPECT_EQ(box.upper, (Vector2{10, 10}));

  // Circle at (2, 1.5), radius 0.5: [1.5, 2.5] x [1, 2]. Capsule at (6, 1.5), l = 1, R = 0.5,
  // upright: end caps (6, 0.5) and (6, 2.5), so [5.5, 6.5] x [0, 3]. Union [1.5, 6.5] x [0, 3],
  // larger extent 5, padded by 0.25: [1.25, 6.75] x [-0.25, 3.25]. Known before any step.
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  circle.r = {2, real(1.5)};
  auto& capsule =
      simulator.registerObject(std::make_unique<CappedRectangle>(real(1), real(0.5), real(1)));
  capsule.r = {6, real(1.5)};
  capsule.alpha = real(1.5707963267948966);
  box = worldBounds(simulator);
  EXPECT_NEAR(box.lower.x, real(1.25), test::tight);
  EXPECT_NEAR(box.lower.y, real(-0.25), test::tight);
  EXPECT_NEAR(box.upper.x, real(6.75), test::tight);
  EXPECT_NEAR(box.upper.y, real(3.25), test::tight);

  // After a step (nothing pushes, nothing touches: nothing moves) the simulator's own boxes
  // give the same.
  simulator.advanceTime();
  const Vector2 lower{std::min(circle.boxMin.x, capsule.boxMin.x),
                      std::min(circle.boxMin.y, capsule.boxMin.y)};
  const Vector2 upper{std::max(circle.boxMax.x, capsule.boxMax.x),
                      std::max(circle.boxMax.y, capsule.boxMax.y)};
  const real pad = real(0.05) * std::max(upper.x - lower.x, upper.y - lower.y);
  const BoundingBox after = worldBounds(simulator);
  EXPECT_NEAR(after.lower.x, lower.x - pad, test::tight);
  EXPECT_NEAR(after.lower.y, lower.y - pad, test::tight);
  EXPECT_NEAR(after.upper.x, upper.x + pad, test::tight);
  EXPECT_NEAR(after.upper.y, upper.y + pad, test::tight);
}

}  // namespace
}  // namespace thyrix
