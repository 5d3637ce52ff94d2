// `throughput --busy-start [STEPS] [ROUNDS]`: what a run started beside a
// busy process loses while its team settles (sim/physics/team.hpp). A loop
// spins on one of the cores; each round times the first STEPS steps (default
// 200) of the granular column (25,538 points) from a fresh team, once with
// 1 thread and once with 2 asked for, after a pause of 250 ms that lets
// OpenMP's workers fall asleep as they are at the start of a run. Prints the
// least and the median of each over the ROUNDS (default 11). The whole-run
// figure is `--sizes --busy`'s; this one isolates the team's first counts.
#include <omp.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "bench/size_sweep.hpp"
#include "sim/physics/step.hpp"

namespace bench {

namespace {

double milliseconds_of_steps(const sim::World& world, const sim::StepInput& input, int threads,
                             int steps) {
  sim::World c = world;
  c.team = sim::Team{};
  omp_set_num_threads(threads);
  usleep(250'000);
  sim::StepReport report;
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k) sim::step(c, input, report);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void print_spread(const char* label, std::vector<double> ms) {
  std::sort(ms.begin(), ms.end());
  std::printf("  %-12s least %7.1f ms, median %7.1f ms\n", label, ms.front(), ms[ms.size() / 2]);
}

}  // namespace

int busy_start(int argc, char** argv) {
  const int steps = argc > 0 ? std::atoi(argv[0]) : 200;
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 11;
  if (steps < 1 || rounds < 1 || argc > 2) {
    std::fprintf(stderr, "throughput --busy-start: expected [STEPS >= 1] [ROUNDS >= 1]\n");
    return 2;
  }
  Row row = make_row(1);
  warm_up(row);
  const sim::World& world = row.world;
  const sim::StepInput& input = row.input;
  const pid_t busy = start_busy_loop();
  std::printf("first %d steps of the granular column (%zu points) from a fresh team, a busy "
              "loop (pid %d) beside, %d rounds in turns:\n",
              steps, world.points.size(), static_cast<int>(busy), rounds);
  std::vector<double> one, two;
  for (int r = 0; r < rounds; ++r) {
    one.push_back(milliseconds_of_steps(world, input, 1, steps));
    two.push_back(milliseconds_of_steps(world, input, 2, steps));
  }
  kill(busy, SIGKILL);
  waitpid(busy, nullptr, 0);
  print_spread("1 thread", one);
  print_spread("2 asked for", two);
  return 0;
}

}  // namespace bench
