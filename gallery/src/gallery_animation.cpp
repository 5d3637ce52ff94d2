// The gallery's side-by-side animation, and the small helpers its figures
// share with it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <future>
#include <stdexcept>
#include <string>

#include "gallery/src/gallery_figure.hpp"
#include "gallery/src/gallery_parts.hpp"
#include "render/font.hpp"
#include "render/png_io.hpp"

namespace app::gallery {

namespace fs = std::filesystem;

namespace {

// Four 960-px panels keep the mp4's page near full HD; the GIF's pages are
// painted at 420 px a panel (about 1000 px a page), where the figure's text
// rule (digits 1.2 % of the page) still gives 12 px digits.
constexpr int kPanelWidth = 960, kGifPanelWidth = 420;
constexpr double kInterval = 0.5;  // s of slide time between frames (the runs' frame_interval)

std::string frame_name(int i) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%06d.png", i);
  return buf;
}

// The latest frame at or before slide time t (frames are in time order).
const Frame& frame_at(const std::vector<Frame>& frames, double t) {
  std::size_t k = 0;
  while (k + 1 < frames.size() && frames[k + 1].time <= t + 1e-6) ++k;
  return frames[k];
}

// Page `page` painted with the calling thread's own painter and font.
using PageAt = std::function<render::Image(FramePainter&, render::Font&, int page)>;

// Pages 0..pages-1 as dir/000000.png ..., every one the size of the last: a
// caption grows by a line where its run has ended, and ffmpeg drops what it
// has filtered where the frames' size changes (render::encode_video refuses
// such a clip). Earlier pages are padded below with the page's white.
//
// The even pages are painted on this thread and the odd ones on another,
// each with its own OSMesa context and font: the friction-angle animation of
// `landslide gallery --quick` (painting and encoding) took 3.8, 4.4, 3.8 and
// 4.5 s against 4.4, 5.4, 4.5 and 4.5 s on one thread, in turns, the same
// files byte for byte (issue 17, fifteenth pass).
void write_pages(const fs::path& dir, int pages, const PageAt& page_at) {
  FramePainter painter(kPanelWidth, 300);
  render::Font font;
  const render::Image last = page_at(painter, font, pages - 1);
  const auto write_every_other = [&](int first, FramePainter& own_painter, render::Font& own_font) {
    for (int page = first; page < pages; page += 2) {
      render::Image image = page == pages - 1 ? last : page_at(own_painter, own_font, page);
      if (image.width() > last.width() || image.height() > last.height())
        throw std::logic_error("side-by-side page " + std::to_string(page) +
                               " is larger than the last page");
      if (image.width() != last.width() || image.height() != last.height()) {
        render::Image padded(last.width(), last.height());
        padded.blit(image, 0, 0);
        image = std::move(padded);
      }
      render::write_png(image, (dir / frame_name(page)).string());
    }
  };
  std::future<void> odd = std::async(std::launch::async, [&] {
    FramePainter odd_painter(kPanelWidth, 300);
    render::Font odd_font;
    write_every_other(1, odd_painter, odd_font);
  });
  write_every_other(0, painter, font);
  odd.get();
}

}  // namespace

std::string fmt(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string ending(const RunResult& r) {
  if (!r.failed.empty())
    return "run FAILED after " + fmt(r.slide_time) + " s: last frame";
  return "end at " + fmt(r.slide_time) + " s" + (r.at_rest ? " (at rest)" : "") + ", runout " +
         fmt(r.runout) + " m";
}

void copy_atomically(const fs::path& from, const fs::path& to) {
  fs::path tmp = to;
  tmp += ".tmp";
  fs::copy_file(from, tmp, fs::copy_options::overwrite_existing);
  fs::rename(tmp, to);
}

std::vector<render::VideoFiles> write_side_by_side(const std::vector<const RunResult*>& runs,
                                                   const std::vector<std::string>& labels,
                                                   const std::string& title, const fs::path& work,
                                                   const fs::path& out, const std::string& name) {
  double end = 0;
  std::vector<const std::vector<float>*> values;
  std::vector<const Frame*> all;
  for (const RunResult* r : runs) {
    if (r->slide_frames.empty()) return {};  // a run that failed before its slide
    end = std::max(end, r->slide_frames.back().time);
    for (const Frame& f : r->slide_frames) {
      values.push_back(&f.values[0]);
      all.push_back(&f);
    }
  }
  const int pages = int(std::ceil(end / kInterval - 1e-6)) + 1;
  if (pages < 2) return {};
  const FieldStyle style = field_style(Field::DisplacementX, runs.front()->scenario);
  const Range range = field_range(style, values);
  const int cols = runs.size() >= 4 ? 2 : int(runs.size());

  const fs::path frames = work / "frames", gif_frames = work / "gif-frames";
  fs::create_directories(frames);
  fs::create_directories(gif_frames);
  const Window window = figure_window(runs.front()->scenario, all);
  auto page_at = [&](FramePainter& painter, render::Font& font, int page, int width) {
    const double t = page * kInterval;
    std::vector<FigurePanel> panels;
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const RunResult& r = *runs[k];
      const bool over = t > r.slide_frames.back().time + 1e-6;
      panels.push_back({&r.scenario, &frame_at(r.slide_frames, t), labels[k] + (over ? ": " + ending(r) : "")});
    }
    FigureShape shape;
    shape.cols = cols;
    shape.window = window;
    shape.title = title + ", t = " + fmt(t) + " s";
    shape.panel_width = width;
    return figure_page(font, painter, panels, 0, style, range, shape).image;
  };
  for (const auto& [dir, width] : {std::pair{frames, kPanelWidth}, {gif_frames, kGifPanelWidth}})
    write_pages(dir, pages, [&, w = width](FramePainter& painter, render::Font& font, int page) {
      return page_at(painter, font, page, w);
    });
  render::VideoOptions options = video_options(kInterval);
  options.gif_frames_dir = gif_frames.string();
  const render::VideoFiles v = render::encode_video(frames.string(), work.string(), name, options);
  std::vector<render::VideoFiles> files{{(out / (name + ".mp4")).string(), ""}};
  copy_atomically(v.mp4, files[0].mp4);
  if (!v.gif.empty()) {
    files[0].gif = (out / (name + ".gif")).string();
    copy_atomically(v.gif, files[0].gif);
  }
  fs::remove_all(work);
  return files;
}

}  // namespace app::gallery
