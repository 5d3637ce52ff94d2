#include "render/image_diff.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "render/error.hpp"
#include "render/png_io.hpp"

namespace render {

namespace {

int max_delta(const std::uint8_t* a, const std::uint8_t* b) {
  int d = 0;
  for (int k = 0; k < 4; ++k) d = std::max(d, std::abs(int(a[k]) - int(b[k])));
  return d;
}

}  // namespace

std::string DiffResult::summary() const {
  char buf[256];
  if (!size_matches) {
    std::snprintf(buf, sizeof buf, "size differs: actual %dx%d, expected %dx%d", actual_width,
                  actual_height, expected_width, expected_height);
  } else {
    std::snprintf(buf, sizeof buf,
                  "%zu of %zu pixels differ (%.4f%%), largest channel difference %d",
                  differing_pixels, total_pixels, 100.0 * differing_fraction,
                  max_channel_delta);
  }
  return buf;
}

DiffResult diff_images(const Image& actual, const Image& expected, const DiffTolerance& tol) {
  DiffResult r;
  r.actual_width = actual.width(), r.actual_height = actual.height();
  r.expected_width = expected.width(), r.expected_height = expected.height();
  r.size_matches = r.actual_width == r.expected_width && r.actual_height == r.expected_height;
  if (!r.size_matches) return r;
  r.total_pixels = std::size_t(actual.width()) * actual.height();
  const std::uint8_t* a = actual.data();
  const std::uint8_t* e = expected.data();
  for (std::size_t i = 0; i < r.total_pixels; ++i, a += 4, e += 4) {
    const int d = max_delta(a, e);
    r.max_channel_delta = std::max(r.max_channel_delta, d);
    if (d > tol.per_channel) ++r.differing_pixels;
  }
  r.differing_fraction = r.total_pixels ? double(r.differing_pixels) / r.total_pixels : 0.0;
  r.passed = r.differing_fraction <= tol.max_fraction;
  return r;
}

Image diff_image(const Image& actual, const Image& expected, const DiffTolerance& tol) {
  if (actual.width() != expected.width() || actual.height() != expected.height()) {
    throw InvalidArgument("diff_image: sizes differ");
  }
  Image out(actual.width(), actual.height());
  for (int y = 0; y < actual.height(); ++y) {
    const std::uint8_t* a = actual.row(y);
    const std::uint8_t* e = expected.row(y);
    std::uint8_t* o = out.row(y);
    for (int x = 0; x < actual.width(); ++x, a += 4, e += 4, o += 4) {
      if (max_delta(a, e) > tol.per_channel) {
        o[0] = 255, o[1] = 0, o[2] = 0;
      } else {
        // Faded luminance keeps the picture recognisable under the red.
        const int lum = (e[0] * 77 + e[1] * 150 + e[2] * 29) >> 8;
        o[0] = o[1] = o[2] = std::uint8_t(170 + lum / 3);
      }
      o[3] = 255;
    }
  }
  return out;
}

CheckResult check_against_file(const Image& actual, const std::string& expected_path,
                               const DiffTolerance& tol) {
  namespace fs = std::filesystem;
  CheckResult c;
  const fs::path expected(expected_path);
  const fs::path dir = expected.parent_path();
  const std::string stem = expected.stem().string();
  const std::string actual_path = (dir / (stem + ".actual.png")).string();
  const std::string diff_path = (dir / (stem + ".diff.png")).string();

  if (!fs::exists(expected)) {
    write_png(actual, actual_path);
    c.message = "expected image " + expected_path + " does not exist; wrote " + actual_path;
    return c;
  }
  const Image want = read_png(expected_path);
  c.diff = diff_images(actual, want, tol);
  if (c.diff.passed) {
    c.passed = true;
    return c;
  }
  write_png(actual, actual_path);
  c.message = expected_path + ": " + c.diff.summary() + "; tolerance " +
              std::to_string(tol.per_channel) + " per channel, " +
              std::to_string(100.0 * tol.max_fraction) + "% of pixels; wrote " + actual_path;
  if (c.diff.size_matches) {
    write_png(diff_image(actual, want, tol), diff_path);
    c.message += " and " + diff_path;
  }
  return c;
}

}  // namespace render
