#include "render/frame_spec.hpp"

#include <cmath>

#include "render/colour_map.hpp"
#include "render/error.hpp"
#include "render/viewport.hpp"

namespace render {

void validate_frame_spec(const FrameSpec& s) {
  if (s.width < 64 || s.height < 64 || s.width > 16384 || s.height > 16384) {
    throw InvalidArgument("frame size " + std::to_string(s.width) + "x" +
                          std::to_string(s.height) + " is outside 64..16384");
  }
  validate_window(WorldWindow{s.world_x0, s.world_x1, s.world_y0, s.world_y1});
  (void)ColourMap::by_name(s.colour_map);  // throws on unknown names
  validate_range(s.range_lo, s.range_hi);
  if (s.show_time && !std::isfinite(s.time)) {
    throw InvalidArgument("frame time " + std::to_string(s.time) + " is not finite");
  }
}

}  // namespace render
