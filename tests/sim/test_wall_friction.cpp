// Coulomb friction walls (sim/physics/wall_friction.hpp) against the block on an
// inclined plane: gravity tilted by an angle t to a friction floor with
// coefficient mu. A rigid block slides with a = g (sin t - mu cos t) when
// tan t > mu and stays put when tan t <= mu; friction then does
// mu m g cos t per metre slid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim/run/simulation.hpp"
#include "support.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.81;
constexpr double kDuration = 1.0;  // s of sliding

struct Slide {
  double velocity = 0;       // gained by the centre of mass along the floor in the slide, m/s
  double distance = 0;       // moved by the centre of mass along the floor in the slide, m
  double lift = 0;           // and normal to it, m
  double mass = 0;           // kg/m
  sim::EnergyBalance energy; // of the slide
};

// The centre of mass of the points: position along and normal to the floor
// from the initial one, and velocity along it.
struct Centre {
  double x = 0, y = 0, vx = 0, mass = 0;
};

Centre centre(const sim::Particles& p) {
  Centre c;
  for (std::size_t i = 0; i < p.size(); ++i) {
    c.mass += p.mass[i];
    c.x += p.mass[i] * (p.x[i] - p.x0[i]);
    c.y += p.mass[i] * (p.y[i] - p.y0[i]);
    c.vx += p.mass[i] * p.vx[i];
  }
  c.x /= c.mass;
  c.y /= c.mass;
  c.vx /= c.mass;
  return c;
}

class AtSlideStart : public sim::Observer {
 public:
  void stage_begins(const sim::Simulation& s, const sim::StageSpec& stage) override {
    if (stage.type == sim::StageType::Dynamic) start = centre(s.world().points);
  }
  Centre start;
};

// A 2 m x 0.25 m elastic plate on a floor of friction mu, under gravity
// tilted by t degrees: gravity ramped in over 0.1 s (a gravity stage without
// damping, so the plate is loaded without a shock), then kDuration s more.
Slide slide(double t_deg, double mu, sim::TransferScheme transfer = sim::TransferScheme::Flip) {
  sim::Scenario s = simtest::block_scenario({1.0, 0.0}, {3.0, 0.25}, 0.0625, 2, {0, 0}, {14, 1});
  s.transfer = transfer;
  s.boundaries.bottom = {sim::BoundaryKind::Friction, mu};
  const double t = t_deg * kPi / 180;
  s.gravity = {kG * std::sin(t), -kG * std::cos(t)};
  sim::StageSpec ramp;
  ramp.name = "ramp";
  ramp.type = sim::StageType::Gravity;
  ramp.duration = 0.1;
  ramp.ramp_fraction = 1.0;
  sim::StageSpec stage;
  stage.name = "slide";
  stage.type = sim::StageType::Dynamic;
  stage.duration = kDuration;
  s.stages = {ramp, stage};
  sim::Simulation simulation(s);
  AtSlideStart observer;
  simulation.run(observer);
  const Centre end = centre(simulation.world().points);
  Slide r;
  r.mass = end.mass;
  r.velocity = end.vx - observer.start.vx;
  r.distance = end.x - observer.start.x;
  r.lift = end.y - observer.start.y;
  r.energy = simulation.results().back().energy;
  return r;
}

// Where tan t <= mu: less than 0.5 % of the free slide, which would have
// taken it g sin t T^2 / 2 (0.6 m at 15 deg), and almost no speed: what the
// noise of the point velocities (Eq. 30) makes the stuck nodes slip (0.3 to
// 3.3 mm).
void expect_stays_put(const Slide& r, double t_deg, double mu) {
  const double t = t_deg * kPi / 180;
  const double free = 0.5 * kG * std::sin(t) * kDuration * kDuration;
  EXPECT_LT(std::fabs(r.distance), 5e-3 * free) << "t = " << t_deg << ", mu = " << mu;
  EXPECT_LT(std::fabs(r.velocity), 1e-3 * kG * std::sin(t) * kDuration) << "t = " << t_deg << ", mu = " << mu;
}

