// The step's phases timed one by one: the granular column of the size sweep
// (bench/granular_column.hpp) at a given refinement, stepped on one thread by
// calling the phases of sim::step in its order (outside a parallel region one
// thread owns every band). Prints ns per point for each phase and a hash of
// the points and the step's sums, so that two builds can be compared for
// speed and for bits. Run two builds in turns and compare the minima: this
// machine's speed drifts by up to 40 % from minute to minute.
// --own-strength gives every point its own friction angle (28 to 32 degrees
// in a fixed pattern), as a random field does: each point then has its own
// Mohr-Coulomb surface (sim/physics/point_strength.hpp). The points are
// sorted into cell order every kStepsPerSort steps, as the time loop does
// (sim/physics/point_order.hpp; timed as "sort"); --scene-order leaves them
// in scene order. --mixed seeds the points in a random order (a fixed
// shuffle), as a long runout leaves soil whose neighbours were seeded far
// apart: the case the sort is for, where the column's own seeding order is
// already close to the step's. --threads N steps with a team of N threads,
// as sim::step does, with a barrier after every phase (the time a phase's
// threads wait for each other is counted in that phase). --scene NAME steps
// scenarios/NAME.json instead of the column (REFINE must then be 1), from
// its seeded state under its full gravity: a slope's window, unlike the
// column's, is mostly air above its face. --sorts N then times N sorts into
// cell order of a copy of the world, each after one more step, whether due
// or not: the sort alone, one figure per sort (the first ones size the
// sort's scratch arrays), after the hash, which they do not touch.
// --slide-at T (with --scene) runs the scene's stages first, as `landslide
// run` does, and times its steps from T s into its first dynamic stage: the
// slide's spread-out window and yielding soil, where the gallery's runs
// spend most of their steps, rather than the seeded state.
// --whole-step then times sim::step itself, as the time loop calls it (no
// barrier between phases: a band waits only for its neighbours' marks),
// on 1 thread and on N (--threads, at least 2) in turns, three rounds, each
// on a copy of the world: ns per point-step, each thread's own work from the
// grid's reset to G2P (its pace's seconds, waits left out; locate is folded
// into the next step's) and where the bands were split. Where one thread
// works longer than the other, the difference is mostly the other's wait.
//   build/bench/phases [REFINE] [STEPS] [--own-strength] [--scene-order] [--mixed] [--threads N]
//                      [--scene NAME [--slide-at T]] [--sorts N] [--whole-step]
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <random>
#include <algorithm>
#include <map>
#include <omp.h>
#include <string>
#include <vector>

#include "bench/granular_column.hpp"
#include "sim/physics/point_order.hpp"
#include "sim/physics/point_strength.hpp"
#include "sim/physics/step.hpp"
#include "sim/physics/team.hpp"
#include "sim/run/simulation.hpp"
#include "sim/scene/seed.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// FNV-1a over the bytes of the points' state and the step's sums.
struct Hash {
  std::uint64_t h = 1469598103934665603ull;
  void add(const void* data, std::size_t bytes) {
    const auto* c = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ c[i]) * 1099511628211ull;
  }
};

