// The world window and image size of a run's frames (output/frames.hpp): the
// scenario's own view, or the region its material occupies over the painted
// stages, so the slope fills the frame rather than the whole domain.
#include <algorithm>
#include <cmath>

#include "output/frames.hpp"
#include "render/annotate.hpp"

namespace app {

namespace {

void set_window(render::FrameSpec& spec, const Window& w) {
  spec.world_x0 = w.x0;
  spec.world_x1 = w.x1;
  spec.world_y0 = w.y0;
  spec.world_y1 = w.y1;
}

}  // namespace

Window frame_window(const sim::Scenario& s) {
  const double w = s.domain_max[0] - s.domain_min[0];
  const double h = s.domain_max[1] - s.domain_min[1];
  const double margin = std::max(0.03 * std::max(w, h), s.cell_size);
  return Window{s.domain_min[0] - margin, s.domain_max[0] + margin, s.domain_min[1] - margin,
                s.domain_max[1] + margin};
}

void Extent::add(const Frame& frame) {
  for (std::size_t i = 0; i < frame.x.size(); ++i) {
    const double half = kSquareFill * double(frame.half[i]);
    const double x = frame.x[i], y = frame.y[i];
    if (!std::isfinite(half) || !std::isfinite(x) || !std::isfinite(y)) continue;
    x0 = std::min(x0, x - half);
    x1 = std::max(x1, x + half);
    y0 = std::min(y0, y - half);
    y1 = std::max(y1, y + half);
  }
}

Window view_window(const sim::Scenario& s, const Extent& material) {
  if (s.output.has_view)
    return Window{s.output.view_min[0], s.output.view_max[0], s.output.view_min[1],
                  s.output.view_max[1]};
  const Window clip = frame_window(s);
  if (material.empty()) return clip;
  const double w = material.x1 - material.x0, h = material.y1 - material.y0;
  const double margin = std::max(kViewMargin * std::max(w, h), s.cell_size);
  Window v{std::max(clip.x0, material.x0 - margin), std::min(clip.x1, material.x1 + margin),
           std::max(clip.y0, material.y0 - margin), std::min(clip.y1, material.y1 + margin)};
  // Material outside the domain's window (a point thrown past a wall) is
  // clipped: the window stays inside frame_window() and keeps a size.
  if (!(v.x0 < v.x1 && v.y0 < v.y1)) return clip;
  return v;
}

FrameView frame_view(const sim::Scenario& s, const Window& window, render::Font& font) {
  FrameView view;
  view.window = window;
  view.width = s.output.image_size[0];
  view.height = s.output.image_size[1];
  if (view.height == sim::kAutoHeight) view.height = auto_height(s, window, view.width, font);
  return view;
}

// Frames of one run share one size, but their titles (field and stage) and
// bar labels differ: the height is the tallest any of them needs.
int auto_height(const sim::Scenario& s, const Window& window, int width, render::Font& font) {
  const FrameView probe{window, width, render::kMinFrameSide};  // the height is not read
  std::vector<std::string> stages = s.output.frame_stages;
  if (stages.empty()) stages.push_back("");
  int height = render::kMinFrameSide;
  // Every field, not only output.fields: `landslide render` paints any of them
  // in the run's frame size.
  for (const std::string& name : field_names()) {
    const FieldStyle style = field_style(parse_field(name), s);
    for (const std::string& stage : stages) {
      Frame frame;
      frame.stage = stage;
      const render::FrameSpec spec =
          frame_spec(s, style, s.output.colour_map, Range{0, 1}, frame, probe);
      height = std::max(height, render::fit_frame_height(font, spec));
    }
  }
  return height;
}

render::FrameSpec frame_spec(const sim::Scenario& scenario, const FieldStyle& style,
                             const std::string& colour_map, const Range& range,
                             const Frame& frame, const FrameView& view) {
  render::FrameSpec spec;
  spec.width = view.width;
  spec.height = view.height;
  set_window(spec, view.window);
  spec.colour_map = style.categorical ? "categorical" : colour_map;
  const DisplayUnit shown = display_unit(style, range);
  spec.range_lo = range.lo;
  spec.range_hi = range.hi;
  spec.bar_scale = shown.scale;
  if (style.categorical) spec.bar_names = style.names;
  spec.title = scenario.name + " \u2014 " + style.title;
  if (!frame.stage.empty()) spec.title += " (" + frame.stage + ")";
  spec.field_label = style.label;
  spec.unit = shown.unit;
  spec.time = frame.time;
  return spec;
}

render::FrameSpec frame_spec(const sim::Scenario& scenario, const FieldStyle& style,
                             const std::string& colour_map, const Range& range,
                             const Frame& frame) {
  const Window window = frame_window(scenario);
  FrameView view{window, scenario.output.image_size[0], scenario.output.image_size[1]};
  if (view.height == sim::kAutoHeight) {
    render::Font font;
    view = frame_view(scenario, window, font);
  }
  return frame_spec(scenario, style, colour_map, range, frame, view);
}

}  // namespace app
