#pragma once
// Image comparison for golden-image tests in any test folder.
#include <cstddef>
#include <string>

#include "render/image.hpp"

namespace render {

struct DiffTolerance {
  int per_channel = 0;        // a pixel differs if any channel differs by more
  double max_fraction = 0.0;  // largest allowed share of differing pixels
};

struct DiffResult {
  bool size_matches = false;
  int actual_width = 0, actual_height = 0, expected_width = 0, expected_height = 0;
  std::size_t differing_pixels = 0;
  std::size_t total_pixels = 0;
  double differing_fraction = 0.0;
  int max_channel_delta = 0;  // over all pixels and channels
  bool passed = false;
  // One line with the numbers, for failure messages.
  std::string summary() const;
};

DiffResult diff_images(const Image& actual, const Image& expected,
                       const DiffTolerance& tol = {});

// Red where a pixel differs beyond tolerance, a faded grey copy of the
// expected image elsewhere. Sizes must match (InvalidArgument otherwise).
Image diff_image(const Image& actual, const Image& expected, const DiffTolerance& tol = {});

struct CheckResult {
  bool passed = false;
  std::string message;  // empty when passed
  DiffResult diff;
};

// Compares against the PNG at expected_path. On failure writes
// <stem>.actual.png and (sizes permitting) <stem>.diff.png next to it and
// returns a message with the numbers and those paths. A missing expected
// file fails the same way, so a new golden can be reviewed and copied in.
CheckResult check_against_file(const Image& actual, const std::string& expected_path,
                               const DiffTolerance& tol = {});

}  // namespace render
