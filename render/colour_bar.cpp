#include "render/colour_bar.hpp"

#include <algorithm>
#include <cmath>

#include "render/error.hpp"

namespace render {

namespace {

constexpr Rgba kInk{30, 30, 30, 255};

bool categorical(const ColourBarSpec& s) {
  return ColourMap::by_name(s.colour_map).is_categorical();
}

// A categorical bar pads half an id each side so every id gets a block of
// equal height.
void bar_range(const ColourBarSpec& s, double* lo, double* hi) {
  const bool cat = categorical(s);
  *lo = cat ? std::round(s.range_lo) - 0.5 : s.range_lo;
  *hi = cat ? std::round(s.range_hi) + 0.5 : s.range_hi;
}

}  // namespace

Ticks colour_bar_ticks(const ColourBarSpec& s, int length) {
  const int per_tick = std::max(1, int(std::lround(40.0 * s.tick_px / 15.0)));
  if (!categorical(s)) {
    // Nice steps in the labelled unit, placed at the values they stand for.
    Ticks t = nice_ticks(s.range_lo * s.label_scale, s.range_hi * s.label_scale,
                         std::max(2, length / per_tick));
    for (double& v : t.values) v /= s.label_scale;
    return t;
  }
  Ticks t = nice_ticks(s.range_lo, s.range_hi, std::max(2, length / per_tick));
  t.step = std::max(1.0, t.step);
  if (!s.names.empty()) t.step = 1;  // every name is shown
  t.decimals = 0;
  t.values.clear();
  t.labels.clear();
  for (double v = std::ceil(s.range_lo); v <= s.range_hi; v += t.step) {
    const std::size_t id = std::size_t(v - std::ceil(s.range_lo));
    t.values.push_back(v);
    t.labels.push_back(id < s.names.size() ? s.names[id] : format_tick(v, 0));
  }
  return t;
}

int colour_bar_room(Font& font, const ColourBarSpec& s, const Ticks& ticks) {
  const int label = s.label.empty() ? 0 : s.gap + font.line_height(s.label_px);
  return 1 + s.tick_len + s.gap + widest_label(font, ticks, s.tick_px) + label;
}

void draw_colour_bar(Image& img, Font& font, const Rect& r, const ColourBarSpec& s,
                     const Ticks& ticks) {
  const ColourMap cmap = ColourMap::by_name(s.colour_map);
  double lo = 0, hi = 1;
  bar_range(s, &lo, &hi);
  for (int y = 0; y < r.h; ++y) {
    // Row centre -> value; the top row is the high end.
    const double v = lo + (hi - lo) * (r.h - y - 0.5) / r.h;
    img.fill_rect(Rect{r.x, r.y + y, r.w, 1}, cmap.map(v, s.range_lo, s.range_hi));
  }
  img.frame_rect(r, kInk);
  int widest_label = 0;
  for (std::size_t i = 0; i < ticks.values.size(); ++i) {
    const double p = r.bottom() - (ticks.values[i] - lo) / (hi - lo) * r.h;
    const int y = tick_pixel(p, r.y, r.bottom());
    img.fill_rect(Rect{r.right() + 1, y, s.tick_len, 1}, kInk);
    const Rect t = font.draw(img, ticks.labels[i], s.tick_px, r.right() + 1 + s.tick_len + s.gap,
                             y, HAlign::Left, VAlign::Middle, kInk);
    widest_label = std::max(widest_label, t.w);
  }
  if (s.label.empty()) return;
  // A label longer than the bar is set smaller rather than run past its ends
  // (into the time stamp above, or off a small frame).
  int px = s.label_px;
  while (px > 6 && font.text_width(s.label, px) > r.h) --px;
  const TextMask m = rotate_ccw(font.render(s.label, px));
  draw_mask(img, m, r.right() + 1 + s.tick_len + 2 * s.gap + widest_label, r.y + r.h / 2,
            HAlign::Left, VAlign::Middle, kInk);
}

Image paint_colour_bar(Font& font, const ColourBarSpec& s, int strip_w, int strip_h, int pad,
                       Rgba background) {
  if (strip_w < 1 || strip_h < 8 || pad < 0)
    throw InvalidArgument("colour bar strip " + std::to_string(strip_w) + "x" +
                          std::to_string(strip_h) + " (pad " + std::to_string(pad) +
                          ") is too small");
  validate_range(s.range_lo, s.range_hi);
  if (!(s.label_scale > 0) || !std::isfinite(s.label_scale))
    throw InvalidArgument("colour bar label scale " + std::to_string(s.label_scale) +
                          " is not a positive number");
  const Ticks ticks = colour_bar_ticks(s, strip_h);
  // Half a tick label of room above and below, where the end labels reach.
  const int half_text = font.line_height(s.tick_px) / 2 + 1;
  Image img(pad + 1 + strip_w + colour_bar_room(font, s, ticks) + pad,
            2 * (pad + half_text) + strip_h, background);
  draw_colour_bar(img, font, Rect{pad + 1, pad + half_text, strip_w, strip_h}, s, ticks);
  return img;
}

}  // namespace render
