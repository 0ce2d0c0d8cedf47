// The world-to-pixel map of the view: y flipped, uniform scale, checked against the formula
// written out by hand; zoom keeps the point under the cursor, pan moves the picture by the
// mouse's pixels, fit shows the whole box centred.

#include <GUIWx/ViewTransform.h>

#include <gtest/gtest.h>

namespace thyrix {
namespace {

constexpr double pixelTolerance = 1e-6;

TEST(ViewTransform, MapsWorldToPixelsWithYUp) {
  ViewTransform t;
  t.setSize(200, 100);
  t.set(10, {5, 2});
  // The centre of the world view is at the middle of the view.
  const PixelPoint middle = t.toPixel({5, 2});
  EXPECT_NEAR(middle.x, 100, pixelTolerance);
  EXPECT_NEAR(middle.y, 50, pixelTolerance);
  // One metre right is 10 pixels right; one metre up is 10 pixels up (smaller y).
  const PixelPoint p = t.toPixel({6, 3});
  EXPECT_NEAR(p.x, 110, pixelTolerance);
  EXPECT_NEAR(p.y, 40, pixelTolerance);
  const Vector2 back = t.toWorld({110, 40});
  EXPECT_NEAR(back.x, 6, 1e-9);
  EXPECT_NEAR(back.y, 3, 1e-9);
}

TEST(ViewTransform, ZoomKeepsTheAnchorFixed) {
  ViewTransform t;
  t.setSize(300, 200);
  t.set(20, {1, 1});
  const PixelPoint anchor{40, 170};
  const Vector2 before = t.toWorld(anchor);
  t.zoomAbout(anchor, 1.5);
  EXPECT_NEAR(t.scale(), 30, 1e-12);
  const Vector2 after = t.toWorld(anchor);
  EXPECT_NEAR(after.x, before.x, 1e-9);
  EXPECT_NEAR(after.y, before.y, 1e-9);
  t.zoomAbout(anchor, 1e30);  // clamped, never infinite
  EXPECT_EQ(t.scale(), ViewTransform::maxScale);
  t.zoomAbout(anchor, 0);  // ignored
  EXPECT_EQ(t.scale(), ViewTransform::maxScale);
}

TEST(ViewTransform, PanMovesThePictureWithTheMouse) {
  ViewTransform t;
  t.setSize(100, 100);
  t.set(10, {0, 0});
  const PixelPoint before = t.toPixel({2, 3});
  t.panBy(7, -4);
  const PixelPoint after = t.toPixel({2, 3});
  EXPECT_NEAR(after.x - before.x, 7, pixelTolerance);
  EXPECT_NEAR(after.y - before.y, -4, pixelTolerance);
}

TEST(ViewTransform, FitShowsTheWholeBoxCentred) {
  ViewTransform t;
  t.setSize(400, 100);
  t.fit({{0, 0}, {10, 5}});
  // The height limits: 100 pixels for 5 m.
  EXPECT_NEAR(t.scale(), 20, 1e-12);
  const PixelPoint low = t.toPixel({0, 0});
  const PixelPoint high = t.toPixel({10, 5});
  EXPECT_NEAR(low.y, 100, pixelTolerance);
  EXPECT_NEAR(high.y, 0, pixelTolerance);
  EXPECT_NEAR((low.x + high.x) / 2, 200, pixelTolerance);
  t.setSize(50, 400);
  t.fit({{0, 0}, {10, 5}});  // now the width limits: 50 pixels for 10 m
  EXPECT_NEAR(t.scale(), 5, 1e-12);
}

}  // namespace
}  // namespace thyrix
