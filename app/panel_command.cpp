// `landslide panel`: PNGs on one page in the gallery's journal layout
// (render/panel.hpp).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "output/counted.hpp"
#include "render/error.hpp"
#include "render/font.hpp"
#include "render/panel.hpp"
#include "render/png_io.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

std::vector<render::Image> read_images(const std::vector<std::string>& paths) {
  std::vector<render::Image> images;
  for (const std::string& p : paths) images.push_back(render::read_png(p));
  return images;
}

render::Image compose(const std::vector<render::Image>& images,
                      const std::vector<std::string>& captions, int cols,
                      const std::string& title) {
  const int n = int(images.size());
  const int c = std::max(1, std::min(cols, n));
  const int rows = (n + c - 1) / c;
  render::Font font;
  // The gallery's layout: captions after (a), (b), ... right above each
  // image, in text whose digits are 1.2 % of the page's width.
  int widest = 0;
  for (const render::Image& img : images) widest = std::max(widest, img.width());
  render::PanelStyle st;
  st.caption_px = render::figure_text_px(font, c * widest);
  st.title_px = st.caption_px * 5 / 4;
  st.margin = st.gap = st.caption_px / 2;
  return render::compose_panel(font, images, captions, rows, c, title, st);
}

}  // namespace

int panel_command(const PanelOptions& o) {
  if (o.items.empty() || o.items.size() % 2 != 0) {
    std::cerr << "error: expected pairs IMAGE.png CAPTION (got "
              << counted(o.items.size(), "argument") << ")\n";
    return kExitBadInput;
  }
  if (o.cols < 1) {
    std::cerr << "error: --cols " << o.cols << ": expected at least 1\n";
    return kExitBadInput;
  }
  if (!ends_with(o.out, ".png")) {
    std::cerr << "error: " << o.out << ": the panel is written as a .png file\n";
    return kExitBadInput;
  }
  std::vector<std::string> paths, captions;
  for (std::size_t i = 0; i < o.items.size(); i += 2) {
    paths.push_back(o.items[i]);
    captions.push_back(o.items[i + 1]);
  }
  std::vector<render::Image> images;
  render::Image page;
  try {
    images = read_images(paths);
    page = compose(images, captions, o.cols, o.title);
  } catch (const render::Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitBadInput;
  }
  try {
    const fs::path out(o.out);
    if (out.has_parent_path()) fs::create_directories(out.parent_path());
    render::write_png(page, o.out);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitFailed;
  }
  std::cout << o.out << '\n';
  return kExitOk;
}

}  // namespace app
