// The colour bar on its own, and the text-size rule of annotated frames.
#include <gtest/gtest.h>

#include <vector>

#include "render/colour_bar.hpp"
#include "render/error.hpp"
#include "render/painter.hpp"

namespace render {
namespace {

TEST(ColourBar, StandaloneBarRunsLowToHighUpwards) {
  Font font;
  ColourBarSpec s;
  s.range_lo = -3, s.range_hi = 7;
  s.label = "displacement [mm]";
  const Image img = paint_colour_bar(font, s, 20, 200, 4);
  const ColourMap cmap = ColourMap::viridis();
  // The strip starts at x = pad + 1 below half a tick line of room.
  const int top = 4 + font.line_height(s.tick_px) / 2 + 1;
  // Each row shows the value at its centre: row 1 of 200 is 1.5 % below the top.
  EXPECT_EQ(img.at(15, top + 1), cmap.map(7 - 10 * 1.5 / 200, -3, 7));
  EXPECT_EQ(img.at(15, top + 198), cmap.map(-3 + 10 * 1.5 / 200, -3, 7));
  EXPECT_GT(img.width(), 20 + 8 + font.text_width("-2", s.tick_px));
}

TEST(ColourBar, CategoricalNamesSitAtTheirTicks) {
  ColourBarSpec s;
  s.colour_map = "categorical";
  s.range_lo = 0, s.range_hi = 1;
  s.names = {"soil", "house"};
  const Ticks t = colour_bar_ticks(s, 300);
  ASSERT_EQ(t.labels.size(), 2u);
  EXPECT_EQ(t.labels[0], "soil");
  EXPECT_EQ(t.labels[1], "house");
  EXPECT_DOUBLE_EQ(t.values[1], 1.0);
}

TEST(ColourBar, TooSmallStripThrows) {
  Font font;
  EXPECT_THROW(paint_colour_bar(font, ColourBarSpec{}, 0, 100, 2), InvalidArgument);
}

// Issue 14: tick labels at least 12 px tall in a 480 px wide GIF frame, and
// scaling with the width above it.
TEST(FrameText, DigitsAtLeastTwelvePixelsTallAt480AndScaleWithWidth) {
  Font font;
  for (const int width : {480, 1280, 2560}) {
    FrameSpec s;
    s.width = width, s.height = width * 9 / 16;
    s.world_x1 = 116, s.world_y1 = 20;
    const FrameLayout L = layout_frame(font, s);
    EXPECT_GE(ink_height(font.render("0123456789", L.tick_px)), 12) << width << " px";
    EXPECT_GE(L.tick_px, int(0.0165 * width)) << width << " px";
  }
}

// Issue 14: in a 480 px GIF frame of its own height a long title takes more
// lines, and a bar label longer than its bar more lines, both at full size,
// whichever side the bar is on.
TEST(FrameText, TitleAndBarLabelKeepTheirSizeInA480PxFrame) {
  Font font;
  for (const double world_h : {18.0, 100.0}) {  // a slope (bar below), a column (bar right)
    FrameSpec s;
    s.width = 480;
    s.world_x0 = 28, s.world_x1 = 78, s.world_y1 = world_h;
    s.title = "paper-slope-phi20-n1661 \u2014 horizontal displacement (slide)";
    s.field_label = "relative yield (1: at yield, 2: yielded this step)";
    s.height = fit_frame_height(font, s);
    const FrameLayout L = layout_frame(font, s);
    EXPECT_EQ(L.bar.side, world_h < 50 ? BarSide::Below : BarSide::Right) << world_h;
    ASSERT_GE(L.title_lines.size(), 2u) << world_h;
    for (const std::string& line : L.title_lines)
      EXPECT_LE(font.text_width(line, L.title_px), s.width - 2 * L.margin) << line;
    const int length = std::max(L.colour_bar.w, L.colour_bar.h);
    const BarLabel label = bar_label_lines(font, L.bar, length);
    EXPECT_EQ(label.px, L.label_px) << world_h;
    for (const std::string& line : label.lines)
      EXPECT_LE(font.text_width(line, label.px), length) << line;
    EXPECT_GE(ink_height(font.render("0123456789", label.px)), 12) << world_h;
  }
}

TEST(FrameText, NoHeadingRowWithoutTitleOrTime) {
  Font font;
  FrameSpec s;
  s.world_x1 = 116, s.world_y1 = 20;
  const int with = layout_frame(font, s).plot_area.y;
  s.show_time = false;
  s.title.clear();
  const FrameLayout L = layout_frame(font, s);
  EXPECT_LT(L.plot_area.y, with - font.line_height(L.title_px) / 2);
}

}  // namespace
}  // namespace render
