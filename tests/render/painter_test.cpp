#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "render/error.hpp"
#include "render/painter.hpp"

namespace render {
namespace {

struct Cloud {
  std::vector<double> x, y, hw, hh, v;
  PointsView view() const {
    return PointsView{x.size(), x.data(), y.data(), hw.data(), hh.data(), v.data()};
  }
};

// Points on a grid filling [x0, x1] x [y0, y1], value = x.
Cloud block(double x0, double x1, double y0, double y1, double h) {
  Cloud c;
  for (double y = y0 + h; y < y1; y += 2 * h) {
    for (double x = x0 + h; x < x1; x += 2 * h) {
      c.x.push_back(x), c.y.push_back(y), c.hw.push_back(h), c.hh.push_back(h);
      c.v.push_back(x);
    }
  }
  return c;
}

FrameSpec slope_spec() {
  FrameSpec s;
  s.world_x0 = 0, s.world_x1 = 117, s.world_y0 = 0, s.world_y1 = 20;
  s.range_lo = 0, s.range_hi = 117;
  s.title = "Slope collapse";
  s.field_label = "displacement";
  s.unit = "m";
  s.time = 12.5;
  return s;
}

// No ink within `band` pixels of the image border: nothing was clipped.
void expect_clean_border(const Image& img, Rgba bg, int band) {
  int ink = 0;
  for (int y = 0; y < img.height(); ++y) {
    for (int x = 0; x < img.width(); ++x) {
      const bool edge = x < band || y < band || x >= img.width() - band ||
                        y >= img.height() - band;
      if (edge && img.at(x, y) != bg) ++ink;
    }
  }
  EXPECT_EQ(ink, 0) << "annotation ink within " << band << " px of the border";
}

TEST(Painter, PaintsPointsInsideAnAspectKeepingWindow) {
  Painter painter(1280, 720);
  const FrameSpec spec = slope_spec();
  const Cloud c = block(10, 40, 2, 8, 0.25);
  const Image img = painter.paint(spec, c.view());
  ASSERT_EQ(img.width(), 1280);
  ASSERT_EQ(img.height(), 720);
  const FrameLayout& L = painter.last_layout();
  // 1 m in x is 1 m in y.
  EXPECT_NEAR(double(L.box.w) / L.box.h, 117.0 / 20.0, 0.05);
  // Centred in the plot area, within the rounding of fit_window (the
  // corner's floor) and of box() (the far edge's nearest pixel).
  EXPECT_NEAR(L.box.x - L.plot_area.x, L.plot_area.right() - L.box.right(), 2);
  EXPECT_NEAR(L.box.y - L.plot_area.y, L.plot_area.bottom() - L.box.bottom(), 2);
  // A point's colour at its pixel, background beside the block.
  const ColourMap cm = ColourMap::viridis();
  const int px = int(L.map.x(20.125)), py = int(L.map.y(5.25));
  EXPECT_EQ(img.at(px, py), cm.map(20.125, 0, 117));
  EXPECT_EQ(img.at(int(L.map.x(80)), int(L.map.y(10))), kWhite);
  expect_clean_border(img, kWhite, 4);
}

// The pixel on the bar's centre line `f` of the way from its low end.
Rgba bar_pixel(const Image& img, const Rect& bar, BarSide side, double f) {
  if (side == BarSide::Below) return img.at(bar.x + int(f * (bar.w - 1)), bar.y + bar.h / 2);
  return img.at(bar.x + bar.w / 2, bar.bottom() - 1 - int(f * (bar.h - 1)));
}

TEST(Painter, ColourBarBesideATallWindowRunsLowToHighUpwards) {
  Painter painter(1280, 720);
  FrameSpec spec = slope_spec();
  spec.world_x1 = 20;
  spec.colour_map = "jet";
  const Cloud c = block(0, 10, 0, 2, 0.5);
  const Image img = painter.paint(spec, c.view());
  const FrameLayout& L = painter.last_layout();
  ASSERT_EQ(L.bar.side, BarSide::Right);
  const Rect bar = L.colour_bar;
  ASSERT_GT(bar.h, 100);
  EXPECT_GT(bar.x, L.box.right());
  const ColourMap jet = ColourMap::jet();
  const int cx = bar.x + bar.w / 2;
  EXPECT_EQ(img.at(cx, bar.y), jet.at(1.0));
  EXPECT_EQ(img.at(cx, bar.bottom() - 1), jet.at(0.0));
  for (int y = 0; y < bar.h; ++y) {
    ASSERT_EQ(img.at(cx, bar.y + y), jet.at((bar.h - y - 0.5) / bar.h)) << "row " << y;
  }
  EXPECT_FALSE(L.bar_ticks.values.empty());
}

// A slope's window is wide: the bar goes under the plot, where it is long,
// and runs low to high from left to right.
TEST(Painter, ColourBarBelowAWideWindowRunsLowToHighRightwards) {
  Painter painter(1280, 720);
  FrameSpec spec = slope_spec();
  spec.colour_map = "jet";
  const Cloud c = block(0, 10, 0, 2, 0.5);
  const Image img = painter.paint(spec, c.view());
  const FrameLayout& L = painter.last_layout();
  ASSERT_EQ(L.bar.side, BarSide::Below);
  const Rect bar = L.colour_bar;
  EXPECT_GT(bar.y, L.box.bottom());
  ASSERT_GT(bar.w, 300);
  EXPECT_LE(bar.right(), L.box.right());
  const ColourMap jet = ColourMap::jet();
  const int cy = bar.y + bar.h / 2;
  for (int x = 0; x < bar.w; ++x) {
    ASSERT_EQ(img.at(bar.x + x, cy), jet.at((x + 0.5) / bar.w)) << "column " << x;
  }
  EXPECT_GE(L.bar_ticks.values.size(), 3u);
  expect_clean_border(img, kWhite, 4);
}

TEST(Painter, NothingClippedForTallWindowsLongLabelsAndSmallFrames) {
  Painter painter(1280, 720);
  FrameSpec tall = slope_spec();
  tall.world_x0 = -1000.25, tall.world_x1 = -990, tall.world_y0 = -1500, tall.world_y1 = -1460;
  tall.range_lo = -12345.5, tall.range_hi = 1e5;
  tall.title = "A rather long title for a tall, narrow column collapse test";
  const Cloud c = block(-1000, -991, -1499, -1470, 0.5);
  expect_clean_border(painter.paint(tall, c.view()), kWhite, 3);

  FrameSpec wordy = slope_spec();
  wordy.title = std::string(12, ' ') + "An extremely long title that could never fit on one line at "
                "the normal title size, so it has to be set smaller instead";
  expect_clean_border(painter.paint(wordy, c.view()), kWhite, 3);

  FrameSpec small = slope_spec();
  small.width = 640, small.height = 360;
  const Image img = painter.paint(small, c.view());
  EXPECT_EQ(img.width(), 640);
  expect_clean_border(img, kWhite, 2);
}

TEST(Painter, CategoricalFieldsGetOneBlockPerId) {
  Painter painter(800, 450);
  FrameSpec spec = slope_spec();
  spec.width = 800, spec.height = 450;
  spec.colour_map = "categorical";
  spec.range_lo = 0, spec.range_hi = 2;
  spec.field_label = "material";
  spec.unit = "";
  Cloud c = block(0, 30, 0, 5, 0.5);
  for (std::size_t i = 0; i < c.v.size(); ++i) c.v[i] = double(i % 3);
  const Image img = painter.paint(spec, c.view());
  const FrameLayout& L = painter.last_layout();
  ASSERT_EQ(L.bar_ticks.labels.size(), 3u);
  const ColourMap cat = ColourMap::categorical();
  EXPECT_EQ(bar_pixel(img, L.colour_bar, L.bar.side, 0.01), cat.map(0, 0, 2));
  EXPECT_EQ(bar_pixel(img, L.colour_bar, L.bar.side, 0.5), cat.map(1, 0, 2));
  EXPECT_EQ(bar_pixel(img, L.colour_bar, L.bar.side, 0.99), cat.map(2, 0, 2));
}

TEST(Painter, BadSpecsThrowNamingTheValue) {
  Painter painter(320, 240);
  const Cloud c = block(0, 1, 0, 1, 0.5);
  FrameSpec spec = slope_spec();
  spec.colour_map = "plasma9";
  try {
    painter.paint(spec, c.view());
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("plasma9"), std::string::npos);
  }
  spec = slope_spec();
  spec.range_hi = spec.range_lo;
  EXPECT_THROW(painter.paint(spec, c.view()), InvalidArgument);
  spec = slope_spec();
  spec.world_x1 = -5;
  EXPECT_THROW(painter.paint(spec, c.view()), InvalidArgument);
  spec = slope_spec();
  spec.width = 10;
  EXPECT_THROW(painter.paint(spec, c.view()), InvalidArgument);
  PointsView broken = c.view();
  broken.value = nullptr;
  EXPECT_THROW(painter.paint(slope_spec(), broken), InvalidArgument);
}

TEST(Painter, FormatsTimeAndBarLabel) {
  EXPECT_EQ(format_time(12.5), "t = 12.50 s");
  FrameSpec s;
  s.field_label = "displacement";
  s.unit = "m";
  EXPECT_EQ(bar_label(s), "displacement [m]");
  s.unit.clear();
  EXPECT_EQ(bar_label(s), "displacement");
}

}  // namespace
}  // namespace render
