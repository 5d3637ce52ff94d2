// A run stopped at any step and continued from its saved state ends in
// exactly the state of a run that never stopped, with the same frames at
// the same times; a state is refused by a scenario it does not belong to.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstdint>
#include <string>
#include <vector>

#include "sim/io/binary_io.hpp"
#include "sim/physics/team.hpp"
#include "sim/run/simulation.hpp"
#include "support.hpp"

namespace {

using simtest::state_hash;

// The paper's slope at 1661 points, cut short: 1 s of gravity, the trigger,
// 1 s of slide, with frames every 0.25 s of the slide.
sim::Scenario short_slope() {
  sim::Scenario s = sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/paper-slope-phi20-n1661.json");
  for (sim::StageSpec& stage : s.stages) {
    stage.duration = std::min(stage.duration, 1.0);
    stage.rest.enabled = false;
  }
  s.output.frame_interval = 0.25;
  return s;
}

struct Stopped {};

// Records frames and results; saves the state and stops once the run has
// passed `stop_at` seconds (or at the end of stage `stop_after_stage`).
class Recorder : public sim::Observer {
 public:
  double stop_at = 1e9;
  int stop_after_stage = -1;
  std::string saved;
  std::vector<std::pair<int, double>> frames;  // number, time

  void frame(const sim::Simulation& s, const sim::StageSpec&, int n) override {
    frames.emplace_back(n, s.time());
  }
  void progress(const sim::Simulation& s, const sim::StageSpec&, long) override {
    if (s.time() >= stop_at) stop(s);
  }
  void stage_ends(const sim::Simulation& s, const sim::StageSpec&,
                  const sim::StageResult&) override {
    if (int(s.stage_index()) - 1 == stop_after_stage) stop(s);
  }

 private:
  void stop(const sim::Simulation& s) {
    saved = s.save_state();
    throw Stopped{};
  }
};

struct Outcome {
  std::uint64_t hash = 0;
  std::vector<sim::StageResult> results;
  std::vector<std::pair<int, double>> frames;
};

Outcome run_through(const sim::Scenario& s) {
  sim::Simulation sim(s);
  Recorder r;
  sim.run(r);
  return {state_hash(sim.world().points), sim.results(), r.frames};
}

// Runs until the recorder stops it, then continues in a fresh Simulation.
Outcome run_stopped(const sim::Scenario& s, Recorder stopper) {
  {
    sim::Simulation first(s);
    EXPECT_THROW(first.run(stopper), Stopped);
  }
  sim::Simulation second(s);
  second.restore_state(stopper.saved, "saved state");
  Recorder rest;
  second.run(rest);
  Outcome o{state_hash(second.world().points), second.results(), stopper.frames};
  o.frames.insert(o.frames.end(), rest.frames.begin(), rest.frames.end());
  return o;
}

void expect_same(const Outcome& a, const Outcome& b) {
  EXPECT_EQ(a.hash, b.hash) << std::hex << "uninterrupted " << a.hash << ", resumed " << b.hash;
  ASSERT_EQ(a.results.size(), b.results.size());
  for (std::size_t k = 0; k < a.results.size(); ++k) {
    EXPECT_EQ(a.results[k].steps, b.results[k].steps) << a.results[k].name;
    EXPECT_EQ(a.results[k].gravity_work, b.results[k].gravity_work) << a.results[k].name;
    EXPECT_EQ(a.results[k].energy.internal_work, b.results[k].energy.internal_work);
    EXPECT_EQ(a.results[k].metrics.runout, b.results[k].metrics.runout);
  }
  EXPECT_EQ(a.frames, b.frames);
}

TEST(Resume, MidStageGivesTheSameFinalState) {
  const sim::Scenario s = short_slope();
  const Outcome whole = run_through(s);
  ASSERT_GE(whole.frames.size(), 5u);
  for (double stop_at : {0.37, 1.61}) {  // in the gravity stage, in the slide between frames
    SCOPED_TRACE(stop_at);
    Recorder stopper;
    stopper.stop_at = stop_at;
    expect_same(whole, run_stopped(s, stopper));
  }
}

TEST(Resume, AtAStageEndGivesTheSameFinalState) {
  const sim::Scenario s = short_slope();
  Recorder stopper;
  stopper.stop_after_stage = 0;  // the gravity stage
  expect_same(run_through(s), run_stopped(s, stopper));
}

TEST(Resume, GravityStateServesAScenarioThatDiffersOnlyAfterIt) {
  const sim::Scenario s = short_slope();
  sim::Scenario other = s;  // the trigger also lowers the friction angle
  ASSERT_EQ(other.stages[1].type, sim::StageType::MaterialChange);
  sim::MaterialChange friction = other.stages[1].changes.front();
  friction.property = "friction_angle";
  friction.value = 0.2;
  other.stages[1].changes.push_back(friction);
  EXPECT_EQ(sim::stage_prefix_key(s, 1), sim::stage_prefix_key(other, 1));
  EXPECT_NE(sim::stage_prefix_key(s, 2), sim::stage_prefix_key(other, 2));

  Recorder at_gravity_end;
  at_gravity_end.stop_after_stage = 0;
  expect_same(run_through(other), run_stopped(other, at_gravity_end));

  sim::Simulation a(s);
  EXPECT_THROW(a.run(at_gravity_end), Stopped);
  sim::Simulation b(other);
  EXPECT_NO_THROW(b.restore_state(at_gravity_end.saved, "gravity state"));

  Recorder mid_slide;
  mid_slide.stop_at = 1.5;
  sim::Simulation c(s);
  EXPECT_THROW(c.run(mid_slide), Stopped);
  sim::Simulation d(other);
  try {
    d.restore_state(mid_slide.saved, "mid-slide state");
    ADD_FAILURE() << "a state of another trigger was accepted";
  } catch (const sim::StateError& e) {
    EXPECT_NE(std::string(e.what()).find("another scenario"), std::string::npos) << e.what();
  }
}

TEST(Resume, TruncatedOrForeignBytesAreRefused) {
  const sim::Scenario s = short_slope();
  Recorder stopper;
  stopper.stop_at = 0.3;
  sim::Simulation a(s);
  EXPECT_THROW(a.run(stopper), Stopped);
  const std::string& good = stopper.saved;
  for (const std::string& bad :
       {good.substr(0, good.size() / 2), good.substr(0, 7), std::string("not a state"),
        good + "x"}) {
    sim::Simulation b(s);
    EXPECT_THROW(b.restore_state(bad, "bad.state"), sim::StateError);
  }
}

}  // namespace