// `steps` whole steps of a copy of `w` on a team of `threads`, after 5
// untimed ones that size its scratch; prints the figures --whole-step names.
void time_whole_steps(const sim::World& w, const sim::StepInput& in, int steps, int threads) {
  omp_set_num_threads(threads);
  sim::World c = w;
  sim::StepReport report;
  for (int k = 0; k < 5; ++k) sim::step(c, in, report);
  std::vector<double> worked(static_cast<std::size_t>(threads), 0.0);
  std::map<std::vector<int>, int> splits;  // the bands' split: steps that had it
  const Clock::time_point start = Clock::now();
  for (int k = 0; k < steps; ++k) {
    if (sim::sort_due(c, k)) sim::sort_points_by_cell(c);
    sim::step(c, in, report);
    if (threads == 1) continue;
    ++splits[std::vector<int>(c.thread_bands.begin() + 1, c.thread_bands.end() - 1)];
    for (int t = 0; t < threads; ++t) worked[t] += c.thread_pace[t].worked;
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const double point_steps = static_cast<double>(c.points.size()) * steps;
  std::printf("%d thread%s: %5.1f ns/pt-step", threads, threads > 1 ? "s" : "",
              seconds / point_steps * 1e9);
  if (threads > 1) {
    std::printf("; each thread's work");
    for (double t : worked) std::printf(" %.1f", t / point_steps * 1e9);
    std::printf(" ns/pt-step; split of %zu bands at", c.band_start.size() - 1);
    for (const auto& [at, count] : splits) {
      for (int b : at) std::printf(" %d", b);
      std::printf(" (%d steps)", count);
    }
  }
  std::printf("\n");
}

// The scene's world `seconds` into its first dynamic stage, and the time step
// the time loop would take next: its stages run as `landslide run` runs them.
struct StopHere {};
class StopInSlide : public sim::Observer {
 public:
  explicit StopInSlide(double seconds) : seconds_(seconds) {}
  void progress(const sim::Simulation& run, const sim::StageSpec& stage, long) override {
    if (stage.type != sim::StageType::Dynamic || run.stage_time() < seconds_) return;
    damping = stage.damping;
    throw StopHere{};
  }
  double damping = 0;  // of the stage stopped in

 private:
  double seconds_;
};
sim::World world_in_slide(const sim::Scenario& s, double seconds, sim::StepInput& in) {
  sim::Simulation run(s);
  StopInSlide stop(seconds);
  try {
    run.run(stop);
  } catch (const StopHere&) {
    in.dt = run.next_time_step();
    in.gravity = s.gravity;
    in.damping = stop.damping;
    std::printf("from t = %.3f s of the slide, dt = %.3g s\n", run.stage_time(), in.dt);
    return run.world();
  }
  std::fprintf(stderr, "phases: the scene ended before %g s into a dynamic stage\n", seconds);
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  bool own = false, sort = true, mixed = false, whole = false;
  int threads = 1, sorts = 0;
  double slide_at = -1;
  std::string scene;
  for (; argc > 1; --argc) {
    const std::string last = argv[argc - 1];
    if (argc > 2 && std::string(argv[argc - 2]) == "--threads") {
      threads = std::atoi(last.c_str());
      --argc;
    } else if (argc > 2 && std::string(argv[argc - 2]) == "--sorts") {
      sorts = std::atoi(last.c_str());
      --argc;
    } else if (argc > 2 && std::string(argv[argc - 2]) == "--slide-at") {
      slide_at = std::atof(last.c_str());
      --argc;
    } else if (argc > 2 && std::string(argv[argc - 2]) == "--scene") {
      scene = last;
      --argc;
    } else if (last == "--own-strength") own = true;
    else if (last == "--whole-step") whole = true;
    else if (last == "--scene-order") sort = false;
    else if (last == "--mixed") mixed = true;
    else break;
  }
  const int refine = argc > 1 ? std::atoi(argv[1]) : 1, steps = argc > 2 ? std::atoi(argv[2]) : 200;
  if (refine < 1 || steps < 1 || argc > 3 || threads < 1 || sorts < 0 ||
      (!scene.empty() && refine != 1) || (slide_at >= 0 && (scene.empty() || own || mixed))) {
    std::fprintf(stderr, "usage: phases [REFINE >= 1] [STEPS >= 1] [--own-strength] "
                         "[--scene-order] [--mixed] [--threads N >= 1] [--scene NAME, REFINE 1] "
                         "[--slide-at T >= 0, with --scene] [--sorts N >= 0] [--whole-step]\n");
    return 2;
  }
  // Everything outside the timed phases' own region (the warm-up steps, the
  // sorts) takes its team from omp_get_max_threads() (sim/physics/team.hpp):
  // as many threads as the phases, or "--threads 1" sorted on two.
  omp_set_num_threads(threads);
  const sim::Scenario s = scene.empty() ? bench::granular_column(refine) : bench::load_scene(scene);
  sim::StepInput in;
  sim::World w = slide_at >= 0 ? world_in_slide(s, slide_at, in) : sim::make_world(s);
  if (own) {
    std::vector<double> angles(w.points.size());
    for (std::size_t p = 0; p < angles.size(); ++p) angles[p] = (28.0 + (p * 7 % 41) * 0.1) * M_PI / 180;
    sim::set_point_strength(w, 0, "friction_angle", angles);
  }
  if (mixed) {  // a fixed shuffle taken as the scene's own order
    w.order.resize(w.points.size());
    std::iota(w.order.begin(), w.order.end(), 0);
    std::mt19937 shuffle(17);
    std::shuffle(w.order.begin(), w.order.end(), shuffle);
    sim::sort_points_by_cell(w);
    w.scene_index.clear();
  }
  if (slide_at < 0) {
    in.dt = s.time_step.courant * s.cell_size / sim::max_signal_speed(w);  // at rest: the fastest P wave
    in.gravity = s.gravity;
  }
  sim::StepReport report;
  for (int k = 0; k < 30; ++k) sim::step(w, in, report);  // past the first, elastic steps

  const char* names[8] = {"sort",         "locate", "reset", "p2g",
                          "walls",        "stress+force", "nodal", "g2p"};
  double seconds[8] = {};
  for (int k = 0; k < steps; ++k) {
    Clock::time_point t[9];
    t[0] = Clock::now();
    if (sort && sim::sort_due(w, k)) sim::sort_points_by_cell(w);  // as the time loop
    t[1] = Clock::now();
    sim::prepare_locate(w);
#pragma omp parallel num_threads(threads)
    {
      // Thread 0 reads the clock after the barrier that ends each phase.
      const auto mark = [&](int i) {
#pragma omp barrier
#pragma omp master
        t[i] = Clock::now();
      };
      if (!sim::locate_and_sort(w)) std::abort();
      mark(2);
      sim::reset_grid(w);
      mark(3);
      sim::points_to_grid(w);
      mark(4);
      sim::enforce_walls_on_momentum(w);
      mark(5);
      sim::update_stress_and_forces(w, in);
      mark(6);
      sim::update_nodal_momentum(w, in.dt);
      mark(7);
      sim::grid_to_points(w, in);
      mark(8);
    }
    for (int i = 0; i < 8; ++i) seconds[i] += std::chrono::duration<double>(t[i + 1] - t[i]).count();
  }
  const double point_steps = static_cast<double>(w.points.size()) * steps;
  double total = 0;
  for (int i = 0; i < 8; ++i) {
    std::printf("%-13s %6.1f ns/pt\n", names[i], seconds[i] / point_steps * 1e9);
    total += seconds[i];
  }
  std::printf("%-13s %6.1f ns/pt (%zu points, %d steps, %d threads)\n", "total",
              total / point_steps * 1e9, w.points.size(), steps, threads);
  sim::restore_scene_order(w);  // the hash reads the points in scene order
  Hash hash;
  const sim::Particles& p = w.points;
  for (const auto* v : {&p.x, &p.y, &p.vx, &p.vy, &p.density, &p.sxx, &p.syy, &p.sxy, &p.szz})
    hash.add(v->data(), v->size() * sizeof(double));
  hash.add(p.yielded.data(), p.yielded.size());
  const sim::StepReport sums = sim::sum_step_report(w);
  hash.add(&sums, sizeof sums);
  std::printf("hash %016llx\n", static_cast<unsigned long long>(hash.h));
  if (sorts > 0) {
    sim::World copy = w;
    std::printf("sorts, ns/pt:");
    for (int k = 0; k < sorts; ++k) {
      sim::step(copy, in, report);
      const Clock::time_point start = Clock::now();
      sim::sort_points_by_cell(copy);
      const double sorted = std::chrono::duration<double>(Clock::now() - start).count();
      std::printf(" %.1f", sorted / static_cast<double>(copy.points.size()) * 1e9);
    }
    std::printf("\n");
  }
  if (whole) {
    sim::follow_free_cores(false);  // the team as asked, on a loaded machine too
    for (int round = 0; round < 3; ++round)
      for (const int team : {1, std::max(threads, 2)}) time_whole_steps(w, in, steps, team);
  }
  return 0;
}
