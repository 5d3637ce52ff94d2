#include "render/panel.hpp"

#include <algorithm>

#include "render/error.hpp"

namespace render {

PanelLayout layout_panel(Font& font, const std::vector<Image>& images, int rows, int cols,
                         bool has_title, bool has_captions, const PanelStyle& st) {
  if (rows < 1 || cols < 1 || rows > 64 || cols > 64) {
    throw InvalidArgument("panel grid " + std::to_string(rows) + "x" + std::to_string(cols) +
                          " is outside 1..64 x 1..64");
  }
  if (images.empty() || images.size() > std::size_t(rows) * std::size_t(cols)) {
    throw InvalidArgument("panel of " + std::to_string(rows) + "x" + std::to_string(cols) +
                          " cells cannot hold " + std::to_string(images.size()) + " images");
  }
  if (st.margin < 0 || st.gap < 0) throw InvalidArgument("panel margin and gap must be >= 0");
  PanelLayout L;
  for (const Image& img : images) {
    if (img.empty()) throw InvalidArgument("panel image is empty");
    L.cell_w = std::max(L.cell_w, img.width());
    L.cell_h = std::max(L.cell_h, img.height());
  }
  const int title_h = has_title ? font.line_height(st.title_px) + st.gap : 0;
  const int caption_h = has_captions ? st.gap / 2 + font.line_height(st.caption_px) : 0;
  const int row_h = L.cell_h + caption_h;
  L.width = 2 * st.margin + cols * L.cell_w + (cols - 1) * st.gap;
  L.height = 2 * st.margin + title_h + rows * row_h + (rows - 1) * st.gap;
  if (has_title) {
    L.title = Rect{st.margin, st.margin, L.width - 2 * st.margin, title_h - st.gap};
  }
  for (std::size_t i = 0; i < images.size(); ++i) {
    const int r = int(i) / cols, c = int(i) % cols;
    const int cx = st.margin + c * (L.cell_w + st.gap);
    const int cy = st.margin + title_h + r * (row_h + st.gap);
    const Image& img = images[i];
    L.images.push_back(Rect{cx + (L.cell_w - img.width()) / 2,
                            cy + (L.cell_h - img.height()) / 2, img.width(), img.height()});
    L.captions.push_back(Rect{cx, cy + L.cell_h + st.gap / 2, L.cell_w, caption_h - st.gap / 2});
  }
  return L;
}

Image compose_panel(Font& font, const std::vector<Image>& images,
                    const std::vector<std::string>& captions, int rows, int cols,
                    const std::string& title, const PanelStyle& st) {
  if (!captions.empty() && captions.size() != images.size()) {
    throw InvalidArgument("panel has " + std::to_string(images.size()) + " images but " +
                          std::to_string(captions.size()) + " captions");
  }
  const PanelLayout L =
      layout_panel(font, images, rows, cols, !title.empty(), !captions.empty(), st);
  Image page(L.width, L.height, st.background);
  if (!title.empty()) {
    font.draw(page, title, st.title_px, L.width / 2, L.title.y, HAlign::Centre, VAlign::Top,
              st.ink);
  }
  for (std::size_t i = 0; i < images.size(); ++i) {
    page.blit(images[i], L.images[i].x, L.images[i].y);
    if (!captions.empty() && !captions[i].empty()) {
      const Rect& c = L.captions[i];
      font.draw(page, captions[i], st.caption_px, c.x + c.w / 2, c.y, HAlign::Centre,
                VAlign::Top, st.ink);
    }
  }
  return page;
}

}  // namespace render
