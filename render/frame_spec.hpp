#pragma once
// What one annotated frame shows. World units are metres.
#include <string>

#include "render/image.hpp"

namespace render {

struct FrameSpec {
  int width = 1280, height = 720;
  // World window; drawn with equal scale in x and y, centred in the plot area.
  double world_x0 = 0, world_x1 = 1, world_y0 = 0, world_y1 = 1;
  std::string colour_map = "viridis";  // "viridis", "jet", "categorical"
  double range_lo = 0, range_hi = 1;   // values outside are clamped
  std::string title;
  std::string field_label;  // colour bar label, e.g. "displacement"
  std::string unit;         // e.g. "m"; shown as "displacement [m]"
  double time = 0;          // seconds, shown as "t = 12.50 s"
  bool show_time = true;
  bool show_colour_bar = true;
  std::string x_label = "x [m]";
  std::string y_label = "y [m]";
  Rgba background = kWhite;
};

// Throws InvalidArgument naming the first bad field.
void validate_frame_spec(const FrameSpec& spec);

}  // namespace render
