// fit_frame_height: the image height that gives the world window the plot's
// whole width, with the margins layout_frame() leaves.
#include <gtest/gtest.h>

#include <cstdlib>

#include "render/annotate.hpp"
#include "render/error.hpp"

namespace render {
namespace {

FrameSpec window_spec(int width, double w, double h) {
  FrameSpec spec;
  spec.width = width;
  spec.world_x0 = -2;
  spec.world_x1 = -2 + w;
  spec.world_y0 = 1;
  spec.world_y1 = 1 + h;
  spec.title = "a title";
  return spec;
}

// At the fitted height the box spans the plot's width and, to the pixel,
// its height: no blank band above or below the points.
void expect_fills(Font& font, int width, double w, double h) {
  FrameSpec spec = window_spec(width, w, h);
  spec.height = fit_frame_height(font, spec);
  const FrameLayout L = layout_frame(font, spec);
  EXPECT_LE(std::abs(L.box.w - L.plot_area.w), 1) << w << " x " << h << " at " << width;
  EXPECT_LE(std::abs(L.box.h - L.plot_area.h), 1) << w << " x " << h << " at " << width;
}

TEST(FitFrameHeight, TheWindowFillsThePlot) {
  Font font;
  expect_fills(font, 1280, 80, 20);
  expect_fills(font, 1280, 50, 17);
  expect_fills(font, 1280, 10, 10);
  expect_fills(font, 640, 120, 23);
}

TEST(FitFrameHeight, FollowsTheWindowsAspect) {
  Font font;
  const int flat = fit_frame_height(font, window_spec(1280, 80, 10));
  const int square = fit_frame_height(font, window_spec(1280, 80, 80));
  EXPECT_LT(flat, square / 2);
  EXPECT_GT(square, 1000);
  // The same window at half the width: about half the height.
  const int half = fit_frame_height(font, window_spec(640, 80, 80));
  EXPECT_NEAR(half, square / 2, square / 10);
}

TEST(FitFrameHeight, StaysInTheImageLimits) {
  Font font;
  EXPECT_EQ(fit_frame_height(font, window_spec(1280, 1, 100)), kMaxFrameSide);
  EXPECT_GE(fit_frame_height(font, window_spec(1280, 1000, 1)), kMinFrameSide);
  EXPECT_THROW(fit_frame_height(font, window_spec(1280, 10, 0)), InvalidArgument);
}

}  // namespace
}  // namespace render
