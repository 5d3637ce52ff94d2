// `landslide gallery`: regenerates the paper's figures (5, 6, 9, 10, 11, 12),
// an animation of the phi = 20 slide and one of the four friction angles side
// by side from the committed scenarios. Each scenario is run once; an
// observer keeps the states the figures need.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "gallery/src/gallery.hpp"
#include "output/exit_status.hpp"
#include "output/output_dir.hpp"
#include "output/frames.hpp"
#include "gallery/src/gallery_figure.hpp"
#include "gallery/src/gallery_observer.hpp"
#include "gallery/src/gallery_parts.hpp"
#include "output/series_plot.hpp"
#include "render/error.hpp"
#include "render/font.hpp"
#include "render/png_io.hpp"
#include "render/video.hpp"
#include "sim/run/simulation.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

using gallery::copy_atomically;
using gallery::field_index;
using gallery::GalleryObserver;
using gallery::kFields;
using gallery::ending;
using gallery::fmt;
using gallery::RunResult;
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

class Gallery {
 public:
  Gallery(fs::path scenarios, fs::path out, bool quick)
      : scenarios_(std::move(scenarios)), out_(std::move(out)), quick_(quick) {}

  // Runs `file` (once; later calls return the same result).
  RunResult& run(const std::string& file, bool animate = false) {
    auto it = runs_.find(file);
    if (it != runs_.end()) return *it->second;
    auto r = std::make_unique<RunResult>();
    r->scenario = sim::load_scenario((scenarios_ / file).string());
    sim::Scenario& s = r->scenario;
    if (quick_) s.cell_size = 1.127;
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
    std::cerr << "running " << s.name << " (" << r->points << " points, h = " << s.cell_size
              << " m)\n";
    GalleryObserver observer(*r, recorder.get(), series.get());
    share_gravity_stage(simulation, observer);
    try {
      simulation.run(observer);
    } catch (const sim::ScenarioError&) {
      throw;
    } catch (const std::exception& e) {
      // A failed run (e.g. a point thrown out of the grid) still shows its
      // last frame; the figure's caption says so.
      r->failed = e.what();
      std::cerr << "  " << s.name << ": the run failed: " << e.what() << '\n';
      if (r->has_last) {
        r->slide_end = r->last;
        r->slide_time = r->last.time;
      } else {
        r->slide_end = r->gravity_end;
      }
      if (recorder && recorder->pending() > 0) recorder->paint_pending();
    }
    r->wall = seconds_since(start);
    std::cerr << "  " << s.name << ": " << fmt(r->wall) << " s wall, slide "
              << fmt(r->slide_time) << " s" << (r->at_rest ? " (at rest)" : "") << ", runout "
              << fmt(r->runout) << " m\n";
    if (recorder) {
      const auto v0 = Clock::now();
      for (const render::VideoFiles& v : recorder->encode_videos()) {
        const std::string base = "anim-" + s.name + "-displacement-x";
        copy_atomically(v.mp4, out_ / (base + ".mp4"));
        if (!v.gif.empty()) copy_atomically(v.gif, out_ / (base + ".gif"));
        r->videos.push_back({(out_ / (base + ".mp4")).string(),
                             v.gif.empty() ? "" : (out_ / (base + ".gif")).string()});
      }
      std::cerr << "  encoded the animation in " << fmt(seconds_since(v0)) << " s\n";
      series->write();
      r->series = read_series(work / "series.csv");
      fs::remove_all(work);
    }
    run_wall_ += r->wall;
    return *runs_.emplace(file, std::move(r)).first->second;
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
    std::string& saved = gravity_states_[sim::stage_prefix_key(s, shared)];
    if (saved.empty()) {
      observer.save_after(shared, &saved);
      return;
    }
    simulation.restore_state(saved, s.name + ": the saved gravity stage");
    const sim::StageSpec& last = s.stages[shared - 1];
    observer.stage_ends(simulation, last, simulation.results()[shared - 1]);
    std::cerr << "  " << s.name << ": starts from the saved end of stage '" << last.name << "' ("
              << fmt(simulation.results()[shared - 1].wall_time) << " s wall when computed)\n";
  }

  double run_wall() const { return run_wall_; }
  std::vector<std::string> failures() const {
    std::vector<std::string> f;
    for (const auto& [file, r] : runs_)
      if (!r->failed.empty()) f.push_back(file + ": " + r->failed);
    return f;
  }
  bool quick() const { return quick_; }

 private:
  FramePainter& painter() {
    if (!painter_) painter_ = std::make_unique<FramePainter>(960, 300);
    return *painter_;
  }

