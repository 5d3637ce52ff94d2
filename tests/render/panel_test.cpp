#include <gtest/gtest.h>

#include "render/error.hpp"
#include "render/panel.hpp"

namespace render {
namespace {

// Every pixel a function of (x, y, id) so a misplaced copy shows.
Image tile(int w, int h, int id) {
  Image img(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      img.set(x, y, Rgba{std::uint8_t(x * 3 + id), std::uint8_t(y * 3), std::uint8_t(40 * id), 255});
    }
  }
  return img;
}

TEST(Panel, SizeAndOffsetsOfATwoByTwoPage) {
  Font font;
  const std::vector<Image> imgs = {tile(60, 40, 1), tile(60, 40, 2), tile(60, 40, 3),
                                   tile(60, 40, 4)};
  PanelStyle st;
  st.margin = 10, st.gap = 8;
  const Image page = compose_panel(font, imgs, {"(a)", "(b)", "(c)", "(d)"}, 2, 2,
                                   "Slope collapse", st);
  const PanelLayout L = layout_panel(font, imgs, 2, 2, true, true, st);
  EXPECT_EQ(page.width(), L.width);
  EXPECT_EQ(page.height(), L.height);
  EXPECT_EQ(L.width, 2 * 10 + 2 * 60 + 8);
  const int title_h = font.line_height(st.title_px) + st.gap;
  const int caption_h = st.gap / 2 + font.line_height(st.caption_px);
  EXPECT_EQ(L.height, 2 * 10 + title_h + 2 * (40 + caption_h) + 8);
  EXPECT_EQ(L.images[0], (Rect{10, 10 + title_h, 60, 40}));
  EXPECT_EQ(L.images[3], (Rect{10 + 68, 10 + title_h + 40 + caption_h + 8, 60, 40}));
  for (std::size_t i = 0; i < imgs.size(); ++i) {
    EXPECT_EQ(page.crop(L.images[i]), imgs[i]) << "image " << i;
  }
  // Captions and title put ink in their strips.
  int ink = 0;
  const Rect c = L.captions[1];
  for (int y = c.y; y < c.bottom(); ++y) {
    for (int x = c.x; x < c.right(); ++x) ink += page.at(x, y) != kWhite;
  }
  EXPECT_GT(ink, 10);
}

TEST(Panel, SmallerImagesAreCentredInTheirCell) {
  Font font;
  const std::vector<Image> imgs = {tile(50, 30, 1), tile(30, 10, 2), tile(20, 20, 3)};
  const Image page = compose_panel(font, imgs, {}, 1, 3, "");
  const PanelLayout L = layout_panel(font, imgs, 1, 3, false, false);
  EXPECT_EQ(L.cell_w, 50);
  EXPECT_EQ(L.cell_h, 30);
  EXPECT_EQ(L.images[1].x, 16 + 50 + 16 + 10);
  EXPECT_EQ(L.images[1].y, 16 + 10);
  EXPECT_EQ(page.height(), 2 * 16 + 30);
  for (std::size_t i = 0; i < imgs.size(); ++i) EXPECT_EQ(page.crop(L.images[i]), imgs[i]);
}

TEST(Panel, RejectsBadGrids) {
  Font font;
  const std::vector<Image> imgs = {tile(4, 4, 1), tile(4, 4, 2), tile(4, 4, 3)};
  EXPECT_THROW(compose_panel(font, imgs, {}, 1, 2, ""), InvalidArgument);
  EXPECT_THROW(compose_panel(font, imgs, {"a"}, 2, 2, ""), InvalidArgument);
  EXPECT_THROW(compose_panel(font, {}, {}, 2, 2, ""), InvalidArgument);
  EXPECT_THROW(compose_panel(font, imgs, {}, 0, 2, ""), InvalidArgument);
}

}  // namespace
}  // namespace render
