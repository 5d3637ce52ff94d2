#pragma once
// The colour bar: a strip of the colour map with ticks and a label. One
// layer used by a single frame (annotate.hpp, at the plot's right) and by a
// figure of several panels that share one bar (panel.hpp).
#include <string>
#include <vector>

#include "render/colour_map.hpp"
#include "render/font.hpp"
#include "render/image.hpp"
#include "render/ticks.hpp"

namespace render {

// Right of the plot, read bottom to top; or below it, read left to right
// (wide windows: annotate.hpp).
enum class BarSide { Right, Below };

struct ColourBarSpec {
  std::string colour_map = "viridis";
  double range_lo = 0, range_hi = 1;
  std::string label;  // the whole label, unit included: "displacement [mm]"
  // Categorical maps: a name per id from range_lo on, written at the ticks in
  // place of the ids. Empty: the ids.
  std::vector<std::string> names;
  double label_scale = 1;  // ticks are labelled value x label_scale (m -> mm: 1000)
  int tick_px = 15, label_px = 17;  // font pixel sizes
  int tick_len = 6, gap = 6;
  BarSide side = BarSide::Right;
};

// Ticks along a bar `length` px long: about one per 40 px at tick_px = 15
// (one per 110 px below the plot, where labels sit side by side), on whole
// ids for a categorical map.
Ticks colour_bar_ticks(const ColourBarSpec& spec, int length);

// The label along a bar `length` px long: in lines no longer than the bar
// at label_px, the first nearest the bar. Smaller type only where one word
// is longer than the bar (an image size fixed too low for it; auto heights
// leave room: fit_frame_height).
struct BarLabel {
  int px = 0;
  std::vector<std::string> lines;
};
BarLabel bar_label_lines(Font& font, const ColourBarSpec& spec, int length);

// Room across a bar `length` px long for what is drawn beside it (right of
// it, or below): ticks, their labels and the label's lines.
int colour_bar_room(Font& font, const ColourBarSpec& spec, const Ticks& ticks, int length);

// Paints the bar into `bar` (its strip; ticks and label go beside it, on
// the side spec.side names).
void draw_colour_bar(Image& img, Font& font, const Rect& bar, const ColourBarSpec& spec,
                     const Ticks& ticks);

// A bar on its own image: `strip_w` x `strip_h` px of colour, its ticks and
// label, `pad` px of background around. For figures whose panels share it.
Image paint_colour_bar(Font& font, const ColourBarSpec& spec, int strip_w, int strip_h,
                       int pad, Rgba background = kWhite);

}  // namespace render
