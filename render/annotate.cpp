#include "render/annotate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/error.hpp"

namespace render {

namespace {

constexpr Rgba kInk{30, 30, 30, 255};

bool has_heading(const FrameSpec& s) { return s.show_time || !s.title.empty(); }

}  // namespace

std::string format_time(double seconds) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "t = %.2f s", seconds);
  return buf;
}

ColourBarSpec colour_bar_spec(const FrameSpec& spec, int tick_px, int label_px, int tick_len,
                              int gap) {
  return ColourBarSpec{spec.colour_map, spec.range_lo, spec.range_hi, bar_label(spec),
                       spec.bar_names,  spec.bar_scale, tick_px,      label_px,
                       tick_len,        gap};
}

std::string bar_label(const FrameSpec& spec) {
  if (spec.unit.empty()) return spec.field_label;
  if (spec.field_label.empty()) return "[" + spec.unit + "]";
  return spec.field_label + " [" + spec.unit + "]";
}

FrameLayout layout_frame(Font& font, const FrameSpec& spec) {
  FrameLayout L;
  L.width = spec.width;
  L.height = spec.height;
  L.tick_px = spec.text_px > 0 ? spec.text_px : frame_text_px(spec.width, spec.height);
  // Every other size keeps its proportion to the tick labels' 15 px of the
  // first layout.
  const double s = L.tick_px / 15.0;
  auto px = [s](double v) { return std::max(1, int(std::lround(v * s))); };
  L.label_px = px(17);
  L.title_px = px(22);
  L.tick_len = px(6);
  L.gap = px(6);
  L.margin = px(14);
  L.bar = colour_bar_spec(spec, L.tick_px, L.label_px, L.tick_len, L.gap);
  const WorldWindow window{spec.world_x0, spec.world_x1, spec.world_y0, spec.world_y1};
  const int tick_h = font.line_height(L.tick_px), label_h = font.line_height(L.label_px);
  const int bar_w = px(22), bar_gap = px(24);

  // Without a heading the top y tick label still needs half a line.
  const int top = has_heading(spec) ? L.margin + font.line_height(L.title_px) + 2 * L.gap
                                    : L.margin + tick_h / 2;
  const int bottom = 1 + L.tick_len + L.gap + tick_h + L.gap + label_h + L.margin;
  // Label widths depend on the ticks, which depend on the scale, which
  // depends on the margins: iterate until the widths settle.
  int ytick_w = font.text_width("00", L.tick_px), bar_room = 0;
  for (int pass = 0; pass < 4; ++pass) {
    const int left = L.margin + label_h + L.gap + ytick_w + L.gap + L.tick_len + 1;
    const int right = spec.show_colour_bar ? bar_gap + bar_w + bar_room + L.margin : L.margin + 1;
    L.plot_area = Rect{left, top, spec.width - left - right, spec.height - top - bottom};
    if (L.plot_area.w < 16 || L.plot_area.h < 16) {
      throw InvalidArgument("image " + std::to_string(spec.width) + "x" +
                            std::to_string(spec.height) +
                            " is too small for axes, labels and colour bar");
    }
    L.map = fit_window(window, L.plot_area);
    L.box = L.map.box();
    // At least three intervals: two would put 0 and 20 m on a 0..18 m window.
    L.y_ticks = nice_ticks(window.y0, window.y1, std::max(3, L.box.h / px(45)));
    // Fewer x ticks until neighbouring labels keep a clear gap.
    for (int n = std::max(2, L.box.w / px(80)); n >= 1; --n) {
      L.x_ticks = nice_ticks(window.x0, window.x1, n);
      const double step_px = L.x_ticks.step * L.map.scale();
      if (step_px >= widest_label(font, L.x_ticks, L.tick_px) + px(16)) break;
    }
    int new_room = 0;
    if (spec.show_colour_bar) {
      const int bar_h = std::min(L.plot_area.h, std::max(L.box.h, px(260)));
      const int cy = L.box.y + L.box.h / 2;
      const int y0 = std::clamp(cy - bar_h / 2, L.plot_area.y, L.plot_area.bottom() - bar_h);
      L.colour_bar = Rect{L.box.right() + bar_gap, y0, bar_w, bar_h};
      L.bar_ticks = colour_bar_ticks(L.bar, bar_h);
      new_room = colour_bar_room(font, L.bar, L.bar_ticks);
    }
    const int new_y = widest_label(font, L.y_ticks, L.tick_px);
    if (new_y <= ytick_w && new_room <= bar_room) break;
    ytick_w = std::max(ytick_w, new_y);
    bar_room = std::max(bar_room, new_room);
  }
  return L;
}

