#include "app/estimate.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "output/amount_text.hpp"
#include "output/frames.hpp"
#include "output/series.hpp"
#include "sim/scene/random_field.hpp"
#include "sim/scene/seed.hpp"
#include "sim/physics/step.hpp"
#include "sim/run/diagnostics.hpp"
#include "sim/run/point_chunks.hpp"

namespace app {

namespace fs = std::filesystem;

namespace {

// A soil block of 7,680 points (20 m x 6 m, h = 0.25 m, 2 x 2 points per
// cell) falling under gravity: plastic returns, walls and empty air, as in
// the shipped slopes.
const char* const kCalibrationScene = R"json({
  "name": "calibration", "description": "landslide check: the step rate of this machine",
  "domain": {"min": [0, 0], "max": [40, 12]},
  "grid": {"cell_size": 0.25, "padding_cells": 2, "points_per_cell": 2},
  "gravity": [0, -9.81],
  "boundaries": {"left": "roller", "right": "roller", "bottom": "fixed", "top": "free"},
  "materials": {"soil": {"model": "mohr-coulomb", "density": 2000, "youngs_modulus": 2e7,
                         "poisson_ratio": 0.25, "cohesion": 0, "friction_angle": 20,
                         "dilation_angle": 0, "critical_density": 1900}},
  "bodies": [{"name": "block", "material": "soil", "rectangle": {"min": [0, 0], "max": [20, 6]}}],
  "time_step": {"courant": 0.5},
  "stages": [{"name": "fall", "type": "dynamic", "duration": 1}],
  "output": {"frame_interval": 0, "vtk": "none"}
})json";

constexpr double kCalibrationSeconds = 0.15;

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

double mem_available_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  while (in >> key >> kb) {
    if (key == "MemAvailable:") return kb * 1024;
    in.ignore(256, '\n');
  }
  return 0;
}

double free_disk_bytes(fs::path p) {
  std::error_code ec;
  while (!p.empty() && !fs::exists(p, ec)) p = p.parent_path();
  if (p.empty()) p = ".";
  const fs::space_info s = fs::space(p, ec);
  return ec ? 0 : double(s.available);
}

// Events at stage times k * every in [from, to] (frame or state times), and
// the stage's end as one more when it falls between two.
double events(double from, double to, double every) {
  const double first = from > 0 ? std::ceil(from / every - 1e-9) : 0;
  const double last = std::floor(to / every + 1e-9);
  return last - first + 1 + (to - last * every > 1e-9 * every ? 1 : 0);
}

// Steps, frames and states of the timed stages still to run.
void count_stages(const sim::Simulation& sim, Estimate& e) {
  const sim::Scenario& s = sim.scenario();
  for (std::size_t k = sim.stage_index(); k < s.stages.size(); ++k) {
    const sim::StageSpec& stage = s.stages[k];
    if (stage.type == sim::StageType::MaterialChange) continue;
    const double from = k == sim.stage_index() && sim.stage_started() ? sim.stage_time() : 0;
    StageSteps st{stage.name, (stage.duration - from) / e.dt, stage.rest.enabled};
    e.steps += st.steps;
    e.may_end_early = e.may_end_early || st.may_end_early;
    e.stages.push_back(st);
    const bool painted = sim::stage_is_painted(s, stage);
    if (e.fields > 0 && painted) e.frames += events(from, stage.duration, s.output.frame_interval);
    // A row at each frame of a painted stage; otherwise at its start, at
    // most one a step at each row interval, and at its end.
    const double every = painted ? s.output.frame_interval : series_interval(s, stage);
    e.rows += painted ? events(from, stage.duration, every)
                      : std::min(st.steps + 2, events(from, stage.duration, every));
    if (s.output.vtk == "stage-end") e.states += 1;
    if (s.output.vtk == "interval") e.states += events(from, stage.duration, s.output.vtk_interval);
  }
  if (s.output.vtk == "frames") e.states = e.frames;
}

}  // namespace

Calibration calibrate() {
  // Once per thread count and process: the members of a sweep (sweep/), each
  // run through run's preflight, would otherwise pay 0.15 s apiece for it.
  static std::map<int, Calibration> measured;
  const int threads = omp_get_max_threads();
  const auto known = measured.find(threads);
  if (known != measured.end()) return known->second;
  const sim::Scenario s = sim::parse_scenario(kCalibrationScene, "the calibration scene");
  sim::World w = sim::make_world(s);
  sim::StepReport report;
  double signal = sim::max_signal_speed(w);
  auto one_step = [&] {
    sim::step(w, sim::StepInput{0.5 * s.cell_size / signal, s.gravity, 0.0}, report);
    signal = report.max_signal;
  };
  one_step();  // first-touch allocation of the scratch arrays
  const auto start = std::chrono::steady_clock::now();
  long steps = 0;
  while (steps < 3 || seconds_since(start) < kCalibrationSeconds) {
    one_step();
    ++steps;
  }
  Calibration c;
  c.point_steps_per_second = double(w.points.size()) * double(steps) / seconds_since(start);
  const auto rows_start = std::chrono::steady_clock::now();
  long rows = 0;
  // What a row measures (output/series.cpp); each sum enters an OpenMP
  // region, a call into libgomp that the compiler cannot drop.
  while (rows < 3 || seconds_since(rows_start) < kCalibrationSeconds / 10) {
    sim::measure_motion(w);
    sim::kinetic_energy(w);
    sim::elastic_energy(w);
    ++rows;
  }
  c.row_seconds_per_point = seconds_since(rows_start) / double(rows) / double(w.points.size());
  return measured[threads] = c;
}