  fs::path scenarios_, out_;
  bool quick_;
  std::map<std::string, std::unique_ptr<RunResult>> runs_;
  std::map<std::uint64_t, std::string> gravity_states_;
  std::unique_ptr<FramePainter> painter_;
  double run_wall_ = 0;
};

// The state at slide time t, or the final state if the slide ended first.
const Frame* state_at(const RunResult& r, double t, std::string& note) {
  auto it = r.at.find(t);
  if (it != r.at.end()) return &it->second;
  if (!r.failed.empty()) {
    note = " (run FAILED after " + fmt(r.slide_time) + " s: last frame)";
    return &r.slide_end;
  }
  note = std::string(r.at_rest ? " (at rest" : " (ended") + " after " + fmt(r.slide_time) +
         " s: final state)";
  return &r.slide_end;
}

// The paper's Fig. 9 shows 4, 8, 12 and 16 s of a slide that lasts longer;
// here it ends sooner, so the panels show a quarter, a half, three quarters
// and the whole of it (the kept frame at or before each time): four distinct
// states. Fewer where the slide kept fewer frames.
std::vector<const Frame*> quarters_of_the_slide(const RunResult& r) {
  std::vector<const Frame*> picked;
  for (const double share : {0.25, 0.5, 0.75}) {
    const Frame* f = nullptr;
    for (const Frame& c : r.slide_frames)
      if (c.time <= share * r.slide_time + 1e-9) f = &c;
    if (f && (picked.empty() || picked.back() != f)) picked.push_back(f);
  }
  picked.push_back(&r.slide_end);
  return picked;
}

std::string pts(const RunResult& r) { return std::to_string(r.points) + " points"; }

}  // namespace

