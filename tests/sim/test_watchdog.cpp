// The watchdog stops a run that leaves its limits with a message naming the
// stage, step, time, point, position and material, and hands over the last
// state that was within them. Faults are injected into a settling block
// through the observer (the only place a test can reach the running world).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "sim/run/simulation.hpp"
#include "sim/run/watchdog.hpp"
#include "support.hpp"

namespace {

// Calls `inject` on the world once, after step `at`.
class Injector : public sim::Observer {
 public:
  Injector(long at, std::function<void(sim::World&)> inject) : at_(at), inject_(std::move(inject)) {}
  void progress(const sim::Simulation& s, const sim::StageSpec&, long steps) override {
    if (steps == at_) inject_(const_cast<sim::World&>(s.world()));  // fault injection
  }

 private:
  long at_;
  std::function<void(sim::World&)> inject_;
};

sim::Scenario settling_block() {
  sim::Scenario s = simtest::block_scenario({1, 0}, {3, 1}, 0.25, 2, {0, 0}, {4, 3});
  s.gravity = {0, -9.81};
  s.boundaries.bottom = {sim::BoundaryKind::Fixed, 0.0};
  sim::StageSpec settle;
  settle.name = "settle";
  settle.type = sim::StageType::Dynamic;
  settle.duration = 0.5;
  s.stages.push_back(settle);
  return s;
}

// Runs with the fault; returns the watchdog's error (fails if none came).
sim::WatchdogError run_with_fault(long at, std::function<void(sim::World&)> inject) {
  sim::Simulation simulation(settling_block());
  Injector injector(at, std::move(inject));
  try {
    simulation.run(injector);
  } catch (const sim::WatchdogError& e) {
    return e;
  }
  ADD_FAILURE() << "the run went on";
  return sim::WatchdogError("", "", 0);
}

void expect_names(const std::string& what, const std::string& part) {
  EXPECT_NE(what.find(part), std::string::npos) << "'" << part << "' missing in: " << what;
}

// The last good state restores, lies before the failure, and is finite.
void expect_good_state(const sim::WatchdogError& e) {
  ASSERT_FALSE(e.last_good_state.empty());
  sim::Simulation good(settling_block());
  good.restore_state(e.last_good_state, "last good");
  EXPECT_EQ(good.time(), e.last_good_time);
  EXPECT_EQ(sim::find_bad_point(good.world()), "");
}

// The last good state as the step count of its stage.
long steps_of_last_good(const sim::WatchdogError& e) {
  sim::Simulation good(settling_block());
  good.restore_state(e.last_good_state, "last good");
  return good.stage_so_far().steps;
}

TEST(Watchdog, NonFiniteVelocityStopsTheRunAtOnce) {
  const long at = sim::kWatchdogSaveSteps + 10;
  const auto e = run_with_fault(at, [](sim::World& w) {
    w.points.vx[7] = std::numeric_limits<double>::quiet_NaN();
  });
  const std::string what = e.what();
  // By the end of the step the NaN has spread through the grid to the
  // neighbours of point 7; the message names the first and counts the rest.
  for (const char* part : {"stage 'settle'", "material 'elastic'", "non-finite",
                           "more points with a non-finite"})
    expect_names(what, part);
  expect_names(what, "after step " + std::to_string(at + 1));
  expect_good_state(e);
  EXPECT_EQ(steps_of_last_good(e), sim::kWatchdogSaveSteps);  // the last save
}

// The scans between two saves keep no state: a fault after the first scan
// loses the steps back to the stage's start.
TEST(Watchdog, ScansBetweenSavesKeepNoState) {
  const auto e = run_with_fault(sim::kWatchdogScanSteps + 10, [](sim::World& w) {
    w.points.vy[5] = std::numeric_limits<double>::infinity();
  });
  expect_names(e.what(), "non-finite");
  expect_good_state(e);
  EXPECT_EQ(steps_of_last_good(e), 0);
  EXPECT_EQ(e.last_good_time, 0.0);
}

TEST(Watchdog, OverCompressedPointStopsAtTheNextScan) {
  const auto e = run_with_fault(10, [](sim::World& w) {
    w.points.density[3] = 1.6 * w.material_specs[0].density;
  });
  const std::string what = e.what();
  for (const char* part : {"after step 50", "point 3", "compressed", "1.5 x 2000"})
    expect_names(what, part);
  expect_good_state(e);
  EXPECT_EQ(e.last_good_time, 0.0);  // the stage start: the scan at step 50 failed
}

TEST(Watchdog, PointLeavingTheGridNamesStageAndPoint) {
  const auto e = run_with_fault(5, [](sim::World& w) { w.points.x[11] = 50.0; });
  const std::string what = e.what();
  for (const char* part : {"stage 'settle'", "after step 5", "point 11", "left the grid"})
    expect_names(what, part);
  expect_good_state(e);
}

TEST(Watchdog, FixedTimeStepAboveTheBoundIsRefusedWithItsStage) {
  sim::Scenario s = settling_block();
  s.time_step.mode = sim::TimeStepSpec::Mode::Fixed;
  s.time_step.fixed_dt = 0.01;
  sim::Simulation simulation(s);
  sim::Observer quiet;
  try {
    simulation.run(quiet);
    ADD_FAILURE() << "a time step 5x above the bound was taken";
  } catch (const sim::WatchdogError& e) {
    expect_names(e.what(), "stage 'settle', after step 0");
    expect_names(e.what(), "exceeds the stable bound");
  }
}

}  // namespace