int fit_frame_height(Font& font, FrameSpec spec) {
  const double aspect = (spec.world_y1 - spec.world_y0) / (spec.world_x1 - spec.world_x0);
  if (!(aspect > 0) || !std::isfinite(aspect))
    throw InvalidArgument("world window of zero or non-finite size");
  // The margins depend on the height (text scales with the image), so look
  // for the height they leave the window's own aspect at: a few passes settle it.
  int h = std::clamp(spec.width, kMinFrameSide, kMaxFrameSide);
  for (int pass = 0; pass < 8; ++pass) {
    spec.height = h;
    const FrameLayout L = layout_frame(font, spec);
    const int margins = h - L.plot_area.h;
    const int plot = std::max(16, int(std::ceil(L.plot_area.w * aspect - 1e-9)));
    const int want = std::clamp(margins + plot, kMinFrameSide, kMaxFrameSide);
    if (want == h) break;
    h = want;
  }
  return h;
}

namespace {

void draw_axes(Image& img, Font& font, const FrameLayout& L, const FrameSpec& spec) {
  const Rect& b = L.box;
  img.frame_rect(b, kInk);
  const int label_top = b.bottom() + 1 + L.tick_len + L.gap;
  for (std::size_t i = 0; i < L.x_ticks.values.size(); ++i) {
    const int x = tick_pixel(L.map.x(L.x_ticks.values[i]), b.x, b.right());
    img.fill_rect(Rect{x, b.bottom() + 1, 1, L.tick_len}, kInk);
    font.draw(img, L.x_ticks.labels[i], L.tick_px, x, label_top, HAlign::Centre,
              VAlign::Top, kInk);
  }
  const int label_right = b.x - 1 - L.tick_len - L.gap;
  int widest_y = 0;
  for (std::size_t i = 0; i < L.y_ticks.values.size(); ++i) {
    const int y = tick_pixel(L.map.y(L.y_ticks.values[i]), b.y, b.bottom());
    img.fill_rect(Rect{b.x - 1 - L.tick_len, y, L.tick_len, 1}, kInk);
    const Rect r = font.draw(img, L.y_ticks.labels[i], L.tick_px, label_right, y,
                             HAlign::Right, VAlign::Middle, kInk);
    widest_y = std::max(widest_y, r.w);
  }
  const int xlabel_top = label_top + font.line_height(L.tick_px) + L.gap;
  font.draw(img, spec.x_label, L.label_px, b.x + b.w / 2, xlabel_top, HAlign::Centre,
            VAlign::Top, kInk);
  const TextMask ylab = rotate_ccw(font.render(spec.y_label, L.label_px));
  draw_mask(img, ylab, label_right - widest_y - L.gap, b.y + b.h / 2, HAlign::Right,
            VAlign::Middle, kInk);
}

void draw_heading(Image& img, Font& font, const FrameLayout& L, const FrameSpec& spec) {
  if (!has_heading(spec)) return;
  const int baseline = L.margin + font.render("Ag", L.title_px).baseline;
  int time_left = L.width - L.margin;
  if (spec.show_time) {
    const Rect t = font.draw(img, format_time(spec.time), L.label_px, L.width - L.margin,
                             baseline, HAlign::Right, VAlign::Baseline, kInk);
    time_left = t.x;
  }
  if (spec.title.empty()) return;
  // A title too long for the line is set smaller rather than clipped.
  const int room = time_left - 2 * L.gap - L.margin;
  int size = L.title_px;
  int w = font.text_width(spec.title, size);
  while (w > room && size > 8) w = font.text_width(spec.title, --size);
  // Centred over the plot; pushed left if it would run into the time stamp.
  int left = L.box.x + L.box.w / 2 - w / 2;
  left = std::min(left, time_left - 2 * L.gap - w);
  left = std::max(left, L.margin);
  font.draw(img, spec.title, size, left, baseline, HAlign::Left, VAlign::Baseline, kInk);
}

}  // namespace

void draw_annotations(Image& img, Font& font, const FrameLayout& L, const FrameSpec& spec) {
  draw_axes(img, font, L, spec);
  if (spec.show_colour_bar) draw_colour_bar(img, font, L.colour_bar, L.bar, L.bar_ticks);
  draw_heading(img, font, L, spec);
}

}  // namespace render