namespace {

// The trigger of short_slope() draws the friction angle from a random field.
sim::Scenario short_slope_with_field(std::uint64_t seed) {
  sim::Scenario s = short_slope();
  for (sim::MaterialChange& c : s.stages[1].changes)
    if (c.property == "friction_angle") {
      c.has_field = true;
      c.field.distribution = sim::RandomFieldSpec::Distribution::TruncatedNormal;
      c.field.mean = c.value;
      c.field.cov = 0.2;
      c.field.lower = 0.5 * c.value;
      c.field.upper = 1.5 * c.value;
      c.field.theta_x = 10;
      c.field.theta_y = 2;
      c.field.seed = seed;
    }
  return s;
}

TEST(Resume, MidSlideWithARandomFieldGivesTheSameFinalState) {
  const sim::Scenario s = short_slope_with_field(11);
  Recorder stopper;
  stopper.stop_at = 1.61;  // the per-point strength travels in the state
  expect_same(run_through(s), run_stopped(s, stopper));
  // Another seed is another scene after the trigger, the same one before it.
  const sim::Scenario other = short_slope_with_field(12);
  EXPECT_EQ(sim::stage_prefix_key(s, 1), sim::stage_prefix_key(other, 1));
  EXPECT_NE(sim::stage_prefix_key(s, 2), sim::stage_prefix_key(other, 2));
}

// The last step's team gathers the point arrays into a saved state
// (SceneOrderArrays, simulation_state.cpp): one thread and three, an uneven
// split, save the same bytes of them. The states differ only in the stages'
// wall times, which come before the points.
TEST(Resume, ThePointsAreSavedTheSameOnAnyTeam) {
  const sim::Scenario s = short_slope_with_field(11);  // with the strength arrays
  std::vector<std::string> saved;
  std::size_t points = 0;
  for (int threads : {1, 3}) {
    sim::follow_free_cores(false);
    omp_set_num_threads(threads);
    Recorder stopper;
    stopper.stop_at = 1.61;
    sim::Simulation sim(s);
    EXPECT_THROW(sim.run(stopper), Stopped);
    saved.push_back(stopper.saved);
    points = sim.world().points.size();
  }
  // 14 arrays of doubles, the material and yield bytes, the two strengths.
  const std::size_t tail = points * (16 * sizeof(double) + 2);
  ASSERT_EQ(saved[0].size(), saved[1].size());
  ASSERT_GT(saved[0].size(), tail);
  EXPECT_TRUE(saved[0].compare(saved[0].size() - tail, tail, saved[1], saved[1].size() - tail,
                               tail) == 0)
      << "the point arrays saved on 3 threads differ from those on 1";
}

}  // namespace