TEST(WallFriction, BlockSlidesAtGTimesSinMinusMuCos) {
  const struct {
    double t_deg, mu;
  } cases[] = {{30, 0.3}, {45, 0.5}, {20, 0.1}, {40, 0.2}, {25, 0.35}, {35, 0.0}};
  std::printf("%6s %5s %10s %10s %8s %12s %10s %10s %12s %8s %8s\n", "t deg", "mu", "a [m/s2]",
              "exact", "error", "friction J", "impacts J", "transfer", "mu N d [J]", "balance",
              "lift mm");
  for (const auto& c : cases) {
    const Slide r = slide(c.t_deg, c.mu);
    const double t = c.t_deg * kPi / 180;
    const double exact = kG * (std::sin(t) - c.mu * std::cos(t));
    const double a = r.velocity / kDuration;
    const double expected_friction = c.mu * r.mass * kG * std::cos(t) * r.distance;
    const sim::EnergyBalance& e = r.energy;
    std::printf("%6.1f %5.2f %10.5f %10.5f %7.3f%% %12.1f %10.1f %10.1f %12.1f %7.3f%% %8.2f\n",
                c.t_deg, c.mu, a, exact, 100 * (a - exact) / exact, e.friction_work, e.wall_loss,
                e.transfer_loss, expected_friction, 100 * e.relative_error, 1000 * r.lift);
    EXPECT_NEAR(a, exact, 0.005 * exact) << "t = " << c.t_deg << " deg, mu = " << c.mu;
    // What the floor takes is mu N d: friction's own term, the impacts of
    // the noisy normal velocity and the transfer of the walls' change
    // (sim/physics/wall_friction.hpp); friction alone is 83 to 100 % of it.
    const double taken = e.friction_work + e.wall_loss + e.transfer_loss;
    EXPECT_NEAR(taken, expected_friction, 0.1 * expected_friction + 1e-3);
    EXPECT_GE(e.friction_work, 0.8 * expected_friction);
    EXPECT_LT(std::fabs(e.relative_error), 0.02);
    // It stays on the floor: the centre rises by at most 2 % of the 0.25 m
    // thickness (up to 4 mm, growing with mu, is measured).
    EXPECT_LT(std::fabs(r.lift), 0.005) << "the block left the floor";
  }
}

TEST(WallFriction, BlockStaysPutWhenTanTIsAtMostMu) {
  const struct {
    double t_deg, mu;
  } cases[] = {{15, 0.3}, {25, 0.5}, {10, 1.0}, {21.4052, 0.4}};  // last: tan t = 0.98 mu
  for (const auto& c : cases) {
    const Slide r = slide(c.t_deg, c.mu);
    std::printf("t = %.2f deg, mu = %.2f: moved %.3e m, speed %.3e m/s\n", c.t_deg, c.mu,
                r.distance, r.velocity);
    expect_stays_put(r, c.t_deg, c.mu);
  }
}

// The same plate with the affine transfer (sim/physics/apic.hpp): its P2G
// once left the walls' gaps unset, so no node was ever in contact and a
// block fell through a friction floor (issue 17, fifteenth pass).
TEST(WallFriction, ApicBlockSlidesAtGTimesSinMinusMuCosAndStaysPutBelowMu) {
  const struct {
    double t_deg, mu;
  } cases[] = {{30, 0.3}, {40, 0.2}, {35, 0.0}, {15, 0.3}, {25, 0.5}};
  for (const auto& c : cases) {
    const Slide r = slide(c.t_deg, c.mu, sim::TransferScheme::Apic);
    const double t = c.t_deg * kPi / 180;
    const double exact = kG * (std::sin(t) - c.mu * std::cos(t));
    const double a = r.velocity / kDuration;
    std::printf("APIC t = %.1f deg, mu = %.2f: a = %.5f m/s2 (exact %.5f), moved %.4f m, lift %.2f mm",
                c.t_deg, c.mu, a, std::max(0.0, exact), r.distance, 1000 * r.lift);
    // The FLIP tests' bounds above. The energy balance is printed, not held
    // to FLIP's 2 %: -2.34 % at 30 deg, mu 0.3, where FLIP's is -0.59 %.
    if (exact > 0) {
      std::printf(", balance %.3f %%\n", 100 * r.energy.relative_error);
      EXPECT_NEAR(a, exact, 0.005 * exact) << "t = " << c.t_deg << " deg, mu = " << c.mu;
    } else {
      std::printf("\n");
      expect_stays_put(r, c.t_deg, c.mu);
    }
    EXPECT_LT(std::fabs(r.lift), 0.005) << "the block left the floor";
  }
}

}  // namespace
