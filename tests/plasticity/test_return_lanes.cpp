// The eight-point Mohr-Coulomb return the step runs (mohr_coulomb_return.hpp,
// T = Lane8) against the one-point return, bit for bit: the trials of
// test_return.cpp, eight at a time, each lane on another case's surface, so
// one vector holds several regions and surfaces at once. Also trials with
// equal in-plane stresses, where the principal direction is undefined, and
// trials a rounding away from the surface on either side.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "sim/physics/mohr_coulomb_return.hpp"
#include "trials.hpp"

namespace {

using namespace plasticity_test;
using sim::Lane8;
using sim::ReturnRegion;

struct Lanes {
  const sim::MohrCoulomb* surface[8];
  sim::Stress trial[8];
};

// Returns the eight trials with the one-point and the eight-point form and
// compares every stress component's bits and the elastic lanes.
int compare(const Lanes& in) {
  sim::StressOf<Lane8> s;
  for (int l = 0; l < 8; ++l) {
    s.xx[l] = in.trial[l].xx;
    s.yy[l] = in.trial[l].yy;
    s.xy[l] = in.trial[l].xy;
    s.zz[l] = in.trial[l].zz;
  }
  sim::mc_return::Regions<Lane8> regions;
  const auto elastic = sim::mc_return::return_in_place(sim::surface_lanes(in.surface), s, regions);
  int plastic = 0;
  for (int l = 0; l < 8; ++l) {
    sim::Stress one = in.trial[l];
    const ReturnRegion region = sim::mohr_coulomb_return(*in.surface[l], one);
    const sim::Stress lane{s.xx[l], s.yy[l], s.xy[l], s.zz[l]};
    EXPECT_EQ(std::memcmp(&one, &lane, sizeof one), 0)
        << "lane " << l << " region " << int(region) << ": (" << one.xx << ", " << one.yy << ", "
        << one.xy << ", " << one.zz << ") one at a time, (" << lane.xx << ", " << lane.yy << ", "
        << lane.xy << ", " << lane.zz << ") eight at a time";
    EXPECT_EQ(elastic[l] != 0, region == ReturnRegion::Elastic) << "lane " << l;
    plastic += region != ReturnRegion::Elastic;
  }
  return plastic;
}

TEST(MohrCoulombReturnLanes, EightAtATimeGiveTheBitsOfOneAtATime) {
  const std::vector<Case> cases = all_cases();
  std::vector<Model> models;
  for (const Case& c : cases) models.push_back(model_of(c));
  std::vector<std::vector<Trial>> trials;
  for (std::size_t ci = 0; ci < cases.size(); ++ci)
    trials.push_back(make_trials(models[ci], seed_of(static_cast<int>(ci))));
  long plastic = 0, total = 0;
  for (std::size_t ci = 0; ci < cases.size(); ++ci) {
    for (std::size_t n = 0; n + 8 <= trials[ci].size(); n += 8) {
      Lanes in;
      for (int l = 0; l < 8; ++l) {
        const std::size_t c = (ci + static_cast<std::size_t>(l) * 5) % cases.size();
        const Trial& t = trials[c][n + l];
        in.surface[l] = &models[c].mc;
        in.trial[l] = stress_of(t.s_b, t.zz_slot, t.theta);
      }
      plastic += compare(in);
      total += 8;
      if (HasFailure()) return;
    }
  }
  // The trials reach every region (test_return.cpp counts them); most yield.
  EXPECT_GT(plastic, total / 2);
}

TEST(MohrCoulombReturnLanes, EqualInPlaneStressesKeepTheirBits) {
  const Model cohesive = model_of(all_cases()[0]);
  Lanes in;
  for (int l = 0; l < 8; ++l) in.surface[l] = &cohesive.mc;
  const double a = cohesive.apex, R = 200e3;
  // Hydrostatic below and beyond the apex, equal in-plane values with
  // sigma_zz above, between and below, and a pure in-plane shear.
  const sim::Stress cases[8] = {{a - R, a - R, 0, a - R}, {a + R, a + R, 0, a + R},
                                {-R, -R, 0, R},           {-R, -R, 0, -3 * R},
                                {-3 * R, -3 * R, 0, -R},  {0, 0, R, 0},
                                {a + R, a + R, 0, a - R}, {-R, -R, 0, -R}};
  std::copy(cases, cases + 8, in.trial);
  EXPECT_GT(compare(in), 0);
}

// The eight-point form first tests f with radii from the processor's
// estimate of 1 / sqrt (radius_above) and, where every lane is inside, keeps
// the trials without taking square roots. Trials a step of the bisection
// apart across the surface, on the ray from a hydrostatic stress inside:
// eight just inside must stay as they are, and one just outside among them
// must still be returned, bit for bit as one at a time.
TEST(MohrCoulombReturnLanes, TrialsAtTheSurfaceKeepTheirBits) {
  const std::vector<Case> cases = all_cases();
  std::vector<const sim::MohrCoulomb*> surfaces;
  std::vector<sim::Stress> inside, outside;
  std::vector<Model> models;
  for (const Case& c : cases) models.push_back(model_of(c));
  for (std::size_t ci = 0; ci < cases.size(); ++ci) {
    const Model& md = models[ci];
    const double p = md.apex - 100e3;
    const sim::Stress from{p, p, 0, p};
    const auto at = [&](const sim::Stress& to, double t) {
      return sim::Stress{from.xx + t * (to.xx - from.xx), from.yy + t * (to.yy - from.yy),
                         from.xy + t * (to.xy - from.xy), from.zz + t * (to.zz - from.zz)};
    };
    const auto elastic = [&](sim::Stress s) {
      return sim::mohr_coulomb_return(md.mc, s) == ReturnRegion::Elastic;
    };
    const std::vector<Trial> trials = make_trials(md, seed_of(static_cast<int>(ci)));
    for (std::size_t n = 0; n < trials.size() && n < 200; ++n) {
      const sim::Stress to = stress_of(trials[n].s_b, trials[n].zz_slot, trials[n].theta);
      if (elastic(to)) continue;
      double lo = 0, hi = 1;  // elastic at lo, not at hi
      for (double mid = 0.5; mid > lo && mid < hi; mid = 0.5 * (lo + hi))
        (elastic(at(to, mid)) ? lo : hi) = mid;
      surfaces.push_back(&md.mc);
      inside.push_back(at(to, lo));
      outside.push_back(at(to, hi));
    }
  }
  ASSERT_GE(inside.size(), 64u);
  long returned = 0;
  for (std::size_t n = 0; n + 8 <= inside.size(); n += 8) {
    Lanes in;
    for (int l = 0; l < 8; ++l) {
      in.surface[l] = surfaces[n + l];
      in.trial[l] = inside[n + l];
    }
    EXPECT_EQ(compare(in), 0);
    const int l = static_cast<int>(n / 8 % 8);
    in.trial[l] = outside[n + l];
    returned += compare(in);
    if (HasFailure()) return;
  }
  EXPECT_EQ(returned, static_cast<long>(inside.size() / 8));
}

}  // namespace

