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
  const double spacing = s.side == BarSide::Below ? 110.0 : 40.0;
  const int per_tick = std::max(1, int(std::lround(spacing * s.tick_px / 15.0)));
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

BarLabel bar_label_lines(Font& font, const ColourBarSpec& s, int length) {
  BarLabel b;
  if (s.label.empty()) return b;
  b.px = s.label_px;
  while (b.px > 6 && widest_word(font, s.label, b.px) > length) --b.px;
  b.lines = wrap_text(font, s.label, b.px, length);
  return b;
}

int colour_bar_room(Font& font, const ColourBarSpec& s, const Ticks& ticks, int length) {
  const BarLabel label = bar_label_lines(font, s, length);
  const int lines = int(label.lines.size());
  const int label_room = lines == 0 ? 0 : s.gap + lines * font.line_height(label.px);
  const int tick_room = s.side == BarSide::Below ? font.line_height(s.tick_px)
                                                 : widest_label(font, ticks, s.tick_px);
  return 1 + s.tick_len + s.gap + tick_room + label_room;
}

namespace {

// The strip: low end at the bottom (or left), high end at the top (right).
void draw_strip(Image& img, const Rect& r, const ColourBarSpec& s, double lo, double hi) {
  const ColourMap cmap = ColourMap::by_name(s.colour_map);
  const bool below = s.side == BarSide::Below;
  const int length = below ? r.w : r.h;
  for (int i = 0; i < length; ++i) {
    // Row (column) centre -> value.
    const double v = lo + (hi - lo) * (i + 0.5) / length;
    const Rgba c = cmap.map(v, s.range_lo, s.range_hi);
    if (below)
      img.fill_rect(Rect{r.x + i, r.y, 1, r.h}, c);
    else
      img.fill_rect(Rect{r.x, r.bottom() - 1 - i, r.w, 1}, c);
  }
  img.frame_rect(r, kInk);
}

void draw_beside_right(Image& img, Font& font, const Rect& r, const ColourBarSpec& s,
                       const Ticks& ticks, double lo, double hi) {
  int widest = 0;
  for (std::size_t i = 0; i < ticks.values.size(); ++i) {
    const double p = r.bottom() - (ticks.values[i] - lo) / (hi - lo) * r.h;
    const int y = tick_pixel(p, r.y, r.bottom());
    img.fill_rect(Rect{r.right() + 1, y, s.tick_len, 1}, kInk);
    const Rect t = font.draw(img, ticks.labels[i], s.tick_px, r.right() + 1 + s.tick_len + s.gap,
                             y, HAlign::Left, VAlign::Middle, kInk);
    widest = std::max(widest, t.w);
  }
  const BarLabel label = bar_label_lines(font, s, r.h);
  int x = r.right() + 1 + s.tick_len + 2 * s.gap + widest;
  for (const std::string& line : label.lines) {
    const TextMask m = rotate_ccw(font.render(line, label.px));
    x = draw_mask(img, m, x, r.y + r.h / 2, HAlign::Left, VAlign::Middle, kInk).right();
  }
}

void draw_beside_below(Image& img, Font& font, const Rect& r, const ColourBarSpec& s,
                       const Ticks& ticks, double lo, double hi) {
  const int label_top = r.bottom() + 1 + s.tick_len + s.gap;
  for (std::size_t i = 0; i < ticks.values.size(); ++i) {
    const double p = r.x + (ticks.values[i] - lo) / (hi - lo) * r.w;
    const int x = tick_pixel(p, r.x, r.right());
    img.fill_rect(Rect{x, r.bottom() + 1, 1, s.tick_len}, kInk);
    font.draw(img, ticks.labels[i], s.tick_px, x, label_top, HAlign::Centre, VAlign::Top, kInk);
  }
  const BarLabel label = bar_label_lines(font, s, r.w);
  int y = label_top + font.line_height(s.tick_px) + s.gap;
  for (const std::string& line : label.lines) {
    font.draw(img, line, label.px, r.x + r.w / 2, y, HAlign::Centre, VAlign::Top, kInk);
    y += font.line_height(label.px);
  }
}

}  // namespace

void draw_colour_bar(Image& img, Font& font, const Rect& r, const ColourBarSpec& s,
                     const Ticks& ticks) {
  double lo = 0, hi = 1;
  bar_range(s, &lo, &hi);
  draw_strip(img, r, s, lo, hi);
  if (s.side == BarSide::Below)
    draw_beside_below(img, font, r, s, ticks, lo, hi);
  else
    draw_beside_right(img, font, r, s, ticks, lo, hi);
}

Image paint_colour_bar(Font& font, const ColourBarSpec& s, int strip_w, int strip_h, int pad,
                       Rgba background) {
  if (strip_w < 1 || strip_h < 8 || pad < 0)
    throw InvalidArgument("colour bar strip " + std::to_string(strip_w) + "x" +
                          std::to_string(strip_h) + " (pad " + std::to_string(pad) +
                          ") is too small");
  if (s.side != BarSide::Right) throw InvalidArgument("a colour bar on its own stands upright");
  validate_range(s.range_lo, s.range_hi);
  if (!(s.label_scale > 0) || !std::isfinite(s.label_scale))
    throw InvalidArgument("colour bar label scale " + std::to_string(s.label_scale) +
                          " is not a positive number");
  const Ticks ticks = colour_bar_ticks(s, strip_h);
  // Half a tick label of room above and below, where the end labels reach.
  const int half_text = font.line_height(s.tick_px) / 2 + 1;
  Image img(pad + 1 + strip_w + colour_bar_room(font, s, ticks, strip_h) + pad,
            2 * (pad + half_text) + strip_h, background);
  draw_colour_bar(img, font, Rect{pad + 1, pad + half_text, strip_w, strip_h}, s, ticks);
  return img;
}

}  // namespace render
