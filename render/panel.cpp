#include "render/panel.hpp"

#include <algorithm>

#include "render/error.hpp"

namespace render {

namespace {

void check_grid(const std::vector<Image>& images, int rows, int cols, const PanelStyle& st) {
  if (rows < 1 || cols < 1 || rows > 64 || cols > 64) {
    throw InvalidArgument("panel grid " + std::to_string(rows) + "x" + std::to_string(cols) +
                          " is outside 1..64 x 1..64");
  }
  if (images.empty() || images.size() > std::size_t(rows) * std::size_t(cols)) {
    throw InvalidArgument("panel of " + std::to_string(rows) + "x" + std::to_string(cols) +
                          " cells cannot hold " + std::to_string(images.size()) + " images");
  }
  if (st.margin < 0 || st.gap < 0) throw InvalidArgument("panel margin and gap must be >= 0");
  for (const Image& img : images)
    if (img.empty()) throw InvalidArgument("panel image is empty");
}

std::string caption_text(const PanelStyle& st, std::size_t i, const std::string& caption) {
  if (!st.letters) return caption;
  return caption.empty() ? panel_letter(i) : panel_letter(i) + " " + caption;
}

}  // namespace

std::string panel_letter(std::size_t i) {
  if (i < 26) return std::string("(") + char('a' + i) + ")";
  return "(" + std::to_string(i + 1) + ")";
}

int figure_text_px(Font& font, int page_width, double fraction) {
  const double wanted = fraction * page_width;
  int px = 6;
  while (px < 512 && ink_height(font.render("0123456789", px)) < wanted) ++px;
  return px;
}

PanelLayout layout_panel(Font& font, const std::vector<Image>& images, int rows, int cols,
                         int title_lines, int caption_lines, const PanelStyle& st,
                         const Image* colour_bar) {
  check_grid(images, rows, cols, st);
  PanelLayout L;
  for (const Image& img : images) {
    L.cell_w = std::max(L.cell_w, img.width());
    L.cell_h = std::max(L.cell_h, img.height());
  }
  const int title_h = title_lines > 0 ? title_lines * font.line_height(st.title_px) + st.gap : 0;
  const int caption_h = caption_lines > 0 ? caption_lines * font.line_height(st.caption_px) : 0;
  const int row_h = caption_h + L.cell_h;
  const int grid_w = cols * L.cell_w + (cols - 1) * st.gap;
  const int grid_h = rows * row_h + (rows - 1) * st.gap;
  const int bar_w = colour_bar ? st.gap + colour_bar->width() : 0;
  L.width = 2 * st.margin + grid_w + bar_w;
  L.height = 2 * st.margin + title_h + std::max(grid_h, colour_bar ? colour_bar->height() : 0);
  if (title_lines > 0)
    L.title = Rect{st.margin, st.margin, L.width - 2 * st.margin, title_h - st.gap};
  const int grid_y = st.margin + title_h;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const int r = int(i) / cols, c = int(i) % cols;
    const int cx = st.margin + c * (L.cell_w + st.gap);
    const int cy = grid_y + r * (row_h + st.gap);
    const Image& img = images[i];
    L.captions.push_back(Rect{cx, cy, L.cell_w, caption_h});
    L.images.push_back(Rect{cx + (L.cell_w - img.width()) / 2,
                            cy + caption_h + (L.cell_h - img.height()) / 2, img.width(),
                            img.height()});
  }
  if (colour_bar) {
    L.colour_bar = Rect{st.margin + grid_w + st.gap,
                        grid_y + (std::max(grid_h, colour_bar->height()) - colour_bar->height()) / 2,
                        colour_bar->width(), colour_bar->height()};
  }
  return L;
}

Image compose_panel(Font& font, const std::vector<Image>& images,
                    const std::vector<std::string>& captions, int rows, int cols,
                    const std::string& title, const PanelStyle& st, const Image* colour_bar) {
  if (!captions.empty() && captions.size() != images.size()) {
    throw InvalidArgument("panel has " + std::to_string(images.size()) + " images but " +
                          std::to_string(captions.size()) + " captions");
  }
  int cell_w = 0;
  for (const Image& img : images) cell_w = std::max(cell_w, img.width());
  std::vector<std::vector<std::string>> lines;
  std::size_t most = 0;
  for (std::size_t i = 0; i < captions.size(); ++i) {
    lines.push_back(wrap_text(font, caption_text(st, i, captions[i]), st.caption_px, cell_w));
    most = std::max(most, lines.back().size());
  }
  // A title wider than the page is wrapped onto more lines.
  const int page_w = layout_panel(font, images, rows, cols, 0, int(most), st, colour_bar).width;
  const std::vector<std::string> title_lines =
      wrap_text(font, title, st.title_px, std::max(1, page_w - 2 * st.margin));
  const PanelLayout L = layout_panel(font, images, rows, cols, int(title_lines.size()),
                                     int(most), st, colour_bar);
  Image page(L.width, L.height, st.background);
  for (std::size_t k = 0; k < title_lines.size(); ++k)
    font.draw(page, title_lines[k], st.title_px, L.width / 2,
              L.title.y + int(k) * font.line_height(st.title_px), HAlign::Centre, VAlign::Top,
              st.ink);
  const int line_h = font.line_height(st.caption_px);
  for (std::size_t i = 0; i < images.size(); ++i) {
    page.blit(images[i], L.images[i].x, L.images[i].y);
    for (std::size_t k = 0; i < lines.size() && k < lines[i].size(); ++k)
      font.draw(page, lines[i][k], st.caption_px, L.captions[i].x,
                L.captions[i].y + int(k) * line_h, HAlign::Left, VAlign::Top, st.ink);
  }
  if (colour_bar) page.blit(*colour_bar, L.colour_bar.x, L.colour_bar.y);
  return page;
}

}  // namespace render