Estimate estimate_run(const sim::Simulation& sim, int width, int height, const fs::path& out,
                      int threads) {
  const sim::Scenario& s = sim.scenario();
  Estimate e;
  e.points = sim.world().points.size();
  e.nodes = std::size_t(sim.world().grid.nx) * std::size_t(sim.world().grid.ny);
  e.dt = sim.next_time_step();
  e.threads = threads;
  e.frame_width = width;
  e.frame_height = height;
  e.fields = width > 0 ? int(s.output.fields.size()) : 0;
  count_stages(sim, e);
  e.point_steps = e.steps * double(e.points);
  const double pixels = double(width) * height;
  const double spilled = 4.0 * e.points * (3 + e.fields) + (s.materials.size() > 1 ? e.points : 0);
  e.disk_bytes = e.frames * (spilled + e.fields * pixels * kFrameBytesPerPixel) +
                 e.states * e.points * kVtkBytesPerPoint;
  e.memory_bytes = kBaseMemoryBytes + kBytesPerPoint * e.points + kBytesPerNode * e.nodes;
  if (e.frames > 0 && e.fields > 0)
    e.memory_bytes += (sim::kBytesPerPaintedPoint + sim::kBytesPerPaintedFieldPoint * e.fields) *
                      e.points;
  // A random field's draw is freed before the points' own strengths are
  // made (sim::set_point_strength), so the larger of the two counts: for a
  // 601,148-point slope 375 MB of draw, against 365 MB more peak RSS
  // measured than the same run without a field (README.md).
  if (sim::sets_random_field(s))
    e.memory_bytes += std::max(sim::field_draw_peak_bytes(sim::field_lattice(s)),
                               sim::kBytesPerPointWithField * e.points);
  const Calibration c = calibrate();
  e.point_steps_per_second = c.point_steps_per_second;
  // A scene of more than one chunk measures its rows on the run's threads.
  const double row_threads = double(std::min<std::size_t>(threads, sim::point_chunks(e.points)));
  e.row_seconds = e.rows * double(e.points) * c.row_seconds_per_point / std::max(1.0, row_threads);
  const double paint_seconds = pixels * kPaintSecondsPerPixel + e.points * kPaintSecondsPerPoint;
  e.wall_seconds = e.point_steps / e.point_steps_per_second + e.row_seconds +
                   e.frames * e.fields * paint_seconds + e.states * e.points * kVtkSecondsPerPoint;
  e.available_memory_bytes = mem_available_bytes();
  e.free_disk_bytes = out.empty() ? 0 : free_disk_bytes(out);
  return e;
}

void print_estimate(std::ostream& o, const Estimate& e) {
  const char* upto = e.may_end_early ? "up to " : "";
  o << "estimate: " << e.points << " points, " << e.nodes << " grid nodes, first dt = " << e.dt
    << " s\n  steps:";
  for (const StageSteps& st : e.stages)
    o << ' ' << st.name << ' ' << (st.may_end_early ? "up to " : "") << count_text(st.steps)
      << (st.may_end_early ? " (ends early at rest)" : "") << ',';
  o << " in all " << upto << count_text(e.steps) << " steps, " << count_text(e.point_steps)
    << " point-steps\n";
  if (e.fields > 0)
    o << "  frames: " << upto << count_text(e.frames) << " per field, " << e.fields
      << " fields, " << e.frame_width << " x " << e.frame_height << " px\n";
  if (e.states > 0) o << "  VTK states: " << upto << count_text(e.states) << '\n';
  o << "  series rows: " << upto << count_text(e.rows) << " (" << duration_text(e.row_seconds)
    << ")\n";
  o << "  disk: " << upto << bytes_text(e.disk_bytes);
  if (e.free_disk_bytes > 0) o << " (" << bytes_text(e.free_disk_bytes) << " free)";
  o << "\n  memory: about " << bytes_text(e.memory_bytes);
  if (e.available_memory_bytes > 0) o << " (" << bytes_text(e.available_memory_bytes) << " available)";
  o << "\n  wall time: " << (e.may_end_early ? "up to about " : "about ")
    << duration_text(e.wall_seconds) << " (" << count_text(e.point_steps_per_second)
    << " point-steps/s on " << e.threads << (e.threads == 1 ? " thread" : " threads")
    << ", measured now)\n";
}

std::string limit_passed(const Estimate& e, const std::string& file) {
  std::ostringstream m;
  m << file << ": ";
  if (e.available_memory_bytes > 0 && e.memory_bytes > e.available_memory_bytes)
    m << "the run needs about " << bytes_text(e.memory_bytes) << " of memory (" << e.points
      << " points, " << e.nodes << " grid nodes): expected at most the "
      << bytes_text(e.available_memory_bytes) << " this machine has available";
  else if (e.disk_bytes > kMaxDiskBytes)
    m << "the run would write up to " << bytes_text(e.disk_bytes) << " (" << count_text(e.frames)
      << " frames per field, " << count_text(e.states) << " VTK states): expected at most "
      << bytes_text(kMaxDiskBytes);
  else if (e.free_disk_bytes > 0 && e.disk_bytes > e.free_disk_bytes)
    m << "the run would write up to " << bytes_text(e.disk_bytes) << ": expected at most the "
      << bytes_text(e.free_disk_bytes) << " free on the output's disk";
  else if (e.steps > kMaxSteps)
    m << "the run would take " << (e.may_end_early ? "up to " : "") << count_text(e.steps)
      << " steps (first dt = " << e.dt << " s): expected at most " << count_text(kMaxSteps);
  else if (e.wall_seconds > kMaxWallSeconds)
    m << "the run would take about " << duration_text(e.wall_seconds) << " of wall time ("
      << count_text(e.point_steps) << " point-steps at " << count_text(e.point_steps_per_second)
      << " per second): expected at most " << duration_text(kMaxWallSeconds);
  else
    return "";
  return m.str();
}

}  // namespace app
