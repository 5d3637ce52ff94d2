#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include "render/error.hpp"
#include "render/gl_context.hpp"
#include "render/image.hpp"

namespace render {
namespace {

TEST(Image, FillsAndAddressesTopRowFirst) {
  Image img(4, 3, Rgba{1, 2, 3, 4});
  EXPECT_EQ(img.width(), 4);
  EXPECT_EQ(img.height(), 3);
  EXPECT_EQ(img.byte_size(), 4u * 3u * 4u);
  img.set(1, 0, kBlack);
  EXPECT_EQ(img.data()[4], 0);  // pixel (1, 0) is the second in memory
  EXPECT_EQ(img.at(1, 0), kBlack);
  EXPECT_EQ(img.at(3, 2), (Rgba{1, 2, 3, 4}));
}

TEST(Image, RejectsBadSizesAndCoordinates) {
  EXPECT_THROW(Image(-1, 3), InvalidArgument);
  EXPECT_THROW(Image(20000, 3), InvalidArgument);
  Image img(2, 2);
  EXPECT_THROW(img.pixel(2, 0), InvalidArgument);
}

TEST(Image, FillRectAndBlitClipAtTheEdges) {
  Image img(5, 5, kWhite);
  img.fill_rect(Rect{3, 3, 10, 10}, kBlack);
  EXPECT_EQ(img.at(4, 4), kBlack);
  EXPECT_EQ(img.at(2, 2), kWhite);
  Image small(2, 2, Rgba{9, 9, 9, 255});
  img.blit(small, -1, -1);
  EXPECT_EQ(img.at(0, 0), (Rgba{9, 9, 9, 255}));
  EXPECT_EQ(img.at(1, 1), kWhite);
  EXPECT_EQ(img.crop(Rect{3, 3, 2, 2}).at(1, 1), kBlack);
}

TEST(Image, BlendIsSourceOver) {
  Image img(1, 1, kWhite);
  img.blend(0, 0, kBlack, 255);
  EXPECT_EQ(img.at(0, 0), kBlack);
  Image half(1, 1, kWhite);
  half.blend(0, 0, kBlack, 128);
  EXPECT_NEAR(half.at(0, 0).r, 127, 1);
  half.blend(5, 5, kBlack, 255);  // outside: ignored
}

TEST(OffscreenContext, ClearsAndFlipsRowsToTopFirst) {
  OffscreenContext ctx(8, 6);
  EXPECT_FALSE(ctx.renderer().empty());
  ctx.make_current();
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  // GL counts rows from the bottom: its top two rows are 4 and 5.
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 4, 8, 2);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  const Image img = ctx.read_image();
  ASSERT_EQ(img.width(), 8);
  ASSERT_EQ(img.height(), 6);
  EXPECT_EQ(img.at(3, 0), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(img.at(3, 1), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(img.at(3, 2), kWhite);
  EXPECT_EQ(img.at(3, 5), kWhite);
}

TEST(OffscreenContext, SeveralContextsCoexist) {
  OffscreenContext a(4, 4);
  {
    OffscreenContext b(6, 2);
    b.resize(3, 3);
    EXPECT_EQ(b.read_image().width(), 3);
  }
  EXPECT_EQ(a.read_image().height(), 4);
  EXPECT_THROW(OffscreenContext(0, 4), InvalidArgument);
}

}  // namespace
}  // namespace render
