#include "app/preflight.hpp"

#include <omp.h>

#include <iostream>
#include <sstream>

#include "output/output_dir.hpp"
#include "output/state_cache.hpp"
#include "sim/io/binary_io.hpp"
#include "render/error.hpp"
#include "render/video.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

// Bad input found by the preflight, its one-line message ready.
struct Refusal {
  std::string message;
};

void check_paths(const PreflightRequest& r) {
  if (!r.out.empty()) {
    check_writable_dir(r.out, "--out");
    if (!r.checkpoint && !r.overwrite) refuse_earlier_outputs(r.out);
  }
  if (!r.state_cache.empty()) check_writable_dir(r.state_cache, "--state-cache");
}

// Painting is set up before anything runs or is written: a missing ffmpeg
// or OSMesa, or frames too small for their axes, must not show up after
// hours of simulation. Returns the frames' full size (0 x 0: none).
std::pair<int, int> set_up_painting(const PreflightRequest& r, Prepared& p) {
  const sim::Scenario& s = *r.scenario;
  if (!paints_frames(s)) return {0, 0};
  std::string why;
  if (!render::ffmpeg_available(&why))
    throw Refusal{r.scenario_file +
                  " asks for painted frames (output.frame_interval > 0), which are encoded "
                  "into mp4 and gif by ffmpeg: " + why};
  try {
    p.recorder = std::make_unique<FrameRecorder>(s, r.out);
  } catch (const std::exception& e) {
    throw Refusal{std::string("cannot set up the off-screen painter: ") + e.what()};
  }
  try {
    const FrameView view = p.recorder->check_layouts();
    return {view.width, view.height};
  } catch (const render::Error& e) {
    const auto& size = s.output.image_size;
    std::ostringstream m;
    m << r.scenario_file << ": output.image_size = [" << size[0] << ", "
      << (size[1] == sim::kAutoHeight ? std::string("\"auto\"") : std::to_string(size[1]))
      << "]: expected a size that holds a frame's axes, labels and colour bar (" << e.what()
      << ")";
    throw Refusal{m.str()};
  }
}

void set_up_simulation(const PreflightRequest& r, Prepared& p) {
  try {
    p.simulation = std::make_unique<sim::Simulation>(*r.scenario);  // seeds the points
    if (r.checkpoint)
      p.simulation->restore_state(r.checkpoint->state, checkpoint_path(r.out).string());
    else if (!r.state_cache.empty())
      p.reused_stages = restore_cached_state(r.state_cache, *p.simulation);
  } catch (const sim::ScenarioError& e) {  // e.g. a body that holds no point
    throw Refusal{e.what()};
  } catch (const sim::StateError& e) {
    throw Refusal{e.what()};
  }
}

}  // namespace

Verdict preflight_verdict(const PreflightRequest& r, Prepared& p, std::ostream& estimate_out) {
  Verdict v;
  try {
    check_paths(r);
    const auto [width, height] = set_up_painting(r, p);
    set_up_simulation(r, p);
    try {
      p.estimate = estimate_run(*p.simulation, width, height, r.out, r.threads);
    } catch (const sim::ScenarioError& e) {  // a fixed time step above the stable bound
      throw Refusal{e.what()};
    }
    print_estimate(estimate_out, p.estimate);
    const std::string passed = limit_passed(p.estimate, r.scenario_file);
    if (!passed.empty() && !r.allow_long) throw Refusal{passed + " (or --allow-long)"};
    v.warning = passed;
    return v;
  } catch (const Refusal& e) {
    v.refusal = e.message;
  } catch (const PathError& e) {
    v.refusal = e.what();
  }
  p = Prepared{};
  return v;
}

bool preflight(const PreflightRequest& r, Prepared& p, std::ostream& estimate_out) {
  const Verdict v = preflight_verdict(r, p, estimate_out);
  if (!v.warning.empty()) std::cerr << "warning: " << v.warning << "; going on (--allow-long)\n";
  if (!v.refusal.empty()) std::cerr << "error: " << v.refusal << '\n';
  return v.refusal.empty();
}

int use_threads(int asked) {
  if (asked > 0) omp_set_num_threads(asked);
  return omp_get_max_threads();
}

}  // namespace app
