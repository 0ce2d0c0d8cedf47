// SvgAnimation: one group per frame, each shown in its slot of the loop by a discrete SMIL
// animation, the world drawn where SvgGUI draws it.

#include <ThyrixLite/Circle.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/SvgAnimation.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace thyrix {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SvgAnimationTest, OneFrameASlotOfTheLoop) {
  // A circle in a field g = (1, 0) moves 0.5 m per 50 steps of 0.01 s: frames at x = 1, 1.5, 2
  // in a 10 m wide view of 100 pixels are drawn at cx = 10, 15, 20.
  Simulator simulator(real(0.01));
  simulator.setGravity({1, 0});
  auto& circle = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  circle.r = {1, 5};
  SvgAnimation animation({0, 0}, {10, 10}, 100, 0.5);
  for (int frame = 0; frame < 3; ++frame) {
    animation.addFrame(simulator, {}, "frame " + std::to_string(frame));
    for (int step = 0; step < 50; ++step) simulator.advanceTime();
  }
  EXPECT_EQ(animation.frameCount(), 3u);
  const std::string svg = animation.svg();
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  EXPECT_EQ(count(svg, "<g class=\"frame\""), 3u);
  EXPECT_EQ(count(svg, "</g>"), 3u);
  EXPECT_EQ(count(svg, "visibility=\"hidden\">"), 2u);  // the first frame shows without SMIL
  EXPECT_EQ(count(svg, "dur=\"1.5s\""), 3u);
  EXPECT_NE(svg.find("values=\"visible;hidden\" keyTimes=\"0;0.333333333\""), std::string::npos);
  EXPECT_NE(svg.find("values=\"hidden;visible;hidden\" keyTimes=\"0;0.333333333;0.666666667\""),
            std::string::npos);
  EXPECT_NE(svg.find("values=\"hidden;visible\" keyTimes=\"0;0.666666667\""), std::string::npos);
  const std::size_t first = svg.find("cx=\"10\"");
  const std::size_t second = svg.find("cx=\"15\"");
  const std::size_t third = svg.find("cx=\"20\"");
  ASSERT_NE(first, std::string::npos);
  ASSERT_NE(second, std::string::npos);
  ASSERT_NE(third, std::string::npos);
  EXPECT_LT(first, second);
  EXPECT_LT(second, third);
  EXPECT_NE(svg.find(">frame 2</text>"), std::string::npos);
}

TEST(SvgAnimationTest, SavesTheDocumentAndRefusesBadInput) {
  Simulator simulator(real(0.01));
  SvgAnimation animation({0, 0}, {1, 1}, 50, 0.1);
  animation.addFrame(simulator);
  const auto path = std::filesystem::temp_directory_path() / "thyrix_svg_animation_test.svg";
  animation.save(path.string());
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), animation.svg());
  EXPECT_EQ(count(text.str(), "<animate"), 0u);  // a single frame needs no animation
  std::filesystem::remove(path);
  EXPECT_THROW(animation.save((path / "no" / "such.svg").string()), std::runtime_error);
  try {
    SvgAnimation({0, 0}, {1, 1}, 50, 0);
    FAIL() << "no exception";
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.field(), "SvgAnimation.frameSeconds");
  }
}

}  // namespace
}  // namespace thyrix
