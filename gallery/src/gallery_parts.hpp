// What `landslide gallery` keeps of each run, shared between the figures
// (gallery.cpp) and the side-by-side animation (gallery_animation.cpp).
#pragma once

#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "output/frames.hpp"
#include "output/series.hpp"
#include "render/video.hpp"
#include "sim/scene/scenario.hpp"

namespace app::gallery {

struct RunResult {
  sim::Scenario scenario;
  std::size_t points = 0;
  double wall = 0;
  Frame gravity_end;
  std::map<double, Frame> at;  // slide time -> state
  Frame slide_end;
  double slide_time = 0;
  bool at_rest = false;
  double runout = 0;
  double max_ux = 0;
  Frame last;          // the latest slide frame (every 0.5 s)
  bool has_last = false;
  // Every slide frame (every 0.5 s), displacement-x only: the side-by-side
  // animation paints them after all its runs have ended, with one range.
  std::vector<Frame> slide_frames;
  std::vector<SeriesRow> series;  // of an animated run (output/series.hpp)
  std::string failed;  // why the run failed ("" : it did not)
  std::vector<render::VideoFiles> videos;
};

// "12.3" (digits after the point).
std::string fmt(double v, int digits = 1);

// One whole line on stderr: the gallery's two lanes (gallery_lanes.hpp) run
// at once, and a line written piece by piece could be cut by the other's.
inline void log_line(const std::string& line) {
  static std::mutex m;
  const std::lock_guard<std::mutex> lock(m);
  std::cerr << line << '\n';
}

// "end at 12.8 s (at rest), runout 18.9 m", or what is shown of a failed run.
std::string ending(const RunResult& r);

// An mp4 and a GIF of the runs' slides side by side (2 x 2 for four runs):
// displacement-x every 0.5 s of slide time with one colour range over every
// frame of every run; a run that ended earlier keeps its last frame and its
// caption says how it ended. Frames are written under `work`; the videos go
// to out/<name>.mp4 and .gif. None for fewer than two pages.
std::vector<render::VideoFiles> write_side_by_side(const std::vector<const RunResult*>& runs,
                                                   const std::vector<std::string>& labels,
                                                   const std::string& title,
                                                   const std::filesystem::path& work,
                                                   const std::filesystem::path& out,
                                                   const std::string& name);

// Copies under a temporary name and renames, so `to` is never half-written.
void copy_atomically(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace app::gallery
