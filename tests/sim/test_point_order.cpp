// Points stored in cell order (sim/physics/point_order.hpp): a sort and a
// restore give back every per-point array bit for bit, and where the points
// are stored changes no result of the step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "sim/physics/material.hpp"
#include "sim/physics/point_order.hpp"
#include "sim/physics/step.hpp"
#include "sim/run/watchdog.hpp"
#include "sim/scene/seed.hpp"
#include "support.hpp"

namespace {

// The paper's slope (soil, house, walls) with its cohesion gone and full
// gravity from the first step, so that the soil flows and points change
// cells; APIC or the paper's transfers, with or without a friction angle of
// its own at every soil point (a random field's case).
struct Slope {
  sim::World world;
  sim::StepInput input;
};

Slope flowing_slope(sim::TransferScheme transfer, bool own_strength) {
  sim::Scenario s =
      sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/paper-slope-phi20-n1661.json");
  s.transfer = transfer;
  Slope slope{sim::make_world(s), {}};
  sim::World& w = slope.world;
  double signal = 0;
  for (std::size_t m = 0; m < w.materials.size(); ++m) {
    if (w.materials[m].plastic) {
      sim::apply_material_change(w.material_specs[m], "cohesion", 0.0);
      w.materials[m] = sim::make_material_constants(w.material_specs[m]);
      if (own_strength) {
        std::vector<double> angles(w.points.size());
        for (std::size_t p = 0; p < angles.size(); ++p)
          angles[p] = (15.0 + (p * 7 % 11)) * M_PI / 180;
        sim::set_point_strength(w, static_cast<int>(m), "friction_angle", angles);
      }
    }
    signal = std::max(signal, w.materials[m].wave_speed);
  }
  slope.input.dt = 0.4 * s.cell_size / signal;
  slope.input.gravity = s.gravity;
  return slope;
}

// Every double of every step's report, and the points' state at the end (in
// scene order).
struct Outcome {
  std::vector<double> sums;
  std::uint64_t state = 0;
};

// `steps` steps; with sort_every > 0 the points are sorted before every
// sort_every-th step and put back in scene order once midway, as the time
// loop and its watchdog do.
Outcome run(Slope slope, int steps, int sort_every) {
  Outcome out;
  sim::StepReport r;
  for (int k = 0; k < steps; ++k) {
    if (sort_every > 0 && k % sort_every == 0) sim::sort_points_by_cell(slope.world);
    if (sort_every > 0 && k == steps / 2) sim::restore_scene_order(slope.world);
    sim::step(slope.world, slope.input, r);
    for (double v : {r.internal_work, r.gravity_work, r.kinetic_energy, r.moving_kinetic_energy,
                     r.damping_loss, r.max_signal, r.wall_loss, r.wall_change_on_points,
                     r.friction_work, r.transfer_loss})
      out.sums.push_back(v);
  }
  sim::restore_scene_order(slope.world);
  out.state = simtest::state_hash(slope.world.points);
  return out;
}

void expect_same_outcome(sim::TransferScheme transfer, bool own_strength) {
  const Slope slope = flowing_slope(transfer, own_strength);
  const Outcome scene = run(slope, 160, 0), sorted = run(slope, 160, 3);
  EXPECT_EQ(scene.state, sorted.state) << "state hash in cell order: " << std::hex << sorted.state;
  ASSERT_EQ(scene.sums.size(), sorted.sums.size());
  for (std::size_t i = 0; i < scene.sums.size(); ++i)
    ASSERT_EQ(std::memcmp(&scene.sums[i], &sorted.sums[i], sizeof(double)), 0)
        << "step " << i / 10 << ", report value " << i % 10 << ": " << scene.sums[i]
        << " in scene order, " << sorted.sums[i] << " in cell order";
}

TEST(PointOrder, WhereThePointsAreStoredChangesNoResult) {
  expect_same_outcome(sim::TransferScheme::Flip, false);
}

TEST(PointOrder, NoResultChangesWithApicOrPointStrengths) {
  expect_same_outcome(sim::TransferScheme::Apic, false);
  expect_same_outcome(sim::TransferScheme::Flip, true);
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(PointOrder, SortAndRestoreGiveBackEveryArray) {
  Slope slope = flowing_slope(sim::TransferScheme::Apic, true);
  sim::World& w = slope.world;
  sim::StepReport r;
  for (int k = 0; k < 40; ++k) sim::step(w, slope.input, r);
  const sim::World before = w;
  sim::sort_points_by_cell(w);
  ASSERT_EQ(w.scene_index.size(), w.points.size());
  EXPECT_FALSE(same_bytes(w.points.x, before.points.x)) << "the sort moved no point";
  sim::restore_scene_order(w);
  EXPECT_TRUE(w.scene_index.empty());
  const sim::Particles &p = w.points, &q = before.points;
  for (auto m : {&sim::Particles::x, &sim::Particles::y, &sim::Particles::vx, &sim::Particles::vy,
                 &sim::Particles::mass, &sim::Particles::density, &sim::Particles::sxx,
                 &sim::Particles::syy, &sim::Particles::sxy, &sim::Particles::szz,
                 &sim::Particles::cxx, &sim::Particles::cxy, &sim::Particles::cyx,
                 &sim::Particles::cyy, &sim::Particles::x0, &sim::Particles::y0,
                 &sim::Particles::ref_x, &sim::Particles::ref_y})
    EXPECT_TRUE(same_bytes(p.*m, q.*m));
  EXPECT_TRUE(same_bytes(p.material, q.material));
  EXPECT_TRUE(same_bytes(p.yielded, q.yielded));
  EXPECT_TRUE(same_bytes(w.strength.cohesion, before.strength.cohesion));
  EXPECT_TRUE(same_bytes(w.strength.friction_angle, before.strength.friction_angle));
  std::vector<const std::vector<double>*> now, was;
  sim::for_each_surface_array(w.strength.surfaces, [&](const auto& v) { now.push_back(&v); });
  sim::for_each_surface_array(before.strength.surfaces, [&](const auto& v) { was.push_back(&v); });
  ASSERT_EQ(now.size(), 18u);
  for (std::size_t k = 0; k < now.size(); ++k)
    EXPECT_TRUE(same_bytes(*now[k], *was[k])) << "surface array " << k;
}

// The time loop sorts every kStepsPerSort steps, and only points that have
// left cell order: not again right after a sort, but after a restore.
TEST(PointOrder, SortsOnlyPointsThatHaveLeftCellOrder) {
  Slope slope = flowing_slope(sim::TransferScheme::Flip, false);
  sim::World& w = slope.world;
  sim::StepReport r;
  EXPECT_FALSE(sim::sort_due(w, 0)) << "before the first step there is no order to sort by";
  sim::step(w, slope.input, r);
  EXPECT_TRUE(sim::sort_due(w, sim::kStepsPerSort)) << "the seeding order is not the step's";
  EXPECT_FALSE(sim::sort_due(w, sim::kStepsPerSort + 1));
  // Seeded points sit on the edges of base-node cells (x_p - l_p on a grid
  // line), so the first step's settling moves half of them to the next
  // cell's order: sort once more after it.
  for (int k = 0; k < 2; ++k) {
    sim::sort_points_by_cell(w);
    sim::step(w, slope.input, r);
  }
  EXPECT_FALSE(sim::sort_due(w, 2 * sim::kStepsPerSort)) << "sorted a step ago";
  sim::restore_scene_order(w);
  EXPECT_TRUE(sim::sort_due(w, 2 * sim::kStepsPerSort)) << "back in scene order";
}

// The flowing slope after 20 steps, its points stored in cell order.
Slope slope_in_cell_order() {
  Slope slope = flowing_slope(sim::TransferScheme::Flip, false);
  sim::StepReport r;
  for (int k = 0; k < 20; ++k) sim::step(slope.world, slope.input, r);
  sim::sort_points_by_cell(slope.world);
  return slope;
}

// A point off the grid is named by its index in the scene, wherever it is stored.
TEST(PointOrder, APointOffTheGridIsNamedByItsSceneIndex) {
  Slope slope = slope_in_cell_order();
  sim::World& w = slope.world;
  sim::StepReport r;
  const int n = static_cast<int>(w.points.size());
  int scene = n / 2;  // the first from the middle on that the sort moved
  while (scene < n && sim::slot_of_scene_index(w, scene) == scene) ++scene;
  ASSERT_LT(scene, n) << "the sort moved no point";
  const int slot = sim::slot_of_scene_index(w, scene);
  ASSERT_EQ(sim::scene_index_of(w, slot), scene);
  w.points.x[slot] = w.grid.origin_x - 10 * w.grid.h;
  try {
    sim::step(w, slope.input, r);
    FAIL() << "no error for a point off the grid";
  } catch (const sim::SimulationError& e) {
    const std::string named = "point " + std::to_string(scene) + " (";
    EXPECT_EQ(std::string(e.what()).rfind(named, 0), 0u) << e.what();
  }
}


// The watchdog reads the points where they are stored (sim/run/watchdog.cpp):
// in cell order it names the same point, by scene index, with the same
// values and count of others, as in scene order.
TEST(PointOrder, TheWatchdogNamesTheSamePointInEitherOrder) {
  Slope slope = slope_in_cell_order();
  sim::World& w = slope.world;
  const int n = static_cast<int>(w.points.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Two bad points, the later one in the scene stored first: the scan must
  // not name the first it meets.
  int late = n - 1;
  while (late > 0 && sim::slot_of_scene_index(w, late) >= sim::slot_of_scene_index(w, n / 3)) --late;
  ASSERT_GT(late, n / 3) << "no later point stored before scene point " << n / 3;
  ASSERT_NE(late, n / 2);
  w.points.vy[sim::slot_of_scene_index(w, late)] = nan;
  w.points.sxy[sim::slot_of_scene_index(w, n / 3)] = nan;
  w.points.x[sim::slot_of_scene_index(w, n / 2)] = nan;  // one "more point" after it
  w.team.threads = 1;  // the scan runs on the last step's team (watchdog.cpp)
  const std::string sorted = sim::find_bad_point(w);
  w.team.threads = 3;  // an uneven split
  EXPECT_EQ(sim::find_bad_point(w), sorted);
  sim::restore_scene_order(w);
  const std::string in_scene_order = sim::find_bad_point(w);
  EXPECT_EQ(sorted, in_scene_order);
  const std::string named = "point " + std::to_string(n / 3) + " (";
  EXPECT_EQ(sorted.rfind(named, 0), 0u) << sorted;
  EXPECT_NE(sorted.find("(and 2 more points"), std::string::npos) << sorted;
}

}  // namespace

namespace {

// locate_points from bins fitted to the points' own window, as on a first
// step: the grid's window forgotten.
sim::World located_afresh(sim::World w) {
  w.grid.i_begin = w.grid.i_end = w.grid.j_begin = w.grid.j_end = 0;
  sim::locate_points(w);
  return w;
}

void expect_same_sort(const sim::World& from_last_step, const sim::World& afresh) {
  EXPECT_EQ(from_last_step.order, afresh.order);
  EXPECT_EQ(from_last_step.band_start, afresh.band_start);
  EXPECT_EQ(from_last_step.thread_bands, afresh.thread_bands);
  EXPECT_EQ(from_last_step.grid.i_begin, afresh.grid.i_begin);
  EXPECT_EQ(from_last_step.grid.j_end, afresh.grid.j_end);
}

}  // namespace

// The counting sort counts the points in the last step's bins (locate.cpp);
// it must sort them as bins fitted to this step's window do, and count again
// where a point has moved off the last step's bins.
TEST(PointOrder, BinsFromTheLastStepSortAsFreshBins) {
  Slope slope = flowing_slope(sim::TransferScheme::Flip, false);
  sim::World& w = slope.world;
  sim::StepReport r;
  for (int k = 0; k < 40; ++k) sim::step(w, slope.input, r);
  sim::sort_points_by_cell(w);
  const sim::World before = w;
  sim::locate_points(w);
  expect_same_sort(w, located_afresh(before));
  // One point three cells up the slope, off the last step's bins' margin.
  sim::World jumped = before;
  int p = 0;
  for (int q = 1; q < static_cast<int>(jumped.points.size()); ++q)
    if (jumped.points.y[q] > jumped.points.y[p]) p = q;
  jumped.points.y[p] += 3 * jumped.grid.h;
  const sim::World fresh = located_afresh(jumped);
  sim::locate_points(jumped);
  ASSERT_GT(fresh.grid.j_end, before.grid.j_end) << "the moved point did not leave the window";
  expect_same_sort(jumped, fresh);
}
