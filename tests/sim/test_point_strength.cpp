// A random field of friction angle set by the trigger (issue 16) gives each
// soil point its own Mohr-Coulomb surface: the value of the field's lattice
// node it started on, used by the return of Eqs. (20)-(23); a later number
// replaces the field; a run with a field is the same on 1 and 2 threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>

#include "sim/physics/team.hpp"
#include "sim/physics/mohr_coulomb.hpp"
#include "sim/run/simulation.hpp"
#include "sim/scene/random_field.hpp"
#include "support.hpp"

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180;

sim::RandomFieldSpec friction_field() {
  sim::RandomFieldSpec f;
  f.distribution = sim::RandomFieldSpec::Distribution::TruncatedNormal;
  f.mean = 20 * kDeg;
  f.cov = 0.15;
  f.lower = 12 * kDeg;
  f.upper = 28 * kDeg;
  f.theta_x = 20;
  f.theta_y = 2;
  f.seed = 7;
  return f;
}

// The paper's slope at 1661 points whose trigger draws the friction angle
// from friction_field(); stages cut to `seconds`.
sim::Scenario field_slope(double seconds) {
  sim::Scenario s =
      sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/paper-slope-phi20-n1661.json");
  for (sim::StageSpec& stage : s.stages) {
    stage.duration = std::min(stage.duration, seconds);
    stage.rest.enabled = false;
  }
  s.output.frame_interval = 0;
  for (sim::MaterialChange& c : s.stages[1].changes)
    if (c.property == "friction_angle") {
      c.has_field = true;
      c.field = friction_field();
      c.value = c.field.mean;
    }
  return s;
}

// Materials are indexed in the order of their names: house 0, soil 1.
int soil_index(const sim::Scenario& s) {
  for (std::size_t m = 0; m < s.materials.size(); ++m)
    if (s.materials[m].name == "soil") return int(m);
  ADD_FAILURE() << "no soil";
  return -1;
}

// Stops the run once the trigger stage has ended.
struct AfterTrigger : sim::Observer {
  struct Stop {};
  void stage_ends(const sim::Simulation& s, const sim::StageSpec&,
                  const sim::StageResult&) override {
    if (s.stage_index() == 2) throw Stop{};
  }
};

TEST(PointStrength, EachSoilPointTakesTheFieldAtTheNodeItStartedOn) {
  const sim::Scenario s = field_slope(1.0);
  sim::Simulation sim(s);
  AfterTrigger stop;
  EXPECT_THROW(sim.run(stop), AfterTrigger::Stop);
  const sim::World& w = sim.world();
  ASSERT_TRUE(w.strength.active());
  // The field drawn directly: points are seeded on the lattice's nodes.
  const sim::FieldLattice l = sim::field_lattice(s);
  const sim::RandomFieldSpec f = friction_field();
  const std::vector<double> g =
      sim::GaussianFieldGenerator(l, {f.theta_x, f.theta_y}).standard_field(f.seed);
  const std::vector<double> phi =
      sim::to_truncated_normal(g, {f.mean, f.cov, f.lower, f.upper});
  double lo = 1e9, hi = -1e9;
  int soil = 0;
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    const sim::MohrCoulomb& mc = sim::point_mohr_coulomb(w, p);
    if (w.points.material[p] != soil_index(s)) {  // the house keeps no strength
      EXPECT_EQ(w.strength.friction_angle[p], 0.0);
      continue;
    }
    const int i = int(std::lround((w.points.x0[p] - l.x0) / l.dx));
    const int j = int(std::lround((w.points.y0[p] - l.y0) / l.dy));
    ASSERT_NEAR(w.points.x0[p], l.x0 + i * l.dx, 1e-9);
    EXPECT_EQ(mc.friction_angle, phi[i + l.nx * j]) << p;
    EXPECT_EQ(mc.cohesion, 0.0);  // the trigger's number, kept beside the field
    EXPECT_EQ(mc.dilation_angle, 10 * kDeg);
    lo = std::min(lo, mc.friction_angle);
    hi = std::max(hi, mc.friction_angle);
    ++soil;
  }
  EXPECT_GT(soil, 1000);
  EXPECT_GE(lo, f.lower);
  EXPECT_LE(hi, f.upper);
  EXPECT_GT(hi - lo, 8 * kDeg) << "a field with cov 0.15 spreads over most of [12, 28] deg";
}

TEST(PointStrength, YieldedPointsLieOnTheirOwnSurface) {
  const sim::Scenario s = field_slope(0.5);
  sim::Simulation sim(s);
  sim::Observer quiet;
  sim.run(quiet);
  const sim::World& w = sim.world();
  const int soil = soil_index(s);
  const sim::MohrCoulomb& material = w.materials[soil].mohr_coulomb;  // phi = the mean, 20 deg
  int yielded = 0, off_the_mean_surface = 0;
  for (std::size_t p = 0; p < w.points.size(); ++p) {
    if (w.points.material[p] != soil || !w.points.yielded[p]) continue;
    const sim::Stress st{w.points.sxx[p], w.points.syy[p], w.points.sxy[p], w.points.szz[p]};
    const double scale = std::abs(st.xx) + std::abs(st.yy) + std::abs(st.zz) + 1.0;
    EXPECT_NEAR(sim::yield_function(sim::point_mohr_coulomb(w, p), st), 0.0, 1e-9 * scale) << p;
    off_the_mean_surface += std::abs(sim::yield_function(material, st)) > 1e-3 * scale;
    ++yielded;
  }
  EXPECT_GT(yielded, 100);
  EXPECT_GT(off_the_mean_surface, yielded / 2) << "the return used the material's mean surface";
}

TEST(PointStrength, ANumberAfterTheFieldReplacesIt) {
  sim::Scenario s = field_slope(0.2);
  sim::StageSpec again = s.stages[1];
  again.name = "uniform";
  const int soil = soil_index(s);
  again.changes = {sim::MaterialChange{soil, "friction_angle", 25 * kDeg, false, {}}};
  s.stages.insert(s.stages.begin() + 2, again);
  sim::Simulation sim(s);
  sim::Observer quiet;
  sim.run(quiet);
  const sim::World& w = sim.world();
  for (std::size_t p = 0; p < w.points.size(); ++p)
    if (w.points.material[p] == soil) {
      ASSERT_EQ(sim::point_mohr_coulomb(w, p).friction_angle, 25 * kDeg) << p;
      ASSERT_EQ(sim::point_mohr_coulomb(w, p).sin_phi, w.materials[soil].mohr_coulomb.sin_phi);
    }
}

TEST(PointStrength, OneAndTwoThreadsGiveTheSameState) {
  const sim::Scenario s = field_slope(1.0);
  std::uint64_t hash[2] = {0, 0};
  for (int threads : {1, 2}) {
    sim::follow_free_cores(false);  // two threads even on a loaded machine
    omp_set_num_threads(threads);
    sim::Simulation sim(s);
    sim::Observer quiet;
    sim.run(quiet);
    hash[threads - 1] = simtest::state_hash(sim.world().points);
  }
  std::printf("state hash with a field: 1 thread %016llx, 2 threads %016llx\n",
              static_cast<unsigned long long>(hash[0]), static_cast<unsigned long long>(hash[1]));
  EXPECT_EQ(hash[0], hash[1]) << "new hash with 2 threads: " << std::hex << hash[1];
}

}  // namespace
