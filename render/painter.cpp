#include "render/painter.hpp"

#include <algorithm>
#include <chrono>

#include "render/colour_map.hpp"
#include "render/outline.hpp"

namespace render {

namespace {
using Clock = std::chrono::steady_clock;
constexpr Rgba kOutlineInk{0, 0, 0, 255};
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}
}  // namespace

Painter::Painter(int width, int height, const PainterOptions& options)
    : ctx_(width, height), font_(options.font_path) {
  if (options.keep_heap) keep_freed_heap_memory();
}

Image Painter::paint(const FrameSpec& spec, const PointsView& points) {
  Image out;
  paint_into(out, spec, points);
  return out;
}

void Painter::paint_into(Image& out, const FrameSpec& spec, const PointsView& points) {
  auto t = Clock::now();
  validate_frame_spec(spec);
  validate_points(points);
  const ColourMap cmap = ColourMap::by_name(spec.colour_map);
  layout_ = layout_frame(font_, spec);
  ctx_.resize(spec.width, spec.height);
  timings_.layout_ms = ms_since(t);

  t = Clock::now();
  SplatStyle style;
  style.background = spec.background;
  splatter_.draw(ctx_, layout_.map, layout_.box, points, cmap, spec.range_lo, spec.range_hi,
                 style);
  timings_.splat_ms = ms_since(t);

  t = Clock::now();
  ctx_.read_into(out);  // waits for the GL work, so splat time lands here too
  timings_.readback_ms = ms_since(t);

  t = Clock::now();
  // A line about a tenth of the tick labels' size: 2 px at 1280 px wide.
  draw_material_edges(out, layout_.map, layout_.box, points, kOutlineInk,
                      std::max(1, layout_.tick_px / 10));
  draw_annotations(out, font_, layout_, spec);
  timings_.annotate_ms = ms_since(t);
}

}  // namespace render
