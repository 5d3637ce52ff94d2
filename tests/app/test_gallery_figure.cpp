// The gallery's journal layout (gallery/src/gallery_figure.hpp) on made-up frames:
// every text on a page has digits at least 1.2 % of the page's width, for
// one panel and for four.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gallery/src/gallery_figure.hpp"
#include "render/panel.hpp"
#include "sim/scene/scenario.hpp"

namespace {

app::Frame block_frame(double shift) {
  app::Frame f;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 50; ++i) {
      f.x.push_back(float(i + 0.5 + shift));
      f.y.push_back(float(j + 0.5));
      f.half.push_back(0.5f);
    }
  f.values.push_back(std::vector<float>(f.x.size(), float(shift)));
  return f;
}

TEST(GalleryFigure, TextIsAtLeastOnePointTwoPercentOfThePageWidth) {
  const sim::Scenario s = sim::load_scenario(std::string(LANDSLIDE_SOURCE_DIR) +
                                             "/scenarios/paper-slope-phi20-n1661.json");
  const std::vector<app::Frame> frames = {block_frame(0), block_frame(3), block_frame(6),
                                          block_frame(9)};
  const app::FieldStyle style = app::field_style(app::Field::DisplacementX, s);
  const app::Range range{0, 9};
  app::FramePainter painter(960, 300);
  render::Font font;
  for (const std::size_t n : {std::size_t(1), std::size_t(4)}) {
    std::vector<app::gallery::FigurePanel> panels;
    for (std::size_t i = 0; i < n; ++i) panels.push_back({&s, &frames[i], "panel"});
    app::gallery::FigureShape shape;
    shape.cols = n >= 4 ? 2 : 1;
    shape.title = "title";
    const app::gallery::FigurePage page =
        app::gallery::figure_page(font, painter, panels, 0, style, range, shape);
    const int digits = render::ink_height(font.render("0123456789", page.text_px));
    EXPECT_GE(digits, render::kFigureTextFraction * page.image.width()) << n << " panels";
    EXPECT_GT(page.image.width(), int(shape.cols) * shape.panel_width) << n << " panels";
  }
}

}  // namespace
