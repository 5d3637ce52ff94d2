// The size sweep: the granular column (bench/granular_column.hpp) at cells
// 1, 1/2, 1/4, 1/8 and 1/16 of issue 6's, about 25 k to 6.5 M points. Each
// row builds one world and steps it directly (sim::step, no Simulation: no
// watchdog, frames or rest test; the points sorted into cell order every
// kStepsPerSort steps, as the time loop does), first 2 untimed steps and a
// sort that size the scratch, then timed runs of 1 and 2 threads in turns, each on a copy of
// that world (so every run starts from the same state).
// Every run takes at least STEPS steps and at least 2e7 point-steps, so a
// small scene's run is not lost in the timer's noise. --busy runs a loop
// beside every run and a second 1-thread run in each round, the control.
//
// The bound: a triad a = b + s c over three 200 MB arrays (STREAM's, 24 B
// counted per element) gives this machine's memory bandwidth in the same
// run. A step must at least read the solver's state once, so triad
// bandwidth / World B/pt bounds the point-steps per second from above.
#include "bench/size_sweep.hpp"

#include <omp.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/granular_column.hpp"
#include "bench/memory_use.hpp"
#include "sim/physics/point_order.hpp"
#include "sim/physics/step.hpp"
#include "sim/physics/team.hpp"
#include "sim/scene/seed.hpp"

namespace bench {

namespace {

constexpr int kRefinements[] = {1, 2, 4, 8, 16};
constexpr double kMinPointSteps = 2e7;
constexpr long kCoarsestPoints = 25'538;  // the granular column at refine 1
// Rounds of a row up to 0.5 M points beside a busy loop, whose runs spread
// more than on an idle machine: 1 thread against 1 thread read 0.81 to
// 1.03 in best-of-3 (issue 17, fortieth pass).
constexpr int kBusyRounds = 5;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Best of five triads over three arrays of 25 M doubles, bytes per second.
double triad_bandwidth(int threads) {
  const long n = 25'000'000;
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  omp_set_num_threads(threads);
  double best = 0;
  for (int r = 0; r < 5; ++r) {
    const auto start = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) a[i] = b[i] + 3.0 * c[i];
    best = std::max(best, 24.0 * n / seconds_since(start));
  }
  if (a[n / 2] != 7.0) std::fprintf(stderr, "triad: wrong sum\n");
  return best;
}

// Point-steps per second of `steps` steps on `threads` threads.
double timed_steps(sim::World& world, const sim::StepInput& input, int threads, long steps) {
  omp_set_num_threads(threads);
  sim::StepReport report;
  const auto start = std::chrono::steady_clock::now();
  for (long k = 0; k < steps; ++k) {
    if (sim::sort_due(world, k)) sim::sort_points_by_cell(world);  // as the time loop does
    sim::step(world, input, report);
  }
  return steps * static_cast<double>(world.points.size()) / seconds_since(start);
}


// The same, on a copy of the row's world.
double timed_run(const Row& row, int threads, long steps) {
  sim::World world = row.world;
  return timed_steps(world, row.input, threads, steps);
}

}  // namespace

Row make_row(int refine) {
  const sim::Scenario s = granular_column(refine);
  Row row{sim::make_world(s), {}};
  row.input.dt = s.time_step.courant * s.cell_size / sim::max_signal_speed(row.world);
  row.input.gravity = s.gravity;
  return row;
}

void warm_up(Row& row) {
  timed_steps(row.world, row.input, 1, 2);
  sim::sort_points_by_cell(row.world);
}

pid_t start_busy_loop() {
  const pid_t pid = fork();
  if (pid == 0) {
    volatile unsigned long spin = 0;
    for (;;) ++spin;
  }
  return pid;
}

int size_sweep_rss_child(int refine) {
  if (refine > 0) {
    Row row = make_row(refine);
    warm_up(row);
    timed_steps(row.world, row.input, 1, 1);
  }
  std::printf("%.0f\n", own_peak_rss());
  return 0;
}

