#include <gtest/gtest.h>

#include <filesystem>

#include "render/image_diff.hpp"
#include "render/png_io.hpp"
#include "test_support.hpp"

namespace render {
namespace {

namespace fs = std::filesystem;

Image pattern(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) img.set(x, y, Rgba{std::uint8_t(x * 7), std::uint8_t(y * 5), 90, 255});
  }
  return img;
}

TEST(ImageDiff, IdenticalImagesPass) {
  const Image a = pattern(20, 10);
  const DiffResult r = diff_images(a, a);
  EXPECT_TRUE(r.passed);
  EXPECT_EQ(r.differing_pixels, 0u);
  EXPECT_EQ(r.total_pixels, 200u);
  EXPECT_EQ(r.max_channel_delta, 0);
}

TEST(ImageDiff, OneChangedPixelBeyondToleranceIsCounted) {
  const Image a = pattern(20, 10);
  Image b = a;
  Rgba p = b.at(3, 4);
  p.g = std::uint8_t(p.g + 10);
  b.set(3, 4, p);
  Rgba q = b.at(5, 5);
  q.b = std::uint8_t(q.b + 2);  // within tolerance 2
  b.set(5, 5, q);

  const DiffResult strict = diff_images(b, a, DiffTolerance{2, 0.0});
  EXPECT_FALSE(strict.passed);
  EXPECT_EQ(strict.differing_pixels, 1u);
  EXPECT_EQ(strict.max_channel_delta, 10);
  EXPECT_DOUBLE_EQ(strict.differing_fraction, 1.0 / 200.0);
  EXPECT_NE(strict.summary().find("1 of 200"), std::string::npos);

  EXPECT_TRUE(diff_images(b, a, DiffTolerance{2, 0.01}).passed);  // 0.5% allowed
  EXPECT_TRUE(diff_images(b, a, DiffTolerance{10, 0.0}).passed);
  const Image d = diff_image(b, a, DiffTolerance{2, 0.0});
  EXPECT_EQ(d.at(3, 4), (Rgba{255, 0, 0, 255}));
  EXPECT_NE(d.at(5, 5), (Rgba{255, 0, 0, 255}));
}

TEST(ImageDiff, SizeMismatchFails) {
  const DiffResult r = diff_images(pattern(4, 4), pattern(4, 5));
  EXPECT_FALSE(r.size_matches);
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.summary().find("4x5"), std::string::npos);
}

TEST(ImageDiff, FailureWritesActualAndDiffNextToExpected) {
  render_test::TempDir dir;
  const std::string expected = dir.file("golden.png");
  const Image a = pattern(16, 16);
  write_png(a, expected);
  EXPECT_TRUE(check_against_file(a, expected).passed);
  EXPECT_FALSE(fs::exists(dir.file("golden.actual.png")));

  Image b = a;
  b.fill_rect(Rect{0, 0, 4, 4}, kBlack);
  const CheckResult c = check_against_file(b, expected, DiffTolerance{0, 0.01});
  EXPECT_FALSE(c.passed);
  EXPECT_EQ(c.diff.differing_pixels, 16u);
  EXPECT_NE(c.message.find("16 of 256"), std::string::npos) << c.message;
  EXPECT_NE(c.message.find("golden.diff.png"), std::string::npos) << c.message;
  ASSERT_TRUE(fs::exists(dir.file("golden.actual.png")));
  ASSERT_TRUE(fs::exists(dir.file("golden.diff.png")));
  EXPECT_EQ(read_png(dir.file("golden.actual.png")), b);
  EXPECT_EQ(read_png(dir.file("golden.diff.png")).at(1, 1), (Rgba{255, 0, 0, 255}));
}

TEST(ImageDiff, MissingExpectedFileFailsAndWritesActual) {
  render_test::TempDir dir;
  const CheckResult c = check_against_file(pattern(4, 4), dir.file("new.png"));
  EXPECT_FALSE(c.passed);
  EXPECT_NE(c.message.find("new.png"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir.file("new.actual.png")));
}

}  // namespace
}  // namespace render
