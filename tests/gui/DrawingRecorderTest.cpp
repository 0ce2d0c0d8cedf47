// The recorder carries a picture from the simulation thread to the window: replaying what it
// recorded into an SvgGUI must give the very document that drawing directly gives (an
// independent GUI as the reference), for every kind of call and a whole world with overlays.

#include <GUIWx/DrawingRecorder.h>

#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/ColorDefinitions.h>
#include <ThyrixLite/Simulator.h>
#include <ThyrixLite/SvgGUI.h>
#include <ThyrixLite/WorldDrawing.h>

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace thyrix {
namespace {

void drawEverything(GUI& gui) {
  gui.drawCircle({1, 2}, real(0.5), real(0.3), colors::blue, colors::black);
  gui.drawCapsule({2, 2}, {4, 3}, real(0.25), colors::yellow, colors::darkGray);
  gui.drawLine({0, 0}, {5, 5}, colors::red, real(0.1));
  const std::vector<Vector2> triangle{{6, 6}, {7, 6}, {6.5, 7}};
  gui.drawPolygon(triangle, colors::green, colors::black);
  gui.drawText({1, 8}, "step <42> & more", colors::black);
  gui.drawBorder({0, 0}, {0, 1}, colors::fixedObject);
  gui.drawText({2, 9}, "", colors::gray);
}

TEST(DrawingRecorder, ReplayDrawsWhatWasRecorded) {
  SvgGUI direct({0, 0}, {10, 10}, 300);
  drawEverything(direct);
  DrawingRecorder recorder;
  drawEverything(recorder);
  EXPECT_EQ(recorder.commands().size(), 7u);
  SvgGUI replayed({0, 0}, {10, 10}, 300);
  recorder.replay(replayed);
  EXPECT_EQ(replayed.svg(), direct.svg());
  EXPECT_EQ(recorder.text(recorder.commands()[4]), "step <42> & more");
  EXPECT_EQ(recorder.points(recorder.commands()[3]).size(), 3u);
}

TEST(DrawingRecorder, ClearForgetsAndRecordsAnew) {
  DrawingRecorder recorder;
  drawEverything(recorder);
  recorder.clear();
  EXPECT_TRUE(recorder.commands().empty());
  recorder.drawLine({0, 0}, {1, 1}, colors::red);
  SvgGUI direct({0, 0}, {2, 2}, 100);
  direct.drawLine({0, 0}, {1, 1}, colors::red);
  SvgGUI replayed({0, 0}, {2, 2}, 100);
  recorder.replay(replayed);
  EXPECT_EQ(replayed.svg(), direct.svg());
}

TEST(DrawingRecorder, ReplaysAWholeWorldWithOverlays) {
  Simulator simulator;
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  auto& a = simulator.registerObject(std::make_unique<Circle>(real(0.5), real(1)));
  a.r = {2, real(0.45)};  // resting on the floor, overlapping a little: contacts and forces
  auto& b = simulator.registerObject(std::make_unique<CappedRectangle>(real(0.6), real(0.2), 1));
  b.r = {real(2.9), real(0.6)};
  a.externalForce = {1, -1};
  simulator.advanceTime();
  a.externalForce = {1, -1};
  simulator.advanceTime();
  ASSERT_FALSE(simulator.contacts.empty());
  DrawOptions options;
  options.contacts = options.contactForces = options.tactile = options.visualRays = true;
  SvgGUI direct({0, 0}, {5, 5}, 400);
  drawWorld(simulator, direct, options);
  DrawingRecorder recorder;
  drawWorld(simulator, recorder, options);
  SvgGUI replayed({0, 0}, {5, 5}, 400);
  recorder.replay(replayed);
  EXPECT_EQ(replayed.svg(), direct.svg());
}

}  // namespace
}  // namespace thyrix
