// Plots of a run's series (output/series.hpp): OUT/series.png, and the plot
// `landslide render --series` (and the gallery) put beside a frame. The
// runout above, the kinetic energies (total and moving) below, against the
// time since the run began; a dashed line and the stage's name where each
// stage begins, and a red line at the frame's time.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "output/series.hpp"
#include "render/font.hpp"
#include "render/image.hpp"

namespace app {

constexpr int kSeriesPngWidth = 960, kSeriesPngHeight = 720;

// Throws SeriesError without rows, render::InvalidArgument for a size too
// small to hold the two plots' text.
render::Image series_plot(render::Font& font, const std::vector<SeriesRow>& rows, int width,
                          int height, const std::string& title, std::optional<double> marker);

// Beside a frame of height H the plot is max(H, 360) px tall and 4/3 as
// wide as tall; the frame is centred on its left.
int series_plot_width(int frame_height);
render::Image beside_series(render::Font& font, const render::Image& frame,
                            const std::vector<SeriesRow>& rows, double time);

// The time since the run began of a frame at `stage_time` into `stage`,
// from the stage's rows; a stage the series does not hold (or "") means
// stage_time is already the time since the run began.
double run_time_of(const std::vector<SeriesRow>& rows, const std::string& stage,
                   double stage_time);

}  // namespace app
