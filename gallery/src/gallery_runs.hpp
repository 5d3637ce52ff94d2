// The gallery's runs: each distinct scene (a committed scenario, or a member
// of a study's sweep file) run once, its states kept for the figures
// (gallery_observer.hpp), its gravity stage shared with the scenes whose
// stages match (as --state-cache does, in memory).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "gallery/src/gallery_figure.hpp"
#include "gallery/src/gallery_observer.hpp"
#include "gallery/src/gallery_parts.hpp"
#include "output/frames.hpp"
#include "output/series_plot.hpp"
#include "render/png_io.hpp"
#include "render/video.hpp"
#include "sim/run/simulation.hpp"

namespace app::gallery {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// What the gallery paints and keeps of every run, whatever its scene asks:
// displacement-x frames of its dynamic stages every 0.5 s, no VTK states;
// --quick runs it at h = 1.127 m.
inline void use_gallery_output(sim::Scenario& s, bool quick) {
  if (quick) s.cell_size = 1.127;
  s.output.vtk = "none";
  s.output.frame_interval = 0.5;
  s.output.fields = {"displacement-x"};
  s.output.ranges.clear();
  // The domain is 116 m x 20 m: a low page keeps the panels free of empty bands.
  s.output.image_size = {1280, 560};
  std::vector<std::string> stages;
  for (const sim::StageSpec& st : s.stages)
    if (st.type == sim::StageType::Dynamic) stages.push_back(st.name);
  s.output.frame_stages = stages;
}

// The key of the stages the gallery computes once for every scene whose
// stages match (sim::reusable_stages: the gravity stage, shared by the
// friction angles of one resolution), or of all its stages where it shares
// none. Scenes of one key run on one thread, in order (gallery_lanes.hpp).
inline std::uint64_t shared_stages_key(const sim::Scenario& s) {
  const std::size_t shared = sim::reusable_stages(s);
  return sim::stage_prefix_key(s, shared > 0 ? shared : s.stages.size());
}

class Gallery {
 public:
  Gallery(fs::path scenarios, fs::path out, bool quick)
      : scenarios_(std::move(scenarios)), out_(std::move(out)), quick_(quick) {}

  // Runs the scene `file` of the scenarios folder (see run()).
  RunResult& run_file(const std::string& file, bool animate = false) {
    return run(sim::load_scenario((scenarios_ / file).string()), animate);
  }

  // Runs `scenario` with the gallery's output settings, once: a later call
  // whose scene has the same physics (sim::stage_prefix_key over all its
  // stages, the key of --state-cache) returns the same result, whether it
  // came from a scene file or a sweep's member (its name is not in the key).
  // Two threads may call it at once for scenes that share no stage
  // (gallery_lanes.hpp): the maps are locked, the runs are not.
  RunResult& run(sim::Scenario scenario, bool animate = false) {
    use_gallery_output(scenario, quick_);
    const std::uint64_t key = sim::stage_prefix_key(scenario, scenario.stages.size());
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      auto it = runs_.find(key);
      if (it != runs_.end()) return *it->second;
    }
    auto r = std::make_unique<RunResult>();
    r->scenario = std::move(scenario);
    sim::Scenario& s = r->scenario;
    std::unique_ptr<FrameRecorder> recorder;
    std::unique_ptr<SeriesRecorder> series;
    const fs::path work = out_ / ".work" / s.name;
    if (animate) {
      recorder = std::make_unique<FrameRecorder>(s, work);
      series = std::make_unique<SeriesRecorder>(s, work);
      fs::create_directories(work);
      recorder->start();
    }
    const auto start = Clock::now();
    sim::Simulation simulation(s);
    r->points = simulation.world().points.size();
    std::ostringstream running;
    running << "running " << s.name << " (" << r->points << " points, h = " << s.cell_size << " m)";
    log_line(running.str());
    GalleryObserver observer(*r, stopping_, recorder.get(), series.get());
    share_gravity_stage(simulation, observer);
    try {
      simulation.run(observer);
    } catch (const sim::ScenarioError&) {
      throw;
    } catch (const RunsStopped&) {
      log_line("  " + s.name + ": stopped at t = " + fmt(simulation.time(), 2) +
               " s, as a run on the other lane failed");
      throw;
    } catch (const GalleryInterrupted& stop) {
      log_line("  " + s.name + ": stopped at t = " + fmt(simulation.time(), 2) + " s by " + stop.by());
      throw;
    } catch (const std::exception& e) {
      // A failed run (e.g. a point thrown out of the grid) still shows its
      // last frame; the figure's caption says so.
      r->failed = e.what();
      log_line("  " + s.name + ": the run failed: " + e.what());
      if (r->has_last) {
        r->slide_end = r->last;
        r->slide_time = r->last.time;
      } else {
        r->slide_end = r->gravity_end;
      }
      if (recorder && recorder->pending() > 0) recorder->paint_pending();
    }
    r->wall = seconds_since(start);
    log_line("  " + s.name + ": " + fmt(r->wall) + " s wall, slide " + fmt(r->slide_time) + " s" +
             (r->at_rest ? " (at rest)" : "") + ", runout " + fmt(r->runout) + " m");
    if (recorder) {
      const auto v0 = Clock::now();
      for (const render::VideoFiles& v : recorder->encode_videos()) {
        const std::string base = "anim-" + s.name + "-displacement-x";
        copy_atomically(v.mp4, out_ / (base + ".mp4"));
        if (!v.gif.empty()) copy_atomically(v.gif, out_ / (base + ".gif"));
        r->videos.push_back({(out_ / (base + ".mp4")).string(),
                             v.gif.empty() ? "" : (out_ / (base + ".gif")).string()});
      }
      log_line("  encoded the animation in " + fmt(seconds_since(v0)) + " s");
      series->write();
      r->series = read_series(work / "series.csv");
      fs::remove_all(work);
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    return *runs_.emplace(key, std::move(r)).first->second;
  }