// radius_above must bound the radius from above for every squared radius the
// step can meet, or a group with one lane just outside would be kept as it
// is: with AVX alone it goes through a float (mohr_coulomb_return.hpp), whose
// range ends far inside the doubles'. Radii r from 2^-600 to 2^600 (q = r^2
// below the floats' normal range, inside it, and past 2^120), with the
// in-plane shear alone (q = xy^2) and the normal difference alone.
TEST(MohrCoulombReturnLanes, RadiusEstimateBoundsTheRadius) {
#if !defined(__AVX__)
  GTEST_SKIP() << "no radius estimate in a build without AVX (mohr_coulomb_return.hpp)";
#else
  static_assert(sim::mc_return::kRadiusEstimate, "AVX builds estimate the radius");
  long checked = 0;
  for (int e = -600; e <= 600; ++e)
    for (double m : {1.0, 1.0 + 0x1p-52, 1.2345678901234567, 1.5, 1.9999999999999998}) {
      const double r = std::ldexp(m, e);
      sim::StressOf<Lane8> s{};
      for (int l = 0; l < 8; ++l) {
        const double scale = 1.0 + l * 0x1p-20;
        const bool shear = l % 2 == 0;
        s.xx[l] = shear ? 0.0 : r * scale;
        s.yy[l] = shear ? 0.0 : -r * scale;
        s.xy[l] = shear ? r * scale : 0.0;
      }
      const Lane8 above = sim::mc_return::radius_above(s);
      for (int l = 0; l < 8; ++l) {
        sim::StressOf<double> one{s.xx[l], s.yy[l], s.xy[l], 0.0};
        const double exact = sim::mc_return::circle_radius(one);
        ASSERT_GE(above[l], exact) << "r = " << r << ", lane " << l;
        ++checked;
      }
    }
  EXPECT_EQ(checked, 1201 * 5 * 8);
#endif
}
