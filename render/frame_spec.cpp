#include "render/frame_spec.hpp"

#include <algorithm>
#include <cmath>

#include "render/colour_map.hpp"
#include "render/error.hpp"
#include "render/viewport.hpp"

namespace render {

namespace {
constexpr int kMinTextPx = 17;
constexpr int kThumbnailTextPx = 6;
constexpr double kTextFraction = 0.0165;
}  // namespace

int frame_text_px(int width, int height) {
  const int wanted = std::max(kMinTextPx, int(std::lround(width * kTextFraction)));
  // A thumbnail too low for that still gets its axes, in smaller text.
  return std::min(wanted, std::max(kThumbnailTextPx, height / 12));
}

void validate_frame_spec(const FrameSpec& s) {
  if (s.width < 64 || s.height < 64 || s.width > 16384 || s.height > 16384) {
    throw InvalidArgument("frame size " + std::to_string(s.width) + "x" +
                          std::to_string(s.height) + " is outside 64..16384");
  }
  validate_window(WorldWindow{s.world_x0, s.world_x1, s.world_y0, s.world_y1});
  (void)ColourMap::by_name(s.colour_map);  // throws on unknown names
  validate_range(s.range_lo, s.range_hi);
  if (!(s.bar_scale > 0) || !std::isfinite(s.bar_scale)) {
    throw InvalidArgument("colour bar scale " + std::to_string(s.bar_scale) +
                          " is not a positive number");
  }
  if (s.text_px < 0 || s.text_px > 256) {
    throw InvalidArgument("text size " + std::to_string(s.text_px) + " px is outside 0..256");
  }
  if (s.show_time && !std::isfinite(s.time)) {
    throw InvalidArgument("frame time " + std::to_string(s.time) + " is not finite");
  }
}

}  // namespace render
