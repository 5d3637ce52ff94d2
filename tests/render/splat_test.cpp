#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "render/error.hpp"
#include "render/splat.hpp"

namespace render {
namespace {

struct Cloud {
  std::vector<double> x, y, hw, hh, v;
  void add(double px, double py, double w, double h, double val) {
    x.push_back(px), y.push_back(py), hw.push_back(w), hh.push_back(h), v.push_back(val);
  }
  PointsView view() const {
    return PointsView{x.size(), x.data(), y.data(), hw.data(), hh.data(), v.data()};
  }
};

Image paint(const Cloud& c, const WorldWindow& w, int width, int height, const Rect& area,
            const ColourMap& cmap = ColourMap::viridis()) {
  OffscreenContext ctx(width, height);
  const PixelMap map = fit_window(w, area);
  Splatter s;
  s.draw(ctx, map, map.box(), c.view(), cmap, 0.0, 1.0);
  return ctx.read_image();
}

TEST(Viewport, FitKeepsAspectAndCentres) {
  const PixelMap m = fit_window(WorldWindow{0, 10, 0, 2}, Rect{0, 0, 200, 100});
  EXPECT_DOUBLE_EQ(m.scale(), 20.0);
  EXPECT_DOUBLE_EQ(m.x(0), 0.0);
  EXPECT_DOUBLE_EQ(m.y(2), 30.0);  // (100 - 40) / 2
  EXPECT_DOUBLE_EQ(m.y(0), 70.0);
  EXPECT_EQ(m.box(), (Rect{0, 30, 200, 40}));
  EXPECT_THROW(fit_window(WorldWindow{1, 1, 0, 1}, Rect{0, 0, 10, 10}), InvalidArgument);
  EXPECT_THROW(fit_window(WorldWindow{0, NAN, 0, 1}, Rect{0, 0, 10, 10}), InvalidArgument);
}

// 617 / 0.3 * 0.3 rounds to just above 617, so the spare width is -1e-13:
// its floor put the plot a pixel left of its area, and a build that rounds
// it the other way (FMA) painted every frame a pixel to the right.
TEST(Viewport, RoundOffOfAFullWidthFitDoesNotShiftThePlot) {
  const PixelMap m = fit_window(WorldWindow{0, 0.3, 0, 0.1}, Rect{5, 0, 617, 617});
  EXPECT_DOUBLE_EQ(m.x(0), 5.0);
  EXPECT_EQ(m.box().x, 5);
}

TEST(Splat, KnownSquaresPaintExpectedPixels) {
  Cloud c;
  c.add(2, 6, 1, 0.5, 0.0);  // -> x [10, 30), rows [15, 25)
  c.add(7, 2, 0.5, 1, 1.0);  // -> x [65, 75), rows [50, 70)
  const Image img = paint(c, WorldWindow{0, 10, 0, 8}, 100, 80, Rect{0, 0, 100, 80});
  const ColourMap cm = ColourMap::viridis();
  const Rgba lo = cm.at(0.0), hi = cm.at(1.0);
  EXPECT_EQ(img.at(20, 20), lo);
  EXPECT_EQ(img.at(10, 15), lo);
  EXPECT_EQ(img.at(29, 24), lo);
  EXPECT_EQ(img.at(30, 20), kWhite);
  EXPECT_EQ(img.at(9, 20), kWhite);
  EXPECT_EQ(img.at(20, 14), kWhite);
  EXPECT_EQ(img.at(20, 25), kWhite);
  EXPECT_EQ(img.at(70, 60), hi);
  EXPECT_EQ(img.at(65, 50), hi);
  EXPECT_EQ(img.at(74, 69), hi);
  EXPECT_EQ(img.at(75, 60), kWhite);
  EXPECT_EQ(img.at(70, 70), kWhite);
  EXPECT_EQ(img.at(50, 40), kWhite);
}

TEST(Splat, PixelExactEdgesInAFullSizeFrame) {
  // 1 m per pixel over a 1280x720 frame: large coordinates stay exact.
  Cloud c;
  c.add(1000, 100, 200, 50, 1.0);  // -> x [800, 1200), rows [570, 670)
  const Image img = paint(c, WorldWindow{0, 1280, 0, 720}, 1280, 720, Rect{0, 0, 1280, 720});
  const Rgba hi = ColourMap::viridis().at(1.0);
  for (int y = 560; y < 680; ++y) {
    for (int x : {799, 800, 1199, 1200}) {
      const bool inside = x >= 800 && x < 1200 && y >= 570 && y < 670;
      ASSERT_EQ(img.at(x, y), inside ? hi : kWhite) << x << "," << y;
    }
  }
  for (int x = 790; x < 1210; ++x) {
    EXPECT_EQ(img.at(x, 569), kWhite);
    EXPECT_EQ(img.at(x, 570), x >= 800 && x < 1200 ? hi : kWhite);
    EXPECT_EQ(img.at(x, 669), x >= 800 && x < 1200 ? hi : kWhite);
    EXPECT_EQ(img.at(x, 670), kWhite);
  }
}

TEST(Splat, RandomSquareEdgesWithinOnePixelOfTheMap) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(1.0, 9.0), half(0.05, 0.6);
  const WorldWindow w{0, 10, 0, 10};
  const Rect area{3, 5, 137, 131};  // odd sizes: fractional world->pixel map
  const PixelMap map = fit_window(w, area);
  for (int trial = 0; trial < 20; ++trial) {
    Cloud c;
    const double x = pos(rng), y = pos(rng), hw = half(rng), hh = half(rng);
    c.add(x, y, hw, hh, 0.5);
    const Image img = paint(c, w, 150, 150, area);
    int x0 = 1 << 30, x1 = -1, y0 = 1 << 30, y1 = -1;
    for (int py = 0; py < img.height(); ++py) {
      for (int px = 0; px < img.width(); ++px) {
        if (img.at(px, py) != kWhite) {
          x0 = std::min(x0, px), x1 = std::max(x1, px + 1);
          y0 = std::min(y0, py), y1 = std::max(y1, py + 1);
        }
      }
    }
    ASSERT_GE(x1, 0) << "square " << trial << " painted nothing";
    EXPECT_LE(std::abs(x0 - map.x(x - hw)), 1.0) << trial;
    EXPECT_LE(std::abs(x1 - map.x(x + hw)), 1.0) << trial;
    EXPECT_LE(std::abs(y0 - map.y(y + hh)), 1.0) << trial;
    EXPECT_LE(std::abs(y1 - map.y(y - hh)), 1.0) << trial;
  }
}

TEST(Splat, SubPixelPointsStillShowAndTileWithoutGaps) {
  // 0.08 px squares on a 0.1 px grid: every pixel of the block is covered.
  Cloud c;
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 100; ++j) c.add(0.05 + 0.1 * i, 0.05 + 0.1 * j, 0.04, 0.04, 0.0);
  }
  const Image img = paint(c, WorldWindow{0, 100, 0, 100}, 100, 100, Rect{0, 0, 100, 100});
  for (int py = 90; py < 100; ++py) {
    for (int px = 0; px < 10; ++px) EXPECT_NE(img.at(px, py), kWhite) << px << "," << py;
  }
  EXPECT_EQ(img.at(10, 89), kWhite);
}

