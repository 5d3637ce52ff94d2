#include <gtest/gtest.h>

#include "render/error.hpp"
#include "render/font.hpp"

namespace render {
namespace {

// Ink anywhere in the image outside r, and total ink inside r.
struct InkCount {
  long inside = 0, outside = 0;
};
InkCount count_ink(const Image& img, const Rect& r) {
  InkCount n;
  for (int y = 0; y < img.height(); ++y) {
    for (int x = 0; x < img.width(); ++x) {
      if (img.at(x, y) != kWhite) (r.contains(x, y) ? n.inside : n.outside)++;
    }
  }
  return n;
}

TEST(Font, MissingFileThrowsNamingIt) {
  try {
    Font f("/no/such/font.ttf");
    FAIL() << "expected FontError";
  } catch (const FontError& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/font.ttf"), std::string::npos);
  }
}

TEST(Font, TextLandsInsideItsBoundingBox) {
  Font font;
  const char* samples[] = {"x [m]", "t = 12.50 s", "Jyg|Q()", "-0.25", "\xc2\xb0 \xce\xb5"};
  for (const char* text : samples) {
    for (auto h : {HAlign::Left, HAlign::Centre, HAlign::Right}) {
      for (auto v : {VAlign::Top, VAlign::Middle, VAlign::Baseline, VAlign::Bottom}) {
        Image img(300, 80, kWhite);
        const Rect r = font.draw(img, text, 20, 150, 40, h, v, kBlack);
        const InkCount n = count_ink(img, r);
        EXPECT_EQ(n.outside, 0) << text;
        EXPECT_GT(n.inside, 20) << text;
      }
    }
  }
}

TEST(Font, AnchorsPlaceTheBox) {
  Font font;
  Image img(200, 100, kWhite);
  const TextMask m = font.render("Title", 24);
  EXPECT_EQ(font.text_width("Title", 24), m.width);
  const Rect left = draw_mask(img, m, 10, 50, HAlign::Left, VAlign::Baseline, kBlack);
  EXPECT_EQ(left.x, 10);
  EXPECT_EQ(left.y + m.baseline, 50);
  const Rect right = draw_mask(img, m, 190, 5, HAlign::Right, VAlign::Top, kBlack);
  EXPECT_EQ(right.right(), 190);
  EXPECT_EQ(right.y, 5);
  EXPECT_GE(m.height, font.line_height(24) - 1);
  // Wider text at a bigger size.
  EXPECT_GT(font.text_width("Title", 48), m.width);
}

TEST(Font, RotatedTextReadsBottomToTop) {
  Font font;
  const TextMask m = font.render("y [m]", 18);
  const TextMask r = rotate_ccw(m);
  EXPECT_EQ(r.width, m.height);
  EXPECT_EQ(r.height, m.width);
  // Source column 0 (start of the text) becomes the bottom row; the top
  // source row becomes the left column.
  for (int y = 0; y < m.height; ++y) {
    EXPECT_EQ(r.at(y, r.height - 1), m.at(0, y));
    EXPECT_EQ(r.at(y, 0), m.at(m.width - 1, y));
  }
  Image img(60, 120, kWhite);
  const Rect box = draw_mask(img, r, 30, 60, HAlign::Centre, VAlign::Middle, kBlack);
  EXPECT_EQ(count_ink(img, box).outside, 0);
  EXPECT_GT(count_ink(img, box).inside, 20);
}

TEST(Font, BadUtf8AndSizesThrow) {
  Font font;
  EXPECT_THROW(font.render("\xff", 12), FontError);
  EXPECT_THROW(font.render("\xc2", 12), FontError);
  EXPECT_THROW(font.render("ok", 1), FontError);
  EXPECT_EQ(decode_utf8("a\xc2\xb0"), std::u32string(U"a\u00b0"));
}

}  // namespace
}  // namespace render
