#include "gallery/src/gallery_figure.hpp"

#include <algorithm>

#include "render/annotate.hpp"
#include "render/colour_bar.hpp"
#include "render/panel.hpp"

namespace app::gallery {

namespace {

// A panel's frame: the figure's window, the run's colours, none of its own
// heading or bar, at the figure's text size.
render::FrameSpec panel_spec(const FigurePanel& p, const FieldStyle& style, const Range& range,
                             const Window& window, int width, int text_px) {
  const FrameView view{window, width, 64};
  render::FrameSpec spec =
      frame_spec(*p.scenario, style, p.scenario->output.colour_map, range, *p.frame, view);
  spec.title.clear();
  spec.show_time = false;
  spec.show_colour_bar = false;
  spec.width = width;
  spec.text_px = text_px;
  return spec;
}

render::ColourBarSpec bar_spec(const render::FrameSpec& panel, int text_px) {
  const int tick_len = std::max(2, text_px / 3);
  return render::colour_bar_spec(panel, text_px, text_px, tick_len, tick_len);
}

int page_width(int panel_w, int cols, int gap, int margin, int bar_w) {
  return 2 * margin + cols * panel_w + (cols - 1) * gap + gap + bar_w;
}

}  // namespace

Window figure_window(const sim::Scenario& scenario, const std::vector<const Frame*>& frames) {
  Extent material;
  for (const Frame* f : frames) material.add(*f);
  sim::Scenario s = scenario;
  s.output.has_view = false;
  return view_window(s, material);
}

namespace {

// The window every panel shares, so that they compare: the extent of the
// material in all of them plus the runs' margin (app::view_window), not any
// one scene's own output.view.
Window shared_window(const std::vector<FigurePanel>& panels) {
  std::vector<const Frame*> frames;
  for (const FigurePanel& p : panels) frames.push_back(p.frame);
  return figure_window(*panels.front().scenario, frames);
}

}  // namespace

FigurePage figure_page(render::Font& font, FramePainter& painter,
                       const std::vector<FigurePanel>& panels, std::size_t k,
                       const FieldStyle& style, const Range& range, const FigureShape& shape) {
  const int n = int(panels.size());
  const int cols = std::min(shape.cols, n);
  const int rows = (n + cols - 1) / cols;
  // The text size sets the bar's width, which sets the page's width, which
  // sets the text size: grow the text until its digits reach 1.2 % of the page.
  int text_px = 12, panel_h = 0;
  render::Image bar;
  const Window window = shape.window ? *shape.window : shared_window(panels);
  for (int pass = 0; pass < 8; ++pass) {
    render::FrameSpec spec =
        panel_spec(panels.front(), style, range, window, shape.panel_width, text_px);
    panel_h = render::fit_frame_height(font, spec);
    const int gap = text_px / 2;
    const int caption_h = font.line_height(text_px);
    const int strip_h = std::max(64, rows * panel_h + (rows - 1) * (gap + caption_h) - 2 * text_px);
    bar = render::paint_colour_bar(font, bar_spec(spec, text_px), std::max(8, text_px), strip_h,
                                   gap);
    const int needed = render::figure_text_px(
        font, page_width(shape.panel_width, cols, gap, gap, bar.width()));
    if (needed <= text_px) break;
    text_px = needed;
  }
  std::vector<render::Image> images;
  std::vector<std::string> captions;
  for (const FigurePanel& p : panels) {
    render::FrameSpec spec = panel_spec(p, style, range, window, shape.panel_width, text_px);
    spec.height = panel_h;
    images.push_back(painter.paint(spec, *p.frame, k));
    captions.push_back(p.caption);
  }
  render::PanelStyle st;
  st.margin = st.gap = text_px / 2;
  st.caption_px = text_px;
  st.title_px = text_px * 5 / 4;
  return FigurePage{render::compose_panel(font, images, captions, rows, cols, shape.title, st, &bar),
                    text_px};
}

}  // namespace app::gallery
