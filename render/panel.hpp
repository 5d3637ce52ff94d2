#pragma once
// Several frames on one page: a rows x cols grid, a caption under each
// image and an overall title above (like the paper's 2x2 figures).
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
  Rgba background = kWhite;
  Rgba ink{30, 30, 30, 255};
};

struct PanelLayout {
  int width = 0, height = 0;
  int cell_w = 0, cell_h = 0;  // the largest image's size
  std::vector<Rect> images;    // where each image goes, row-major order
  std::vector<Rect> captions;  // the caption strip under each image
  Rect title;                  // empty without a title
};

// Cells are as large as the largest image; smaller images are centred in
// theirs. Throws InvalidArgument for an empty grid, too many images or a
// caption count that is neither 0 nor the image count.
PanelLayout layout_panel(Font& font, const std::vector<Image>& images, int rows, int cols,
                         bool has_title, bool has_captions, const PanelStyle& style = {});

Image compose_panel(Font& font, const std::vector<Image>& images,
                    const std::vector<std::string>& captions, int rows, int cols,
                    const std::string& title, const PanelStyle& style = {});

}  // namespace render
