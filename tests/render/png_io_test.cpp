#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "render/error.hpp"
#include "render/png_io.hpp"
#include "test_support.hpp"

namespace render {
namespace {

namespace fs = std::filesystem;

Image random_image(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  Image img(w, h);
  for (std::size_t i = 0; i < img.byte_size(); ++i) img.data()[i] = std::uint8_t(rng());
  return img;
}

std::size_t files_in(const std::string& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.is_regular_file();
  return n;
}

TEST(Png, RoundTripIsLossless) {
  render_test::TempDir dir;
  for (int level : {0, 3, 9}) {
    const Image img = random_image(37, 23, unsigned(level) + 1);
    const std::string path = dir.file("rt.png");
    write_png(img, path, PngOptions{level});
    EXPECT_EQ(read_png(path), img) << "level " << level;
  }
}

TEST(Png, WritingLeavesNoTemporaryBehind) {
  render_test::TempDir dir;
  write_png(random_image(8, 8, 1), dir.file("a.png"));
  write_png(random_image(8, 8, 2), dir.file("a.png"));  // overwrite in place
  EXPECT_EQ(files_in(dir.path()), 1u);
  EXPECT_EQ(read_png(dir.file("a.png")), random_image(8, 8, 2));
}

TEST(Png, FailedWriteThrowsAndLeavesNothing) {
  render_test::TempDir dir;
  const std::string bad = dir.file("missing_dir/frame.png");
  try {
    write_png(random_image(4, 4, 3), bad);
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), bad);
    EXPECT_NE(std::string(e.what()).find(bad), std::string::npos);
  }
  EXPECT_EQ(files_in(dir.path()), 0u);
}

TEST(Png, ReadingMissingFileThrowsWithItsName) {
  render_test::TempDir dir;
  const std::string path = dir.file("nope.png");
  try {
    read_png(path);
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
  }
}

TEST(Png, ReadingCorruptFilesThrowsWithItsName) {
  render_test::TempDir dir;
  const std::string not_png = dir.file("text.png");
  std::ofstream(not_png) << "this is not a png";
  EXPECT_THROW(read_png(not_png), FileError);

  // A real PNG cut short: header fine, data missing.
  const std::string cut = dir.file("cut.png");
  write_png(random_image(64, 64, 4), cut);
  fs::resize_file(cut, fs::file_size(cut) / 2);
  try {
    read_png(cut);
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("cut.png"), std::string::npos);
  }
}

}  // namespace
}  // namespace render
