#pragma once
// What one annotated frame shows. World units are metres.
#include <string>
#include <vector>

#include "render/image.hpp"

namespace render {

struct FrameSpec {
  int width = 1280, height = 720;
  // World window; drawn with equal scale in x and y, centred in the plot area.
  double world_x0 = 0, world_x1 = 1, world_y0 = 0, world_y1 = 1;
  std::string colour_map = "viridis";  // "viridis", "jet", "categorical"
  double range_lo = 0, range_hi = 1;   // values outside are clamped
  std::string title;  // "" and show_time false: no heading row at all
  std::string field_label;  // colour bar label, e.g. "displacement"
  std::string unit;         // e.g. "m"; shown as "displacement [m]"
  // The colour bar's labels show value x bar_scale, in `unit` (a range in
  // metres labelled in mm: 1000).
  double bar_scale = 1;
  double time = 0;          // seconds, shown as "t = 12.50 s"
  bool show_time = true;
  bool show_colour_bar = true;
  // Categorical maps: the name of each id at its tick on the colour bar.
  std::vector<std::string> bar_names;
  // Pixel size (em) of tick labels; labels and title scale from it. 0: the
  // default of frame_text_px(width, height).
  int text_px = 0;
  std::string x_label = "x [m]";
  std::string y_label = "y [m]";
  Rgba background = kWhite;
};

// The default tick-label size for an image `width` x `height` px: 1.65 % of
// the width, and not under 17 px, where DejaVu's digits are 12 px tall (a
// 480 px GIF stays legible); only an image under 204 px tall, too low for
// that, gets a twelfth of its height (at least 6 px).
int frame_text_px(int width, int height);

// Throws InvalidArgument naming the first bad field.
void validate_frame_spec(const FrameSpec& spec);

}  // namespace render
