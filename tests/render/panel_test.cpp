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

// Ink (non-background pixels) inside r.
int ink_in(const Image& page, const Rect& r) {
  int ink = 0;
  for (int y = r.y; y < r.bottom(); ++y)
    for (int x = r.x; x < r.right(); ++x) ink += page.at(x, y) != kWhite;
  return ink;
}

TEST(Panel, SizeAndOffsetsOfATwoByTwoPageWithCaptionsAbove) {
  Font font;
  const std::vector<Image> imgs = {tile(60, 40, 1), tile(60, 40, 2), tile(60, 40, 3),
                                   tile(60, 40, 4)};
  PanelStyle st;
  st.margin = 10, st.gap = 8;
  const Image page = compose_panel(font, imgs, {"", "", "", ""}, 2, 2, "Slope", st);
  const PanelLayout L = layout_panel(font, imgs, 2, 2, 1, 1, st);
  EXPECT_EQ(page.width(), L.width);
  EXPECT_EQ(page.height(), L.height);
  EXPECT_EQ(L.width, 2 * 10 + 2 * 60 + 8);
  const int title_h = font.line_height(st.title_px) + st.gap;
  const int caption_h = font.line_height(st.caption_px);
  EXPECT_EQ(L.height, 2 * 10 + title_h + 2 * (40 + caption_h) + 8);
  EXPECT_EQ(L.images[0], (Rect{10, 10 + title_h + caption_h, 60, 40}));
  EXPECT_EQ(L.images[3], (Rect{10 + 68, 10 + title_h + 2 * caption_h + 40 + 8, 60, 40}));
  for (std::size_t i = 0; i < imgs.size(); ++i) {
    EXPECT_EQ(page.crop(L.images[i]), imgs[i]) << "image " << i;
    // The letter sits in the strip right above its own panel.
    EXPECT_EQ(L.captions[i].bottom(), L.images[i].y);
    EXPECT_GT(ink_in(page, L.captions[i]), 10) << "caption " << i;
  }
}

TEST(Panel, FigureTextIsTheSmallestSizeWithTallEnoughDigits) {
  Font font;
  const int px = figure_text_px(font, 2600);
  EXPECT_GE(ink_height(font.render("0123456789", px)), 0.012 * 2600);
  EXPECT_LT(ink_height(font.render("0123456789", px - 1)), 0.012 * 2600);
}

TEST(Panel, ALongTitleWrapsToThePageWidth) {
  Font font;
  const std::vector<Image> imgs = {tile(60, 40, 1)};
  PanelStyle st;
  st.margin = 10;
  const std::string title = "A title much longer than the sixty pixels of the one image";
  const Image page = compose_panel(font, imgs, {}, 1, 1, title, st);
  const int lines = int(wrap_text(font, title, st.title_px, 60).size());
  ASSERT_GE(lines, 2);
  EXPECT_EQ(page.width(), 80);
  EXPECT_EQ(page.height(), 20 + lines * font.line_height(st.title_px) + st.gap + 40);
}

TEST(Panel, LettersRunRowMajor) {
  EXPECT_EQ(panel_letter(0), "(a)");
  EXPECT_EQ(panel_letter(3), "(d)");
  EXPECT_EQ(panel_letter(26), "(27)");
}

TEST(Panel, LongCaptionsWrapToTheCellWidth) {
  Font font;
  const std::string text = "phi = 10 deg, 8370 points: at rest after 19.8 s, runout 59.1 m";
  const std::vector<std::string> lines = wrap_text(font, text, 18, 200);
  ASSERT_GE(lines.size(), 2u);
  for (const std::string& l : lines) EXPECT_LE(font.text_width(l, 18), 200) << l;
  std::string joined;
  for (const std::string& l : lines) joined += (joined.empty() ? "" : " ") + l;
  EXPECT_EQ(joined, text);
}

TEST(Panel, SharedColourBarGoesRightOfTheGrid) {
  Font font;
  const std::vector<Image> imgs = {tile(60, 40, 1), tile(60, 40, 2)};
  const Image bar = tile(12, 70, 5);
  PanelStyle st;
  st.margin = 10, st.gap = 8;
  const Image page = compose_panel(font, imgs, {}, 2, 1, "", st, &bar);
  const PanelLayout L = layout_panel(font, imgs, 2, 1, 0, 0, st, &bar);
  EXPECT_EQ(L.width, 10 + 60 + 8 + 12 + 10);
  EXPECT_EQ(L.colour_bar.x, 10 + 60 + 8);
  EXPECT_EQ(L.colour_bar.y, 10 + (2 * 40 + 8 - 70) / 2);
  EXPECT_EQ(page.crop(L.colour_bar), bar);
}

TEST(Panel, SmallerImagesAreCentredInTheirCell) {
  Font font;
  const std::vector<Image> imgs = {tile(50, 30, 1), tile(30, 10, 2), tile(20, 20, 3)};
  const Image page = compose_panel(font, imgs, {}, 1, 3, "");
  const PanelLayout L = layout_panel(font, imgs, 1, 3, 0, 0);
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