int size_sweep(int argc, char** argv) {
  long steps = 20, up_to = 7'000'000;
  bool busy = false;
  for (int a = 0; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--busy") busy = true;
    else if (arg == "--exact-threads") sim::follow_free_cores(false);
    else if (arg == "--up-to" && a + 1 < argc) up_to = std::atol(argv[++a]);
    else if (std::atol(arg.c_str()) > 0) steps = std::atol(arg.c_str());
    else {
      std::fprintf(stderr, "throughput --sizes: '%s': expected [STEPS] [--up-to POINTS] [--busy] [--exact-threads]\n",
                   arg.c_str());
      return 2;
    }
  }
  const double triad1 = triad_bandwidth(1), triad2 = triad_bandwidth(2);
  std::printf("triad over 3 x 200 MB: %.1f GB/s on 1 thread, %.1f GB/s on 2\n", triad1 / 1e9,
              triad2 / 1e9);
  const double idle_rss = child_peak_rss("--sizes-rss-child 0");
  const pid_t busy_pid = busy ? start_busy_loop() : 0;
  if (busy) std::printf("a busy loop (pid %d) spins beside every run\n", static_cast<int>(busy_pid));
  std::printf("granular column, cell 3.536 mm / refine; each run at least %ld steps and 2e7 "
              "point-steps; best of %d runs up to 0.5 M points, 1 run above\n",
              steps, busy ? kBusyRounds : 3);
  std::printf("%7s %9s %6s %12s %12s %8s %10s %10s %10s %12s %9s", "refine", "points", "steps",
              "1 thr Mpt/s", "2 thr Mpt/s", "speedup", "World B/pt", "grid B/pt", "RSS B/pt",
              "bound Mpt/s", "of bound");
  if (busy) std::printf(" %12s %8s", "1 thr again", "again/1");
  std::printf("\n");
  for (const int refine : kRefinements) {
    // A row has a little more than refine^2 times the coarsest row's points:
    // a row sure to be over the limit is not built.
    if (static_cast<double>(kCoarsestPoints) * refine * refine > up_to) break;
    Row row = make_row(refine);
    const double points = static_cast<double>(row.world.points.size());
    if (points > up_to) break;
    const long run_steps = std::max(steps, static_cast<long>(kMinPointSteps / points));
    warm_up(row);
    // Beside a busy loop each round also runs 1 thread again: the control.
    // Its ratio to the first 1-thread figure is what the same run reads
    // against itself, the floor under which a 2-thread ratio says nothing.
    double one = 0, two = 0, again = 0;
    const int rounds = points > 5e5 ? 1 : busy ? kBusyRounds : 3;
    for (int r = 0; r < rounds; ++r) {
      one = std::max(one, timed_run(row, 1, run_steps));
      two = std::max(two, timed_run(row, 2, run_steps));
      if (busy) again = std::max(again, timed_run(row, 1, run_steps));
    }
    double grid = 0;
    const double world = vector_bytes(row.world, &grid) / points;
    const double rss = (child_peak_rss("--sizes-rss-child " + std::to_string(refine)) - idle_rss) / points;
    const double bound = triad2 / world;
    std::printf("%7d %9.0f %6ld %12.2f %12.2f %8.2f %10.0f %10.0f %10.0f %12.1f %8.0f%%", refine,
                points, run_steps, one / 1e6, two / 1e6, two / one, world, grid / points, rss,
                bound / 1e6, 100 * two / bound);
    if (busy) std::printf(" %12.2f %8.2f", again / 1e6, again / one);
    std::printf("\n");
    std::fflush(stdout);
  }
  if (busy) {
    kill(busy_pid, SIGKILL);
    waitpid(busy_pid, nullptr, 0);
  }
  std::printf("World B/pt: std::vector capacities in sim::World, the grid's over the touched "
              "window; RSS B/pt: peak RSS of a child that builds the row's world, steps it 2 "
              "times, sorts it and steps it once more, less an idle child's; bound: 2-thread triad bandwidth / World B/pt\n");
  return 0;
}

}  // namespace bench