TEST(Splat, ClipsToTheWindowAndCullsOutsidePoints) {
  Cloud c;
  c.add(-5, 5, 1, 1, 0.0);    // wholly left of the window: culled
  c.add(0, 5, 1, 1, 0.0);     // straddles the left edge: clipped
  c.add(5, 5, NAN, 1, 0.0);   // not finite: skipped
  OffscreenContext ctx(60, 40);
  const PixelMap map = fit_window(WorldWindow{0, 10, 0, 10}, Rect{10, 0, 40, 40});
  Splatter s;
  s.draw(ctx, map, map.box(), c.view(), ColourMap::jet(), 0.0, 1.0);
  EXPECT_EQ(s.last_drawn(), 1u);
  const Image img = ctx.read_image();
  EXPECT_EQ(img.at(9, 20), kWhite);  // left of the box: nothing leaks out
  EXPECT_EQ(img.at(11, 20), ColourMap::jet().at(0));
}

// More points than one draw call takes (kSplatBatch), overlapping squares of
// random colours and a same-colour run across the batches' boundary: the
// image is, pixel for pixel, the squares of snap_square filled one after
// another in the points' order (each pixel whose centre a square covers,
// the last square's colour), as one draw call of them all gave.
TEST(Splat, BatchesPaintTheSquaresInOrderPixelForPixel) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> pos(0.5, 39.5), half(0.01, 0.4), value(0.0, 1.0);
  Cloud c;
  const std::size_t n = kSplatBatch + kSplatBatch / 2 + 17;
  for (std::size_t i = 0; i < n; ++i) c.add(pos(rng), pos(rng), half(rng), half(rng), value(rng));
  // One row of touching squares of one colour across the boundary.
  for (std::size_t i = kSplatBatch - 3; i < kSplatBatch + 3; ++i) {
    c.x[i] = 10.05 + 0.1 * double(i - kSplatBatch), c.y[i] = 20.05;
    c.hw[i] = c.hh[i] = 0.05, c.v[i] = 0.25;
  }
  const WorldWindow w{0, 40, 0, 40};
  const int size = 320;
  const Image img = paint(c, w, size, size, Rect{0, 0, size, size});
  const PixelMap map = fit_window(w, Rect{0, 0, size, size});
  const ColourMap cmap = ColourMap::viridis();
  std::vector<Rgba> expected(std::size_t(size) * size, kWhite);
  for (std::size_t i = 0; i < n; ++i) {
    const PixelSquare q = snap_square(map, c.x[i], c.y[i], c.hw[i], c.hh[i]);
    for (int py = std::max(0, q.y0); py < std::min(size, q.y1); ++py)
      for (int px = std::max(0, q.x0); px < std::min(size, q.x1); ++px)
        expected[std::size_t(py) * size + px] = cmap.map(c.v[i], 0.0, 1.0);
  }
  int wrong = 0;
  for (int py = 0; py < size; ++py)
    for (int px = 0; px < size; ++px)
      wrong += img.at(px, py) != expected[std::size_t(py) * size + px];
  EXPECT_EQ(wrong, 0);
}

