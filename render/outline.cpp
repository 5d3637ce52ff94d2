#include "render/outline.hpp"

#include <algorithm>
#include <cmath>

namespace render {

namespace {

constexpr std::uint8_t kEmpty = 255;

// Material id of every pixel of `clip` as the splat paints it: later points
// over earlier ones, like the GL draw.
std::vector<std::uint8_t> label_pixels(const PixelMap& map, const Rect& clip,
                                       const PointsView& p) {
  std::vector<std::uint8_t> label(std::size_t(clip.w) * std::size_t(clip.h), kEmpty);
  for (std::size_t i = 0; i < p.count; ++i) {
    const double hw = std::abs(p.half_width[i]), hh = std::abs(p.half_height[i]);
    if (!std::isfinite(p.x[i]) || !std::isfinite(p.y[i]) || !std::isfinite(hw) ||
        !std::isfinite(hh))
      continue;
    const PixelSquare s = snap_square(map, p.x[i], p.y[i], hw, hh);
    const int x0 = std::max(s.x0, clip.x), x1 = std::min(s.x1, clip.right());
    const int y0 = std::max(s.y0, clip.y), y1 = std::min(s.y1, clip.bottom());
    for (int y = y0; y < y1; ++y)
      std::fill_n(&label[std::size_t(y - clip.y) * clip.w + (x0 - clip.x)], std::max(0, x1 - x0),
                  std::min<std::uint8_t>(p.material[i], kEmpty - 1));
  }
  return label;
}


}  // namespace

void draw_material_edges(Image& img, const PixelMap& map, const Rect& clip_in,
                         const PointsView& points, Rgba ink, int thickness) {
  if (!points.material || points.count == 0) return;
  const Rect clip = clip_rect(clip_in, img.width(), img.height());
  if (clip.w == 0 || clip.h == 0) return;
  const std::vector<std::uint8_t> label = label_pixels(map, clip, points);
  auto at = [&](int x, int y) { return label[std::size_t(y) * clip.w + x]; };
  std::vector<std::uint8_t> edge(label.size(), 0);
  const int t = std::max(1, thickness / 2);
  // Another material at (x, y), seen from material a.
  auto other = [&](int x, int y, std::uint8_t a) {
    if (x < 0 || y < 0 || x >= clip.w || y >= clip.h) return false;
    const std::uint8_t b = at(x, y);
    return b != a && b != kEmpty;
  };
  for (int y = 0; y < clip.h; ++y) {
    for (int x = 0; x < clip.w; ++x) {
      const std::uint8_t a = at(x, y);
      if (a == kEmpty) continue;
      bool on = false;
      for (int d = 1; d <= t && !on; ++d)
        on = other(x - d, y, a) || other(x + d, y, a) || other(x, y - d, a) || other(x, y + d, a);
      edge[std::size_t(y) * clip.w + x] = on;
    }
  }
  for (int y = 0; y < clip.h; ++y)
    for (int x = 0; x < clip.w; ++x)
      if (edge[std::size_t(y) * clip.w + x]) img.set(clip.x + x, clip.y + y, ink);
}

}  // namespace render
