// A run gives bit-identical points whatever the number of threads. On a
// mismatch the test prints both hashes.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstdint>
#include <cstdio>
#include <cstring>

#include "sim/physics/step.hpp"
#include "sim/physics/team.hpp"
#include "sim/run/simulation.hpp"
#include "sim/scene/seed.hpp"
#include "support.hpp"

namespace {

using simtest::state_hash;

std::uint64_t run_with_threads(const char* file, int threads,
                               sim::TransferScheme transfer = sim::TransferScheme::Flip) {
  sim::Scenario s = sim::load_scenario(file);
  s.transfer = transfer;
  s.output.frame_interval = 0;
  for (sim::StageSpec& stage : s.stages) stage.duration = std::min(stage.duration, 1.0);
  for (sim::StageSpec& stage : s.stages) stage.rest.enabled = false;
  sim::follow_free_cores(false);  // two threads even on a loaded machine
  omp_set_num_threads(threads);
  sim::Simulation simulation(s);
  sim::Observer quiet;
  simulation.run(quiet);
  return state_hash(simulation.world().points);
}

TEST(Determinism, OneAndTwoThreadsGiveTheSameState) {
  // The paper's slope with its house: Mohr-Coulomb soil, an elastic body,
  // walls, the gravity ramp and the first second of the slide.
  const char* file = LANDSLIDE_SOURCE_DIR "/scenarios/paper-slope-phi20-n1661.json";
  const std::uint64_t one = run_with_threads(file, 1);
  const std::uint64_t two = run_with_threads(file, 2);
  std::printf("state hash: 1 thread %016llx, 2 threads %016llx\n",
              static_cast<unsigned long long>(one), static_cast<unsigned long long>(two));
  EXPECT_EQ(one, two) << "new hash with 2 threads: " << std::hex << two;
  // Three: locate's pair of threads and one alone with its pool
  // (sim/physics/locate_stencils.cpp).
  const std::uint64_t three = run_with_threads(file, 3);
  EXPECT_EQ(one, three) << "new hash with 3 threads: " << std::hex << three;
}

// The same with APIC's transfers, whose G2P a thread done with its own bands
// shares out as it does the paper's (sim/physics/bands.hpp).
TEST(Determinism, OneAndTwoThreadsGiveTheSameStateWithApic) {
  const char* file = LANDSLIDE_SOURCE_DIR "/scenarios/paper-slope-phi20-n1661.json";
  const std::uint64_t one = run_with_threads(file, 1, sim::TransferScheme::Apic);
  const std::uint64_t two = run_with_threads(file, 2, sim::TransferScheme::Apic);
  EXPECT_EQ(one, two) << "new hash with 2 threads: " << std::hex << two;
}

// The threads' split of the bands follows their measured pace
// (sim/physics/bands.hpp), so it differs from run to run; it must change no
// bit. Here the pace is held before every step so that thread 0 is
// `slower` times as slow per point as thread 1, and the state after 40
// steps of the slope under full gravity is compared with one thread's.
struct SplitRun {
  std::uint64_t hash = 0;
  long points[2] = {0, 0};  // each thread's points in the last step
};

SplitRun steps_with_pace(int threads, double slower) {
  sim::Scenario s = sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/paper-slope-phi20.json");
  sim::World w = sim::make_world(s);
  sim::StepInput in;
  in.dt = s.time_step.courant * s.cell_size / sim::max_signal_speed(w);  // the points are at rest
  in.gravity = s.gravity;
  sim::follow_free_cores(false);
  omp_set_num_threads(threads);
  sim::StepReport report;
  for (int k = 0; k < 40; ++k) {
    sim::ThreadPace pace;
    pace.per_point = slower * 1e-9;  // no points, so the step's time leaves it as it is
    w.thread_pace.assign(static_cast<std::size_t>(threads), pace);
    if (threads > 1) w.thread_pace[1].per_point = 1e-9;
    sim::step(w, in, report);
  }
  SplitRun r;
  r.hash = state_hash(w.points);
  for (int t = 0; t < threads && t < 2; ++t) r.points[t] = w.thread_pace[t].points;
  return r;
}

TEST(Determinism, ASplitByPaceGivesTheSameState) {
  const SplitRun one = steps_with_pace(1, 1.0);
  for (const double slower : {3.0, 1.0 / 3.0}) {
    const SplitRun two = steps_with_pace(2, slower);
    // Thread 0's share of the points, 1 / (1 + slower) but for whole bands
    // (bands.hpp), is well off an even split.
    const double share = static_cast<double>(two.points[0]) / (two.points[0] + two.points[1]);
    if (slower > 1) {
      EXPECT_LT(share, 0.4) << "thread 0 had " << two.points[0] << " points";
    } else {
      EXPECT_GT(share, 0.6) << "thread 0 had " << two.points[0] << " points";
    }
    EXPECT_EQ(one.hash, two.hash) << "new hash with thread 0 " << slower << " times as slow: "
                                  << std::hex << two.hash;
  }
}

}  // namespace
