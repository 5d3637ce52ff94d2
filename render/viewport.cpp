#include "render/viewport.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "render/error.hpp"

namespace render {

void validate_window(const WorldWindow& w) {
  const double v[4] = {w.x0, w.x1, w.y0, w.y1};
  const char* names[4] = {"world_x0", "world_x1", "world_y0", "world_y1"};
  for (int i = 0; i < 4; ++i) {
    if (!std::isfinite(v[i])) {
      throw InvalidArgument(std::string(names[i]) + " is not finite");
    }
  }
  if (!(w.x1 > w.x0) || !(w.y1 > w.y0)) {
    std::ostringstream s;
    s << "world window [" << w.x0 << ", " << w.x1 << "] x [" << w.y0 << ", " << w.y1
      << "] is empty or inverted (need x0 < x1 and y0 < y1)";
    throw InvalidArgument(s.str());
  }
}

Rect PixelMap::box() const {
  // Nearest pixel edges, the same rounding the splat uses for square edges,
  // so points touching the window's edge fill it to the frame (rounding
  // outward left an empty sliver row or column inside the frame).
  const int x0 = int(std::lround(x(window_.x0)));
  const int x1 = int(std::lround(x(window_.x1)));
  const int y0 = int(std::lround(y(window_.y1)));
  const int y1 = int(std::lround(y(window_.y0)));
  return Rect{x0, y0, std::max(x1 - x0, 1), std::max(y1 - y0, 1)};
}

PixelMap fit_window(const WorldWindow& window, const Rect& area) {
  validate_window(window);
  if (area.w <= 0 || area.h <= 0) {
    throw InvalidArgument("plot area " + std::to_string(area.w) + "x" +
                          std::to_string(area.h) + " has no room for the world window");
  }
  const double scale = std::min(area.w / window.width(), area.h / window.height());
  // The spare room is exactly 0 along the axis that sets the scale, and a
  // whole number of pixels wherever the window fits evenly; its round-off
  // must not decide the floor, or a build that rounds differently (an FMA
  // contraction) shifts the whole plot by a pixel. Pixel positions are below
  // 2^13, so round-off stays far below kSlack.
  constexpr double kSlack = 1e-6;
  const double spare_w = std::max(0.0, area.w - window.width() * scale);
  const double spare_h = std::max(0.0, area.h - window.height() * scale);
  const double left = std::floor(area.x + spare_w / 2 + kSlack);
  const double top = std::floor(area.y + spare_h / 2 + kSlack);
  return PixelMap(window, left, top, scale);
}

}  // namespace render
