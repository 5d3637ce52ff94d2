#pragma once
// Axes, ticks, colour bar, title and time stamp around the plotted points.
// Layout is computed first (the splat needs the world->pixel map), drawing
// happens after the points are painted.
#include "render/colour_bar.hpp"
#include "render/colour_map.hpp"
#include "render/font.hpp"
#include "render/frame_spec.hpp"
#include "render/ticks.hpp"
#include "render/viewport.hpp"

namespace render {

struct FrameLayout {
  int width = 0, height = 0;
  Rect plot_area;     // room left for the world window after the margins
  PixelMap map;       // world -> pixel, equal scale, centred in plot_area
  Rect box;           // the world window in pixels (axes frame goes round it)
  Rect colour_bar;    // empty when the spec hides the bar
  Ticks x_ticks, y_ticks, bar_ticks;
  ColourBarSpec bar;  // the bar's map, range, label and sizes
  int tick_px = 15, label_px = 17, title_px = 22;  // font pixel sizes
  // The title in lines that clear the time stamp; their count sets the
  // heading's height.
  std::vector<std::string> title_lines;
  int tick_len = 6, gap = 6, margin = 14;
};

// Sizes scale with the tick labels' (spec.text_px, or frame_text_px of the
// size). The colour bar goes right of the plot or below it, whichever
// leaves the world window the larger box (below, for a slope). Throws
// InvalidArgument if the image is too small to hold the annotations.
FrameLayout layout_frame(Font& font, const FrameSpec& spec);
// layout_frame without the throw: false where the image is too small.
bool try_layout_frame(Font& font, const FrameSpec& spec, FrameLayout* layout);

// The image height at which spec's world window fills the plot's width
// with the margins layout_frame() leaves for this spec.width (spec.height is
// ignored), in [kMinFrameSide, kMaxFrameSide]. Throws InvalidArgument if no
// height holds the annotations.
constexpr int kMinFrameSide = 64, kMaxFrameSide = 8192;
int fit_frame_height(Font& font, FrameSpec spec);

void draw_annotations(Image& img, Font& font, const FrameLayout& layout, const FrameSpec& spec);

// "t = 12.50 s"
std::string format_time(double seconds);
// "displacement [m]", or just the label when the unit is empty.
std::string bar_label(const FrameSpec& spec);
// The colour bar a frame of `spec` shows, at the given sizes (a frame's own,
// or a figure's bar shared by its panels).
ColourBarSpec colour_bar_spec(const FrameSpec& spec, int tick_px, int label_px, int tick_len,
                              int gap);

}  // namespace render
