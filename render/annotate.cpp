#include "render/annotate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/error.hpp"

namespace render {

namespace {

constexpr Rgba kInk{30, 30, 30, 255};

int widest(Font& font, const Ticks& t, int px) {
  int w = 0;
  for (const auto& s : t.labels) w = std::max(w, font.text_width(s, px));
  return w;
}

// Categorical bars show one block per integer id; their ticks sit on ids.
Ticks bar_ticks_for(const FrameSpec& s, bool categorical, int max_ticks) {
  Ticks t = nice_ticks(s.range_lo, s.range_hi, max_ticks);
  if (categorical) {
    t.step = std::max(1.0, t.step);
    t.decimals = 0;
    t.values.clear();
    t.labels.clear();
    for (double v = std::ceil(s.range_lo); v <= s.range_hi; v += t.step) {
      t.values.push_back(v);
      t.labels.push_back(format_tick(v, 0));
    }
  }
  return t;
}

// Bar value range: categorical bars pad half an id each side so every id
// gets a block of equal height.
void bar_range(const FrameSpec& s, bool categorical, double* lo, double* hi) {
  *lo = categorical ? std::round(s.range_lo) - 0.5 : s.range_lo;
  *hi = categorical ? std::round(s.range_hi) + 0.5 : s.range_hi;
}

}  // namespace

std::string format_time(double seconds) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "t = %.2f s", seconds);
  return buf;
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
  const double s = std::max(0.5, std::min(spec.width / 1280.0, spec.height / 720.0));
  auto px = [s](double v) { return std::max(1, int(std::lround(v * s))); };
  L.tick_px = std::max(8, px(15));
  L.label_px = std::max(9, px(17));
  L.title_px = std::max(10, px(22));
  L.tick_len = std::max(3, px(6));
  L.gap = px(6);
  L.margin = px(14);
  const bool categorical = ColourMap::by_name(spec.colour_map).is_categorical();
  const WorldWindow window{spec.world_x0, spec.world_x1, spec.world_y0, spec.world_y1};
  const int tick_h = font.line_height(L.tick_px), label_h = font.line_height(L.label_px);
  const int bar_w = px(22), bar_gap = px(24);

  const int top = L.margin + font.line_height(L.title_px) + 2 * L.gap;
  const int bottom = 1 + L.tick_len + L.gap + tick_h + L.gap + label_h + L.margin;
  // Label widths depend on the ticks, which depend on the scale, which
  // depends on the margins: iterate until the widths settle.
  int ytick_w = font.text_width("00", L.tick_px), bar_tick_w = ytick_w;
  for (int pass = 0; pass < 4; ++pass) {
    const int left = L.margin + label_h + L.gap + ytick_w + L.gap + L.tick_len + 1;
    int right = L.margin + 1;
    if (spec.show_colour_bar) {
      right = bar_gap + bar_w + L.tick_len + L.gap + bar_tick_w + L.gap + label_h + L.margin;
    }
    L.plot_area = Rect{left, top, spec.width - left - right, spec.height - top - bottom};
    if (L.plot_area.w < 16 || L.plot_area.h < 16) {
      throw InvalidArgument("image " + std::to_string(spec.width) + "x" +
                            std::to_string(spec.height) +
                            " is too small for axes, labels and colour bar");
    }
    L.map = fit_window(window, L.plot_area);
    L.box = L.map.box();
    L.y_ticks = nice_ticks(window.y0, window.y1, std::max(2, L.box.h / px(45)));
    // Fewer x ticks until neighbouring labels keep a clear gap.
    for (int n = std::max(2, L.box.w / px(80)); n >= 1; --n) {
      L.x_ticks = nice_ticks(window.x0, window.x1, n);
      const double step_px = L.x_ticks.step * L.map.scale();
      if (step_px >= widest(font, L.x_ticks, L.tick_px) + px(16)) break;
    }
    if (spec.show_colour_bar) {
      const int bar_h = std::min(L.plot_area.h, std::max(L.box.h, px(260)));
      const int cy = L.box.y + L.box.h / 2;
      const int y0 = std::clamp(cy - bar_h / 2, L.plot_area.y, L.plot_area.bottom() - bar_h);
      L.colour_bar = Rect{L.box.right() + bar_gap, y0, bar_w, bar_h};
      L.bar_ticks = bar_ticks_for(spec, categorical, std::max(2, bar_h / px(40)));
    }
    const int new_y = widest(font, L.y_ticks, L.tick_px);
    const int new_bar = spec.show_colour_bar ? widest(font, L.bar_ticks, L.tick_px) : 0;
    if (new_y <= ytick_w && new_bar <= bar_tick_w) break;
    ytick_w = std::max(ytick_w, new_y);
    bar_tick_w = std::max(bar_tick_w, new_bar);
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

// Pixel column/row of a 1 px tick at edge position p inside [lo, hi]. Ticks
// at the window's ends go onto the frame lines (lo - 1 and hi) so 0 and the
// frame coincide on both axes.
int tick_pos(double p, int lo, int hi) {
  if (p < lo + 0.5) return lo - 1;
  if (p > hi - 0.5) return hi;
  return int(std::floor(p));
}

void frame(Image& img, const Rect& r, Rgba c) {
  img.fill_rect(Rect{r.x - 1, r.y - 1, r.w + 2, 1}, c);
  img.fill_rect(Rect{r.x - 1, r.bottom(), r.w + 2, 1}, c);
  img.fill_rect(Rect{r.x - 1, r.y - 1, 1, r.h + 2}, c);
  img.fill_rect(Rect{r.right(), r.y - 1, 1, r.h + 2}, c);
}

void draw_axes(Image& img, Font& font, const FrameLayout& L, const FrameSpec& spec) {
  const Rect& b = L.box;
  frame(img, b, kInk);
  const int label_top = b.bottom() + 1 + L.tick_len + L.gap;
  for (std::size_t i = 0; i < L.x_ticks.values.size(); ++i) {
    const int x = tick_pos(L.map.x(L.x_ticks.values[i]), b.x, b.right());
    img.fill_rect(Rect{x, b.bottom() + 1, 1, L.tick_len}, kInk);
    font.draw(img, L.x_ticks.labels[i], L.tick_px, x, label_top, HAlign::Centre,
              VAlign::Top, kInk);
  }
  const int label_right = b.x - 1 - L.tick_len - L.gap;
  int widest_y = 0;
  for (std::size_t i = 0; i < L.y_ticks.values.size(); ++i) {
    const int y = tick_pos(L.map.y(L.y_ticks.values[i]), b.y, b.bottom());
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

void draw_colour_bar(Image& img, Font& font, const FrameLayout& L, const FrameSpec& spec,
                     const ColourMap& cmap) {
  const Rect& r = L.colour_bar;
  double lo = 0, hi = 1;
  bar_range(spec, cmap.is_categorical(), &lo, &hi);
  for (int y = 0; y < r.h; ++y) {
    // Row centre -> value; top row is the high end.
    const double v = lo + (hi - lo) * (r.h - y - 0.5) / r.h;
    img.fill_rect(Rect{r.x, r.y + y, r.w, 1}, cmap.map(v, spec.range_lo, spec.range_hi));
  }
  frame(img, r, kInk);
  int widest_label = 0;
  for (std::size_t i = 0; i < L.bar_ticks.values.size(); ++i) {
    const double p = r.bottom() - (L.bar_ticks.values[i] - lo) / (hi - lo) * r.h;
    const int y = tick_pos(p, r.y, r.bottom());
    img.fill_rect(Rect{r.right() + 1, y, L.tick_len, 1}, kInk);
    const Rect t = font.draw(img, L.bar_ticks.labels[i], L.tick_px,
                             r.right() + 1 + L.tick_len + L.gap, y, HAlign::Left,
                             VAlign::Middle, kInk);
    widest_label = std::max(widest_label, t.w);
  }
  const std::string label = bar_label(spec);
  if (label.empty()) return;
  const TextMask m = rotate_ccw(font.render(label, L.label_px));
  draw_mask(img, m, r.right() + 1 + L.tick_len + 2 * L.gap + widest_label, r.y + r.h / 2,
            HAlign::Left, VAlign::Middle, kInk);
}

void draw_heading(Image& img, Font& font, const FrameLayout& L, const FrameSpec& spec) {
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

void draw_annotations(Image& img, Font& font, const FrameLayout& L, const FrameSpec& spec,
                      const ColourMap& cmap) {
  draw_axes(img, font, L, spec);
  if (spec.show_colour_bar) draw_colour_bar(img, font, L, spec, cmap);
  draw_heading(img, font, L, spec);
}

}  // namespace render
