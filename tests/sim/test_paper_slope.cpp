// The paper's slope and house (method notes section 3) at the 1661-point
// resolution, for the four friction angles of the paper's Figure 12:
// stable under gravity before the trigger, and after the cohesion is removed
// the runout grows as the friction angle falls (paper Section 7.2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "sim/physics/mohr_coulomb.hpp"
#include "sim/run/simulation.hpp"

namespace {

// Checks the state at the end of the gravity stage, before the trigger.
class GravityCheck : public sim::Observer {
 public:
  void stage_ends(const sim::Simulation& s, const sim::StageSpec& stage,
                  const sim::StageResult& r) override {
    if (stage.type != sim::StageType::Gravity) return;
    const sim::World& w = s.world();
    max_f = -HUGE_VAL;
    for (std::size_t p = 0; p < w.points.size(); ++p) {
      const sim::MaterialConstants& m = w.materials[w.points.material[p]];
      if (!m.plastic) continue;
      const sim::Stress st{w.points.sxx[p], w.points.syy[p], w.points.sxy[p], w.points.szz[p]};
      max_f = std::max(max_f, sim::yield_function(m.mohr_coulomb, st) / m.mohr_coulomb.sigma_c);
      yielded += w.points.yielded[p];
    }
    kinetic_ratio = r.kinetic_energy / r.gravity_work;
  }
  double max_f = 0, kinetic_ratio = 0;
  int yielded = 0;
};

struct SlideResult {
  double runout, main_body, max_f, kinetic_ratio, slope, energy_error;
  int yielded;
};

SlideResult run_slope(int phi) {
  sim::Scenario s = sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/paper-slope-phi" +
                                       std::to_string(phi) + ".json");
  s.cell_size = 1.127;  // 1648 points in the paper's count (method notes section 3)
  s.output.frame_interval = 0;
  sim::Simulation simulation(s);
  GravityCheck check;
  simulation.run(check);
  const sim::StageResult& slide = simulation.results().back();
  return {slide.metrics.runout, slide.metrics.main_body_fraction, check.max_f,
          check.kinetic_ratio, slide.metrics.deposit_slope_deg, slide.energy.relative_error,
          check.yielded};
}

TEST(PaperSlope, StableUnderGravityThenRunoutGrowsAsFrictionFalls) {
  const int angles[] = {25, 20, 15, 10};
  SlideResult r[4];
  std::printf("%5s %12s %12s %14s %10s %10s %12s\n", "phi", "max f/sc", "KE/W grav",
              "runout [m]", "main body", "slope deg", "energy err");
  for (int k = 0; k < 4; ++k) {
    r[k] = run_slope(angles[k]);
    std::printf("%5d %12.4f %12.3e %14.2f %10.4f %10.2f %12.3f\n", angles[k], r[k].max_f,
                r[k].kinetic_ratio, r[k].runout, r[k].main_body, r[k].slope, r[k].energy_error);
    // Before the trigger: every soil point strictly inside the yield surface
    // (f < 0, scaled by the compressive strength) and the slope at rest.
    EXPECT_LT(r[k].max_f, 0.0) << "phi " << angles[k];
    EXPECT_EQ(r[k].yielded, 0) << "phi " << angles[k];
    EXPECT_LT(r[k].kinetic_ratio, 1e-4) << "phi " << angles[k];
  }
  for (int k = 1; k < 4; ++k)
    EXPECT_GT(r[k].runout, r[k - 1].runout) << "phi " << angles[k] << " vs " << angles[k - 1];
  // phi = 25 moves as one bulk: every soil point stays in the largest
  // 8-connected group of occupied cells.
  EXPECT_GE(r[0].main_body, 0.999);
}

}  // namespace
