// Material edges: a line where two materials touch, none against empty
// space, and nothing at all without material ids.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "render/outline.hpp"

namespace render {
namespace {

struct Squares {
  std::vector<double> x, y, h, v;
  std::vector<std::uint8_t> m;
  void add(double cx, double cy, std::uint8_t id) {
    x.push_back(cx), y.push_back(cy), h.push_back(0.5), v.push_back(0), m.push_back(id);
  }
  PointsView view(bool with_material) const {
    PointsView p{x.size(), x.data(), y.data(), h.data(), h.data(), v.data()};
    if (with_material) p.material = m.data();
    return p;
  }
};

// A 10 x 4 m slab of material 0 with a 2 x 2 m block of material 1 on top,
// at 10 px per metre, in a 200 x 100 px image.
Squares slab_and_block() {
  Squares s;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 10; ++i) s.add(i + 0.5, j + 0.5, 0);
  for (int j = 4; j < 6; ++j)
    for (int i = 4; i < 6; ++i) s.add(i + 0.5, j + 0.5, 1);
  return s;
}

TEST(Outline, LinesWhereTwoMaterialsTouchOnly) {
  const PixelMap map(WorldWindow{0, 20, 0, 10}, 0, 0, 10);  // y = 10 m at row 0
  const Squares s = slab_and_block();
  Image img(200, 100, kWhite);
  draw_material_edges(img, map, Rect{0, 0, 200, 100}, s.view(true), kBlack, 2);
  // The block spans x 40..59, rows 40..59 (y 6..4 m) and sits on the slab's
  // top row 60: the rows either side of that contact are inked.
  EXPECT_EQ(img.at(50, 59), kBlack);
  EXPECT_EQ(img.at(50, 60), kBlack);
  EXPECT_EQ(img.at(50, 58), kWhite);
  EXPECT_EQ(img.at(50, 61), kWhite);
  // Borders with empty space stay unlined: the block's top and sides, the slab's.
  EXPECT_EQ(img.at(50, 40), kWhite);
  EXPECT_EQ(img.at(40, 50), kWhite);
  EXPECT_EQ(img.at(10, 60), kWhite);
  int ink = 0;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 200; ++x) ink += img.at(x, y) == kBlack;
  EXPECT_EQ(ink, 2 * 20);
}

TEST(Outline, NoMaterialIdsNoLines) {
  const PixelMap map(WorldWindow{0, 20, 0, 10}, 0, 0, 10);
  const Squares s = slab_and_block();
  Image img(200, 100, kWhite);
  draw_material_edges(img, map, Rect{0, 0, 200, 100}, s.view(false), kBlack, 2);
  EXPECT_EQ(img, Image(200, 100, kWhite));
}

}  // namespace
}  // namespace render
