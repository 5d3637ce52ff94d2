// The diagnostics of a row or a stage's end (sim/run/diagnostics.hpp) run on
// the run's threads in fixed chunks of points (sim/run/point_chunks.hpp):
// the same bits at any thread count, and, for a scene of one chunk, the
// bits of the plain loop in point order that they replaced.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "sim/run/diagnostics.hpp"
#include "sim/run/point_chunks.hpp"
#include "sim/scene/seed.hpp"
#include "support.hpp"

namespace {

// A Mohr-Coulomb block of about `points` points, moved, loosened, stressed
// and set going by hand in a pattern that differs from point to point, so
// that no sum is a multiple of one term.
sim::World moved_block(double points) {
  const double h = std::sqrt(0.3 * 0.1 / (points / 4));  // 2 x 2 points per cell
  sim::Scenario s = simtest::block_scenario({0.0, 0.0}, {0.3, 0.1}, h, 2, {0, 0}, {1, 0.2});
  s.materials[0].model = sim::MaterialModel::MohrCoulomb;
  s.materials[0].friction_angle = 0.5;  // rad
  s.materials[0].critical_density = 0.95 * s.materials[0].density;
  sim::World w = sim::make_world(s);
  sim::Particles& p = w.points;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double t = 0.37 * double(i);
    p.x[i] += 0.2 * p.y0[i] * (1 + 0.1 * std::sin(t));
    p.y[i] -= 0.01 * std::cos(t) * p.y0[i];
    p.vx[i] = std::sin(1.3 * t);
    p.vy[i] = -std::cos(0.7 * t);
    p.density[i] *= 1 - 0.08 * std::fabs(std::sin(0.11 * t));
    p.sxx[i] = -1e3 * (1 + std::sin(t));
    p.syy[i] = -2e3 * (1 + std::cos(t));
    p.sxy[i] = 300 * std::sin(2.1 * t);
    p.szz[i] = -1.5e3;
    p.yielded[i] = i % 3 == 0;
  }
  return w;
}

// Every figure of a stage's end and of the energy balance, as one hash.
std::uint64_t measured_hash(const sim::World& w) {
  const sim::StageMetrics m = sim::measure_stage(w);
  double values[] = {m.max_soil_ux,        m.initial_toe,     m.toe,
                     m.runout,             m.main_body_fraction, m.packed_fraction,
                     m.disconnected_fraction, m.yielding_fraction, m.deposit_slope_deg,
                     m.materials.at(0).mean_ux, m.materials[0].mean_uy,
                     m.materials[0].max_displacement, sim::kinetic_energy(w),
                     sim::elastic_energy(w)};
  return simtest::fnv1a(1469598103934665603ull, values, sizeof values);
}

std::uint64_t hash_with_threads(const sim::World& w, int threads) {
  omp_set_num_threads(threads);
  const std::uint64_t h = measured_hash(w);
  std::printf("%zu points, %d threads: hash %016llx\n", w.points.size(), threads,
              static_cast<unsigned long long>(h));
  return h;
}

TEST(Diagnostics, ChunksGiveTheSameBitsAtAnyThreadCount) {
  const sim::World w = moved_block(2.5 * sim::kChunkPoints);
  ASSERT_EQ(sim::point_chunks(w.points.size()), 3u);
  const std::uint64_t one = hash_with_threads(w, 1);
  for (const int threads : {2, 3}) {
    const std::uint64_t many = hash_with_threads(w, threads);
    EXPECT_EQ(one, many) << "new hash with " << threads << " threads: " << std::hex << many;
  }
  omp_set_num_threads(1);
}

// Sums of the plain loop in point order, the one-chunk case's reference.
struct PlainSums {
  double kinetic = 0, sum_ux = 0;
};
PlainSums plain_sums(const sim::Particles& p) {
  PlainSums s;
  for (std::size_t i = 0; i < p.size(); ++i) {
    s.kinetic += 0.5 * p.mass[i] * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
    s.sum_ux += p.x[i] - p.x0[i];
  }
  return s;
}

TEST(Diagnostics, OneChunkSumsAsThePlainLoopAndMoreChunksCloseToIt) {
  for (const double points : {0.9 * sim::kChunkPoints, 2.5 * sim::kChunkPoints}) {
    const sim::World w = moved_block(points);
    const PlainSums plain = plain_sums(w.points);
    omp_set_num_threads(2);
    const double kinetic = sim::kinetic_energy(w);
    const double mean_ux = sim::measure_motion(w).materials.at(0).mean_ux;
    const double plain_mean = plain.sum_ux / double(w.points.size());
    if (sim::point_chunks(w.points.size()) == 1) {
      EXPECT_EQ(kinetic, plain.kinetic) << w.points.size() << " points";
      EXPECT_EQ(mean_ux, plain_mean) << w.points.size() << " points";
    } else {
      EXPECT_NEAR(kinetic, plain.kinetic, 1e-12 * plain.kinetic) << w.points.size() << " points";
      EXPECT_NEAR(mean_ux, plain_mean, 1e-12 * std::fabs(plain_mean));
    }
  }
  omp_set_num_threads(1);
}

}  // namespace
