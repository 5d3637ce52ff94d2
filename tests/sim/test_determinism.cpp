// A run gives bit-identical points whatever the number of threads. On a
// mismatch the test prints both hashes.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstdint>
#include <cstdio>
#include <cstring>

#include "sim/physics/team.hpp"
#include "sim/run/simulation.hpp"
#include "support.hpp"

namespace {

using simtest::state_hash;

std::uint64_t run_with_threads(const char* file, int threads) {
  sim::Scenario s = sim::load_scenario(file);
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
}

}  // namespace