// snap_square rounds the squares' edges as std::lround does (halves away
// from zero), at exact halves on both sides of zero and at random places.
TEST(Splat, SnapRoundsEdgesAsLround) {
  const PixelMap map = fit_window(WorldWindow{0, 40, 0, 40}, Rect{0, 0, 40, 40});
  const auto lround_of = [](double v) { return int(std::lround(std::clamp(v, -1e7, 1e7))); };
  std::vector<double> xs;
  for (int k = -6; k <= 6; ++k) xs.push_back(k + 1.25);  // edges at k + 0.5 and k + 2
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> pos(-50, 90);
  for (int i = 0; i < 20000; ++i) xs.push_back(pos(rng));
  int checked = 0;
  for (const double x : xs) {
    const double hw = 0.75;
    const PixelSquare q = snap_square(map, x, x, hw, hw);
    const int lo = lround_of(map.x(x - hw)), hi = lround_of(map.x(x + hw));
    if (hi <= lo) continue;  // one pixel at the middle instead
    ASSERT_EQ(q.x0, lo) << x;
    ASSERT_EQ(q.x1, hi) << x;
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST(Splat, NullArraysAndBadRangeThrow) {
  PointsView v;
  v.count = 3;
  EXPECT_THROW(validate_points(v), InvalidArgument);
  Cloud c;
  c.add(1, 1, 1, 1, 0);
  OffscreenContext ctx(10, 10);
  Splatter s;
  const PixelMap map = fit_window(WorldWindow{0, 2, 0, 2}, Rect{0, 0, 10, 10});
  EXPECT_THROW(s.draw(ctx, map, map.box(), c.view(), ColourMap::viridis(), 1.0, 1.0),
               InvalidArgument);
}

}  // namespace
}  // namespace render
