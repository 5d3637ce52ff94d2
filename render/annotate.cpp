#include "render/annotate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/error.hpp"

namespace render {

namespace {

constexpr Rgba kInk{30, 30, 30, 255};

bool has_heading(const FrameSpec& s) { return s.show_time || !s.title.empty(); }

// Room for the title left of the time stamp. The room is set by the widest
// stamp a run shows, not this frame's, so that every frame of a video
// breaks its title alike.
int title_room(Font& font, const FrameSpec& spec, const FrameLayout& L) {
  const int stamp = spec.show_time ? font.text_width(format_time(999.99), L.label_px) : 0;
  return std::max(1, spec.width - 2 * L.margin - stamp - 2 * L.gap);
}

// The first line shares its row with the time stamp; the rest have the
// frame's width.
std::vector<std::string> title_lines(Font& font, const FrameSpec& spec, const FrameLayout& L,
                                     bool wrap) {
  if (spec.title.empty()) return {};
  if (!wrap) return {spec.title};
  std::vector<std::string> lines = wrap_text(font, spec.title, L.title_px, title_room(font, spec, L));
  if (lines.size() < 2) return lines;
  std::string rest = lines[1];
  for (std::size_t i = 2; i < lines.size(); ++i) rest += " " + lines[i];
  const std::vector<std::string> more =
      wrap_text(font, rest, L.title_px, std::max(1, spec.width - 2 * L.margin));
  lines.resize(1);
  lines.insert(lines.end(), more.begin(), more.end());
  return lines;
}

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

namespace {

// Pixel sizes, the bar's side and the title's lines: all that the margins
// are made of. Every size keeps its proportion to the tick labels' 15 px of
// the first layout.
struct Sizes {
  double scale = 1;
  int px(double v) const { return std::max(1, int(std::lround(v * scale))); }
};

FrameLayout frame_sizes(Font& font, const FrameSpec& spec, bool wrap_title, Sizes* z) {
  FrameLayout L;
  L.width = spec.width;
  L.height = spec.height;
  L.tick_px = spec.text_px > 0 ? spec.text_px : frame_text_px(spec.width, spec.height);
  z->scale = L.tick_px / 15.0;
  L.label_px = z->px(17);
  L.title_px = z->px(22);
  L.tick_len = z->px(6);
  L.gap = z->px(6);
  L.margin = z->px(14);
  L.bar = colour_bar_spec(spec, L.tick_px, L.label_px, L.tick_len, L.gap);
  L.title_lines = title_lines(font, spec, L, wrap_title);
  return L;
}

void place_ticks(Font& font, FrameLayout& L, const WorldWindow& window, const Sizes& z) {
  // At least three intervals: two would put 0 and 20 m on a 0..18 m window.
  L.y_ticks = nice_ticks(window.y0, window.y1, std::max(3, L.box.h / z.px(45)));
  // Fewer x ticks until neighbouring labels keep a clear gap.
  for (int n = std::max(2, L.box.w / z.px(80)); n >= 1; --n) {
    L.x_ticks = nice_ticks(window.x0, window.x1, n);
    const double step_px = L.x_ticks.step * L.map.scale();
    if (step_px >= widest_label(font, L.x_ticks, L.tick_px) + z.px(16)) break;
  }
}

// The bar beside the box, at least px(260) long upright (as long as the plot
// allows), at most px(520) below; returns the room its ticks and label need.
int place_colour_bar(Font& font, FrameLayout& L, int axis_below, const Sizes& z) {
  const int thickness = z.px(22), gap = z.px(24);
  if (L.bar.side == BarSide::Below) {
    const int length = std::min(L.box.w, z.px(520));
    L.colour_bar = Rect{L.box.x + (L.box.w - length) / 2, L.box.bottom() + axis_below + z.px(14),
                        length, z.px(18)};
  } else {
    const int length = std::min(L.plot_area.h, std::max(L.box.h, z.px(260)));
    const int cy = L.box.y + L.box.h / 2;
    const int y0 = std::clamp(cy - length / 2, L.plot_area.y, L.plot_area.bottom() - length);
    L.colour_bar = Rect{L.box.right() + gap, y0, thickness, length};
  }
  const int length = std::max(L.colour_bar.w, L.colour_bar.h);
  L.bar_ticks = colour_bar_ticks(L.bar, length);
  return colour_bar_room(font, L.bar, L.bar_ticks, length);
}

// The layout with the bar on `side`; false if the margins leave no plot.
bool layout_with_bar(Font& font, const FrameSpec& spec, BarSide side, bool wrap_title,
                     FrameLayout* out) {
  Sizes z;
  FrameLayout L = frame_sizes(font, spec, wrap_title, &z);
  L.bar.side = side;
  const WorldWindow window{spec.world_x0, spec.world_x1, spec.world_y0, spec.world_y1};
  const int tick_h = font.line_height(L.tick_px), label_h = font.line_height(L.label_px);
  const bool bar = spec.show_colour_bar, below = side == BarSide::Below;
  // Without a heading the top y tick label still needs half a line.
  const int heading_lines = std::max<int>(1, L.title_lines.size());
  const int top = has_heading(spec)
                      ? L.margin + heading_lines * font.line_height(L.title_px) + 2 * L.gap
                      : L.margin + tick_h / 2;
  const int axis_below = 1 + L.tick_len + L.gap + tick_h + L.gap + label_h;
  // Label widths depend on the ticks, which depend on the scale, which
  // depends on the margins: iterate until the widths settle.
  int ytick_w = font.text_width("00", L.tick_px), bar_room = 0;
  for (int pass = 0; pass < 4; ++pass) {
    const int left = L.margin + label_h + L.gap + ytick_w + L.gap + L.tick_len + 1;
    const int right = bar && !below ? z.px(24) + z.px(22) + bar_room + L.margin : L.margin + 1;
    const int bottom = axis_below + (bar && below ? z.px(14) + z.px(18) + bar_room : 0) + L.margin;
    L.plot_area = Rect{left, top, spec.width - left - right, spec.height - top - bottom};
    if (L.plot_area.w < 16 || L.plot_area.h < 16) return false;
    L.map = fit_window(window, L.plot_area);
    L.box = L.map.box();
    place_ticks(font, L, window, z);
    const int new_room = bar ? place_colour_bar(font, L, axis_below, z) : 0;
    const int new_y = widest_label(font, L.y_ticks, L.tick_px);
    if (new_y <= ytick_w && new_room <= bar_room) break;
    ytick_w = std::max(ytick_w, new_y);
    bar_room = std::max(bar_room, new_room);
  }
  *out = L;
  return true;
}

}  // namespace

bool try_layout_frame(Font& font, const FrameSpec& spec, FrameLayout* out) {
  // A title too long for its line takes more lines; in an image too low for
  // them (a small fixed size) it keeps one line and is set smaller.
  for (const bool wrap : {true, false}) {
    FrameLayout right, below;
    const bool fits_right = layout_with_bar(font, spec, BarSide::Right, wrap, &right);
    const bool fits_below =
        spec.show_colour_bar && layout_with_bar(font, spec, BarSide::Below, wrap, &below);
    if (!fits_below && !fits_right) continue;
    // The side that leaves the world the larger picture: below for a wide
    // window (a slope), where the bar is long and its label reads across.
    const auto area = [](const Rect& r) { return double(r.w) * r.h; };
    *out = fits_below && (!fits_right || area(below.box) > area(right.box)) ? below : right;
    return true;
  }
  return false;
}

FrameLayout layout_frame(Font& font, const FrameSpec& spec) {
  FrameLayout L;
  if (!try_layout_frame(font, spec, &L)) {
    throw InvalidArgument("image " + std::to_string(spec.width) + "x" +
                          std::to_string(spec.height) +
                          " is too small for axes, labels and colour bar");
  }
  return L;
}

int fit_frame_height(Font& font, FrameSpec spec) {
  const double aspect = (spec.world_y1 - spec.world_y0) / (spec.world_x1 - spec.world_x0);
  if (!(aspect > 0) || !std::isfinite(aspect))
    throw InvalidArgument("world window of zero or non-finite size");
  // The margins depend on the height (text scales with the image; the
  // title's lines and the bar's side are chosen for it), so look for the
  // height they leave the window's own aspect at. A few passes settle it;
  // where they swing between two heights, the lowest that holds the window
  // is taken.
  int h = std::clamp(spec.width, kMinFrameSide, kMaxFrameSide);
  int roomy = kMaxFrameSide + 1;  // lowest height seen with room to spare
  for (int pass = 0; pass < 12; ++pass) {
    spec.height = h;
    FrameLayout L;
    if (!try_layout_frame(font, spec, &L)) {  // too low for its own margins
      if (h == kMaxFrameSide) break;
      h = std::min(kMaxFrameSide, h + std::max(16, h / 8));
      continue;
    }
    const int margins = h - L.plot_area.h;
    int plot = std::max(16, int(std::ceil(L.plot_area.w * aspect - 1e-9)));
    // An upright colour bar, which spans the plot's height, must hold its
    // label's longest word at full size.
    if (spec.show_colour_bar && L.bar.side == BarSide::Right)
      plot = std::max(plot, widest_word(font, L.bar.label, L.label_px));
    const int want = std::clamp(margins + plot, kMinFrameSide, kMaxFrameSide);
    if (want == h) return h;
    if (want < h) roomy = std::min(roomy, h);
    h = want;
  }
  if (roomy <= kMaxFrameSide) return roomy;
  throw InvalidArgument("no image height at width " + std::to_string(spec.width) +
                        " holds the axes, labels and colour bar");
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
  // A word too long for the line on its own is set smaller rather than clipped.
  for (std::size_t i = 0; i < L.title_lines.size(); ++i) {
    const std::string& line = L.title_lines[i];
    const int room = i == 0 ? title_room(font, spec, L) : L.width - 2 * L.margin;
    const int right = i == 0 ? time_left - 2 * L.gap : L.width - L.margin;
    int size = L.title_px;
    int w = font.text_width(line, size);
    while (w > room && size > 8) w = font.text_width(line, --size);
    // Centred over the plot; pushed left if it would run into the time stamp.
    int left = L.box.x + L.box.w / 2 - w / 2;
    left = std::min(left, right - w);
    left = std::max(left, L.margin);
    font.draw(img, line, size, left, baseline + int(i) * font.line_height(L.title_px),
              HAlign::Left, VAlign::Baseline, kInk);
  }
}

}  // namespace

void draw_annotations(Image& img, Font& font, const FrameLayout& L, const FrameSpec& spec) {
  draw_axes(img, font, L, spec);
  if (spec.show_colour_bar) draw_colour_bar(img, font, L.colour_bar, L.bar, L.bar_ticks);
  draw_heading(img, font, L, spec);
}

}  // namespace render
