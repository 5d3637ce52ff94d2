// Renderer benchmark: one 1280x720 annotated frame of a 67k-point slope.
// Prints milliseconds per frame (median) and the split between splatting,
// annotation and PNG writing. Never fails on timing.
//
//   render_bench [sample.png] [frames] [--default-malloc]
//
// The sample PNG (default /tmp/render_sample.png) is the last smooth-field
// frame. --default-malloc leaves glibc's malloc thresholds alone, to show
// what render::keep_freed_heap_memory() buys.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "render/painter.hpp"
#include "render/png_io.hpp"

namespace {

struct Cloud {
  std::vector<double> x, y, hw, hh, v;
  render::PointsView view() const {
    return render::PointsView{x.size(), x.data(), y.data(), hw.data(), hh.data(), v.data()};
  }
};

// A 10 m high body with a 40 degree face in a 117 m x 20 m domain, points on
// a 0.0885 m grid (67,016 of them), value = x.
Cloud slope_cloud() {
  const double spacing = 0.0885, half = 0.044, height = 10.0, crest = 46.5275;
  const double cot = 1.0 / std::tan(40.0 * M_PI / 180.0);
  const int nx = int(117.0 / spacing), ny = int(20.0 / spacing);
  Cloud c;
  for (int j = 0; j < ny; ++j) {
    const double y = (j + 0.5) * spacing;
    if (y > height) break;
    const double x_max = crest + (height - y) * cot;
    for (int i = 0; i < nx; ++i) {
      const double x = (i + 0.5) * spacing;
      if (x >= x_max) break;
      c.x.push_back(x), c.y.push_back(y), c.hw.push_back(half), c.hh.push_back(half);
      c.v.push_back(x);
    }
  }
  return c;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
      .count();
}

// Paints `frames` frames (after two warm-ups), writing each as a PNG, and
// prints the medians. Leaves the last frame in img.
void run(const char* what, render::Painter& painter, render::FrameSpec spec,
         const render::PointsView& view, int frames, const std::string& png_path,
         render::Image& img) {
  std::vector<double> total, layout, splat, annotate, png;
  for (int f = -2; f < frames; ++f) {
    spec.time = 12.5 + 0.04 * f;
    const auto t0 = std::chrono::steady_clock::now();
    painter.paint_into(img, spec, view);
    const auto t1 = std::chrono::steady_clock::now();
    render::write_png(img, png_path);
    const double png_ms = ms_since(t1);
    if (f < 0) continue;
    const render::PaintTimings& t = painter.last_timings();
    total.push_back(ms_since(t0));
    layout.push_back(t.layout_ms);
    splat.push_back(t.splat_ms + t.readback_ms);
    annotate.push_back(t.annotate_ms);
    png.push_back(png_ms);
  }
  std::printf("%s: %zu quads after run merging\n", what, painter.last_quads());
  std::printf("  median ms/frame %.2f (target < 50)\n", median(total));
  std::printf("    layout    %.2f\n    splat     %.2f (GL draw + readback)\n", median(layout),
              median(splat));
  std::printf("    annotate  %.2f\n    png write %.2f\n", median(annotate), median(png));
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args;
  bool keep_heap = true;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--default-malloc") {
      keep_heap = false;
    } else {
      args.push_back(argv[i]);
    }
  }
  const std::string sample = args.size() > 0 ? args[0] : "/tmp/render_sample.png";
  const int frames = args.size() > 1 ? std::max(1, std::atoi(args[1].c_str())) : 20;
  try {
    Cloud c = slope_cloud();
    render::FrameSpec spec;
    spec.world_x0 = 0, spec.world_x1 = 117, spec.world_y0 = 0, spec.world_y1 = 20;
    spec.colour_map = "viridis";
    spec.range_lo = 0, spec.range_hi = 117;
    spec.title = "Slope collapse, 40\u00b0 face (render bench)";
    spec.field_label = "x";
    spec.unit = "m";

    render::PainterOptions options;
    options.keep_heap = keep_heap;
    render::Painter painter(spec.width, spec.height, options);
    const char* lp = std::getenv("LP_NUM_THREADS");
    std::printf("renderer: %s\n", painter.gl_renderer().c_str());
    std::printf("LP_NUM_THREADS=%s, hardware threads %u\n", lp ? lp : "(unset)",
                std::thread::hardware_concurrency());
    std::printf("points: %zu, frame %dx%d, %d frames, malloc thresholds %s\n", c.x.size(),
                spec.width, spec.height, frames, keep_heap ? "raised" : "glibc default");

    render::Image img;
    const std::string tmp_png = sample + ".bench.png";
    run("smooth field (value = x)", painter, spec, c.view(), frames, tmp_png, img);
    render::write_png(img, sample);

    // Worst case for run merging: every neighbour a different colour.
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0, 117);
    for (double& v : c.v) v = u(rng);
    run("noisy field (random values)", painter, spec, c.view(), frames, tmp_png, img);
    std::remove(tmp_png.c_str());
    std::printf("sample frame: %s\n", sample.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
