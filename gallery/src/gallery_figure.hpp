// A page laid out like a journal's figure, from captured frames: the panels
// without titles, time stamps or bars of their own, "(a) caption" right
// above each, one colour bar for all, and text whose digits are at least
// 1.2 % of the page's width (render/panel.hpp, kFigureTextFraction), so the
// page stays legible printed at a column's width. The gallery's figures and
// its side-by-side animation are such pages.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "output/frames.hpp"
#include "render/font.hpp"
#include "render/image.hpp"
#include "sim/scene/scenario.hpp"

namespace app::gallery {

struct FigurePanel {
  const sim::Scenario* scenario = nullptr;
  const Frame* frame = nullptr;
  std::string caption;  // after the panel's letter
};

struct FigureShape {
  int panel_width = 960;  // px of each panel's image
  int cols = 2;
  std::string title;      // one line over the page ("" : none)
  // The world window of every panel; none: the material's extent in these
  // panels (an animation passes one window for all its pages).
  std::optional<Window> window;
};

// The material's extent in `frames` plus the runs' margin (app::view_window),
// not any one scene's own output.view: panels of several scenes compare.
Window figure_window(const sim::Scenario& scenario, const std::vector<const Frame*>& frames);

struct FigurePage {
  render::Image image;
  int text_px = 0;  // the size of every text on it (the title's is 5/4 of it)
};

// Field k of every panel's frame in one colour range; `style` and `range`
// as app::field_style / field_range give them. Throws render::Error.
FigurePage figure_page(render::Font& font, FramePainter& painter,
                       const std::vector<FigurePanel>& panels, std::size_t k,
                       const FieldStyle& style, const Range& range, const FigureShape& shape);

}  // namespace app::gallery
