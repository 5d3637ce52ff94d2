// What one row of series.csv costs beside the step: the granular column of
// the size sweep (bench/granular_column.hpp) at a given refinement, stepped
// STEPS times so that its points have moved and yielded, then measured as a
// row measures it (sim::measure_motion, the soil's runout inside it, and the
// two energies of the balance) and as a stage's end does (sim::measure_stage)
// REPEATS times. Prints ms per row and ns per
// point for each, and a hash of every figure they return, so that two
// builds, or two thread counts of one build, can be compared for speed and
// for bits. A run without frames takes a row at every 1/100 of each stage
// (scenarios/README.md), so at millions of points the rows can cost as much
// as the steps between them.
//   OMP_NUM_THREADS=N build/bench/series_rows [REFINE >= 1] [REPEATS >= 1] [STEPS >= 0]
#include <omp.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "bench/granular_column.hpp"
#include "sim/physics/step.hpp"
#include "sim/run/diagnostics.hpp"
#include "sim/run/runout.hpp"
#include "sim/scene/seed.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// FNV-1a over the bytes of the figures measured.
struct Hash {
  std::uint64_t h = 1469598103934665603ull;
  void add(double v) {
    unsigned char c[sizeof v];
    std::memcpy(c, &v, sizeof v);
    for (const unsigned char b : c) h = (h ^ b) * 1099511628211ull;
  }
};

void hash_metrics(Hash& hash, const sim::StageMetrics& m) {
  for (const double v : {m.max_soil_ux, m.initial_toe, m.toe, m.runout, m.main_body_fraction,
                         m.packed_fraction, m.disconnected_fraction, m.yielding_fraction,
                         m.deposit_slope_deg})
    hash.add(v);
  for (const sim::MaterialMotion& mm : m.materials)
    for (const double v : {mm.mean_ux, mm.mean_uy, mm.max_displacement}) hash.add(v);
}

template <class F>
double best_seconds(int repeats, F measure) {
  double best = 1e300;
  for (int k = 0; k < repeats; ++k) {
    const auto t = Clock::now();
    measure();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const int refine = argc > 1 ? std::atoi(argv[1]) : 4;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
  const int steps = argc > 3 ? std::atoi(argv[3]) : 20;
  if (argc > 4 || refine < 1 || repeats < 1 || steps < 0) {
    std::fprintf(stderr, "usage: series_rows [REFINE >= 1] [REPEATS >= 1] [STEPS >= 0]\n");
    return 2;
  }
  const sim::Scenario s = bench::granular_column(refine);
  sim::World w = sim::make_world(s);
  sim::StepInput in;
  in.dt = s.time_step.courant * s.cell_size / sim::max_signal_speed(w);
  in.gravity = s.gravity;
  sim::StepReport report;
  for (int k = 0; k < steps; ++k) sim::step(w, in, report);

  Hash hash;
  sim::StageMetrics metrics;
  sim::Runout runout;
  double kinetic = 0, elastic = 0;
  const double stage = best_seconds(repeats, [&] { metrics = sim::measure_stage(w); });
  const double motion = best_seconds(repeats, [&] { sim::measure_motion(w); });
  const double toe = best_seconds(repeats, [&] { runout = sim::measure_runout(w); });
  const double energies = best_seconds(repeats, [&] {
    kinetic = sim::kinetic_energy(w);
    elastic = sim::elastic_energy(w);
  });
  hash_metrics(hash, metrics);
  for (const double v : {runout.initial_toe, runout.toe, kinetic, elastic}) hash.add(v);
  const double n = double(w.points.size());
  std::printf("%zu points, %d threads, best of %d\n", w.points.size(), omp_get_max_threads(),
              repeats);
  const auto line = [&](const char* what, double seconds) {
    std::printf("%-18s %8.2f ms  %6.1f ns/pt\n", what, seconds * 1e3, seconds / n * 1e9);
  };
  line("measure_stage", stage);
  line("measure_motion", motion);
  line("  of it, runout", toe);
  line("energies", energies);
  line("row", motion + energies);
  std::printf("hash %016llx\n", static_cast<unsigned long long>(hash.h));
  return 0;
}