  // One page: the panels of `field` from `frames`, one colour range over all.
  void figure(const std::string& file, const std::string& title,
              const std::vector<std::pair<const RunResult*, const Frame*>>& panels,
              const std::vector<std::string>& captions, Field field) {
    const std::size_t k = field_index(field);
    const FieldStyle style = field_style(field, panels.front().first->scenario);
    // A run that failed before its first captured state leaves an empty
    // frame: it is painted as an empty plot (its caption says why).
    std::vector<Frame> frames;
    for (const auto& p : panels) {
      frames.push_back(*p.second);
      frames.back().values.resize(kFields.size());
    }
    std::vector<const std::vector<float>*> values;
    for (const Frame& f : frames) values.push_back(&f.values[k]);
    const Range range = field_range(style, values);
    std::vector<gallery::FigurePanel> page;
    for (std::size_t i = 0; i < panels.size(); ++i)
      page.push_back({&panels[i].first->scenario, &frames[i], captions[i]});
    gallery::FigureShape shape;
    shape.cols = panels.size() >= 4 ? 2 : 1;
    shape.title = title;
    render::Font font;
    render::write_png(gallery::figure_page(font, painter(), page, k, style, range, shape).image,
                      (out_ / file).string());
  }

  // The slide's end beside the run's time series (output/series_plot.hpp), the
  // frame as `landslide run` paints it.
  void with_series(const std::string& file, const RunResult& r) {
    if (r.series.empty()) return;
    const FieldStyle style = field_style(Field::DisplacementX, r.scenario);
    const Range range = field_range(style, {&r.slide_end.values[0]});
    const render::FrameSpec spec =
        frame_spec(r.scenario, style, r.scenario.output.colour_map, range, r.slide_end);
    render::Font font;
    const double t = run_time_of(r.series, r.slide_end.stage, r.slide_end.time);
    render::write_png(beside_series(font, painter().paint(spec, r.slide_end, 0), r.series, t),
                      (out_ / file).string());
  }

  // Scenes whose gravity stages have the same inputs (sim::stage_prefix_key:
  // the four friction angles of one resolution) compute it once: the first
  // saves its state at the end of the stage, the others start from it.
  void share_gravity_stage(sim::Simulation& simulation, GalleryObserver& observer) {
    const sim::Scenario& s = simulation.scenario();
    const std::size_t shared = sim::reusable_stages(s);
    if (shared == 0) return;
    std::unique_lock<std::mutex> lock(mutex_);
    std::string& saved = gravity_states_[shared_stages_key(s)];  // a map's nodes stay put
    lock.unlock();
    if (saved.empty()) {
      observer.save_after(shared, &saved);
      return;
    }
    simulation.restore_state(saved, s.name + ": the saved gravity stage");
    const sim::StageSpec& last = s.stages[shared - 1];
    observer.stage_ends(simulation, last, simulation.results()[shared - 1]);
    log_line("  " + s.name + ": starts from the saved end of stage '" + last.name + "' (" +
             fmt(simulation.results()[shared - 1].wall_time) + " s wall when computed)");
  }

  std::vector<std::string> failures() const {
    std::vector<std::string> f;
    for (const auto& [key, r] : runs_)
      if (!r->failed.empty()) f.push_back(r->scenario.name + ": " + r->failed);
    return f;
  }
  bool quick() const { return quick_; }

  // Stops every run of this gallery between two steps (RunsStopped), and
  // keeps later ones from starting: for a run on one lane that failed while
  // the other lane's run goes on (gallery_lanes.hpp).
  void stop_runs() { stopping_ = true; }
  bool stopping() const { return stopping_; }

 private:
  FramePainter& painter() {
    if (!painter_) painter_ = std::make_unique<FramePainter>(960, 300);
    return *painter_;
  }

  fs::path scenarios_, out_;
  bool quick_;
  std::map<std::uint64_t, std::unique_ptr<RunResult>> runs_;  // by stage_prefix_key
  std::map<std::uint64_t, std::string> gravity_states_;
  std::unique_ptr<FramePainter> painter_;
  std::mutex mutex_;  // for runs_ and gravity_states_
  std::atomic<bool> stopping_{false};
};

}  // namespace app::gallery
