#pragma once
// Several frames on one page, laid out like a journal's figure: a rows x
// cols grid, each panel headed by its letter and caption ("(a) t = 4 s")
// directly above it, an optional title above all, and an optional colour
// bar that the panels share, right of the grid.
#include <string>
#include <vector>

#include "render/font.hpp"
#include "render/image.hpp"

namespace render {

struct PanelStyle {
  int margin = 16;     // around the whole page
  int gap = 16;        // between cells
  int caption_px = 18;
  int title_px = 26;
  bool letters = true;  // "(a) ", "(b) ", ... before the captions, row-major
  Rgba background = kWhite;
  Rgba ink{30, 30, 30, 255};
};

struct PanelLayout {
  int width = 0, height = 0;
  int cell_w = 0, cell_h = 0;  // the largest image's size
  std::vector<Rect> images;    // where each image goes, row-major order
  std::vector<Rect> captions;  // the caption strip above each image
  Rect title;                  // empty without a title
  Rect colour_bar;             // empty without a shared bar
};

// "(a)" for 0, "(b)" for 1, ... "(z)", then "(27)" on.
std::string panel_letter(std::size_t i);

// Journal figures: text whose digits are at least this share of the page's
// width stays legible when the page is printed at a column's width.
constexpr double kFigureTextFraction = 0.012;
// The smallest font size (em, px) whose digits are at least
// `fraction` x `page_width` px tall.
int figure_text_px(Font& font, int page_width, double fraction = kFigureTextFraction);

// Cells are as large as the largest image; smaller images are centred in
// theirs. `title_lines`, `caption_lines`: the title's and each caption
// strip's height in lines (0: none).
// Throws InvalidArgument for an empty grid, too many images or a bad style.
PanelLayout layout_panel(Font& font, const std::vector<Image>& images, int rows, int cols,
                         int title_lines, int caption_lines, const PanelStyle& style = {},
                         const Image* colour_bar = nullptr);

// Captions (none, or one per image) are wrapped to the cell width, the title
// to the page's; throws
// InvalidArgument for a caption count that is neither 0 nor the image count.
Image compose_panel(Font& font, const std::vector<Image>& images,
                    const std::vector<std::string>& captions, int rows, int cols,
                    const std::string& title, const PanelStyle& style = {},
                    const Image* colour_bar = nullptr);

}  // namespace render