int gallery_command(const GalleryOptions& o) {
  if (o.out.empty()) {
    std::cerr << "error: --out DIR is required\n";
    return kExitBadInput;
  }
  const fs::path scenarios = o.scenarios.empty() ? fs::path("scenarios") : fs::path(o.scenarios);
  if (!scenarios_folder_found(scenarios.string(), !o.scenarios.empty(), "landslide gallery"))
    return kExitBadInput;
  for (const char* f : {"paper-slope-phi20.json", "paper-slope-phi25.json",
                        "paper-slope-phi15.json", "paper-slope-phi10.json",
                        "paper-slope-phi20-n1661.json", "paper-slope-phi20-n28711.json",
                        "paper-slope-phi20-n66787.json"}) {
    try {
      sim::load_scenario((scenarios / f).string());
    } catch (const sim::ScenarioError& e) {
      std::cerr << "error: " << e.what() << " (--scenarios DIR names the scenarios folder)\n";
      return kExitBadInput;
    }
  }
  std::string why;
  if (!render::ffmpeg_available(&why)) {
    std::cerr << "error: the gallery's animation needs ffmpeg: " << why << '\n';
    return kExitBadInput;
  }
  const fs::path out(o.out);
  try {
    FramePainter probe(64, 64);  // OSMesa and the font start
  } catch (const std::exception& e) {
    std::cerr << "error: cannot set up the off-screen painter: " << e.what() << '\n';
    return kExitBadInput;
  }
  const auto total = Clock::now();
  try {
    fs::create_directories(out);
    Gallery g(scenarios, out, o.quick);
    const std::string q = o.quick ? " [quick: h = 1.127 m]" : "";
    auto timed = [&](const std::string& name, auto&& make) {
      const auto start = Clock::now();
      const double runs_before = g.run_wall();
      make();
      const double wall = seconds_since(start);
      std::cout << name << ": " << fmt(wall) << " s (simulating " << fmt(g.run_wall() - runs_before)
                << " s, painting " << fmt(wall - (g.run_wall() - runs_before)) << " s)"
                << std::endl;
    };

    timed("fig05-vertical-stress.png", [&] {
      RunResult& r = g.run("paper-slope-phi20.json", true);
      g.figure("fig05-vertical-stress.png",
               "Fig. 5: vertical stress after the gravity stage (phi = 25 deg until the trigger)" + q,
               {{&r, &r.gravity_end}},
               {"sigma_yy, tension positive, at the end of the 5 s gravity stage, " + pts(r)},
               Field::StressYY);
    });
    timed("fig06-horizontal-displacement.png", [&] {
      RunResult& r = g.run("paper-slope-phi20.json", true);
      g.figure("fig06-horizontal-displacement.png",
               "Fig. 6: horizontal displacement after the gravity stage (phi = 25 deg until the trigger)" + q,
               {{&r, &r.gravity_end}},
               {"at the end of the 5 s gravity stage, " + pts(r) +
                " (the slope faces +x, mirrored from the paper)"},
               Field::DisplacementX);
    });
    timed("fig09-slide.png", [&] {
      RunResult& r = g.run("paper-slope-phi20.json", true);
      std::vector<std::pair<const RunResult*, const Frame*>> panels;
      std::vector<std::string> caps;
      for (const Frame* f : quarters_of_the_slide(r)) {
        panels.push_back({&r, f});
        caps.push_back(f == &r.slide_end ? ending(r)
                                         : "t = " + fmt(f->time) + " s into the slide");
      }
      g.figure("fig09-slide.png",
               "Fig. 9: horizontal displacement, phi = 20 deg, " + pts(r) +
                   (o.quick ? q : " (paper: 40,038; fewer for run time on 2 cores)"),
               panels, caps, Field::DisplacementX);
    });
    timed("fig10-relative-yield-3s.png", [&] {
      RunResult& r = g.run("paper-slope-phi20.json", true);
      std::string note;
      const Frame* f = state_at(r, 3.0, note);
      g.figure("fig10-relative-yield-3s.png",
               "Fig. 10: relative yield 3 s into the slide, phi = 20 deg" + q, {{&r, f}},
               {"0 hydrostatic, 1 on the yield surface, 2 yielded in the last step; house 0; " +
                pts(r) + note},
               Field::RelativeYield);
    });
    timed("series-paper-slope-phi20.png", [&] {
      g.with_series("series-paper-slope-phi20.png", g.run("paper-slope-phi20.json", true));
    });
    timed("fig11-resolutions.png", [&] {
      std::vector<std::pair<const RunResult*, const Frame*>> panels;
      std::vector<std::string> caps;
      const std::vector<std::string> files =
          o.quick ? std::vector<std::string>{"paper-slope-phi20.json"}
                  : std::vector<std::string>{"paper-slope-phi20-n1661.json", "paper-slope-phi20.json",
                                             "paper-slope-phi20-n28711.json",
                                             "paper-slope-phi20-n66787.json"};
      for (const std::string& f : files) {
        RunResult& r = g.run(f, f == "paper-slope-phi20.json");
        panels.push_back({&r, &r.slide_end});
        caps.push_back(pts(r) + ", h = " + fmt(r.scenario.cell_size, 3) + " m: " + ending(r));
      }
      g.figure("fig11-resolutions.png",
               "Fig. 11: end of the slide at four resolutions, phi = 20 deg" + q, panels, caps,
               Field::DisplacementX);
    });
    const std::vector<std::string> angles = {"25", "20", "15", "10"};
    auto friction_run = [&](const std::string& phi) -> RunResult& {
      const std::string f = "paper-slope-phi" + phi + ".json";
      return g.run(f, f == "paper-slope-phi20.json");
    };
    timed("fig12-friction-angles.png", [&] {
      std::vector<std::pair<const RunResult*, const Frame*>> panels;
      std::vector<std::string> caps;
      for (const std::string& phi : angles) {
        RunResult& r = friction_run(phi);
        panels.push_back({&r, &r.slide_end});
        caps.push_back("phi = " + phi + " deg, " + pts(r) + ": " + ending(r));
      }
      g.figure("fig12-friction-angles.png", "Fig. 12: end of the slide, four friction angles" + q,
               panels, caps, Field::DisplacementX);
    });
    const std::string side_by_side = "anim-friction-angles-displacement-x";
    timed(side_by_side + ".mp4/.gif", [&] {
      std::vector<const RunResult*> runs;
      std::vector<std::string> labels;
      for (const std::string& phi : angles) {
        runs.push_back(&friction_run(phi));
        labels.push_back("phi = " + phi + " deg, " + pts(*runs.back()));
      }
      gallery::write_side_by_side(runs, labels,
                                  "The slide at four friction angles: horizontal displacement" + q,
                                  out / ".work" / side_by_side, out, side_by_side);
    });
    fs::remove_all(out / ".work");
    for (const std::string& base : {std::string("anim-paper-slope-phi20-displacement-x"), side_by_side})
      if (fs::exists(out / (base + ".mp4")))  // none where a run failed before its slide
        std::cout << "animation: " << (out / (base + ".mp4")).string() << ", "
                  << (out / (base + ".gif")).string() << '\n';
    std::cout << "gallery: " << fmt(seconds_since(total)) << " s in all -> " << out.string()
              << std::endl;
    const std::vector<std::string> failures = g.failures();
    for (const std::string& f : failures)
      std::cerr << "error: run failed (its panels show its last frame): " << f << '\n';
    if (!failures.empty()) return kExitFailed;
  } catch (const sim::ScenarioError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitFailed;
  }
  return kExitOk;
}

}  // namespace app
