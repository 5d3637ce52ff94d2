// Point-steps per second of the GIMP step on the scenes of issue 6, with 1 and
// 2 threads, and the cost per point-step as the scene grows. Prints figures;
// never fails on timing.
//
// Usage: throughput [STEPS]   (default 300 steps per scene and thread count)
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "sim/simulation.hpp"

namespace {

struct Scene {
  std::string label;
  sim::Scenario scenario;
};

sim::Scenario load(const std::string& name) {
  return sim::load_scenario(LANDSLIDE_SOURCE_DIR "/scenarios/" + name + ".json");
}

// The granular column of issue 6 (CB-Geo MPM's comparison case): a 0.2 m x
// 0.4 m Mohr-Coulomb column (phi = 30 deg, c = 0) against the left wall,
// 2x2 points per cell, 25,600 points, collapsing under full gravity.
sim::Scenario granular_column() {
  sim::Scenario s = load("elastic-column");
  s.name = "granular-column";
  // (0.2 / h) (0.4 / h) 4 points = 25,600 gives h = 0.2 / sqrt(3200) = 3.536 mm.
  s.cell_size = 0.2 / std::sqrt(3200.0);
  s.domain_min = {0, 0};
  s.domain_max = {1.0, 0.45};
  s.boundaries = {sim::BoundaryKind::Fixed, sim::BoundaryKind::Fixed, sim::BoundaryKind::Fixed,
                  sim::BoundaryKind::Free};
  sim::MaterialSpec m;
  m.name = "sand";
  m.model = sim::MaterialModel::MohrCoulomb;
  m.density = 2650;
  m.youngs_modulus = 0.84e6;
  m.poisson_ratio = 0.3;
  m.friction_angle = 30 * M_PI / 180;
  s.materials = {m};
  s.bodies[0].material = 0;
  s.bodies[0].polygon = {{0, 0}, {0.2, 0}, {0.2, 0.4}, {0, 0.4}};
  return s;
}

// Runs `steps` steps of the scene's slide (a dynamic stage under full gravity,
// no frames, no rest test) and returns point-steps per second.
double run(sim::Scenario s, int threads, int steps, std::size_t& points, double& dt) {
  sim::StageSpec stage;
  stage.type = sim::StageType::Dynamic;
  stage.name = "bench";
  s.stages = {stage};
  s.output.frame_interval = 0;
  s.output.vtk = "none";
  omp_set_num_threads(threads);
  sim::Simulation probe(s);
  points = probe.world().points.size();
  // About `steps` steps: the duration of that many steps at rest; the Courant
  // step shortens a little as the points speed up, and the steps taken count.
  double signal = 0;
  for (const auto& m : probe.world().materials) signal = std::max(signal, m.wave_speed);
  dt = s.time_step.courant * s.cell_size / signal;
  s.stages[0].duration = dt * steps;
  sim::Simulation simulation(s);
  sim::Observer quiet;
  const auto start = std::chrono::steady_clock::now();
  simulation.run(quiet);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return simulation.results().back().steps * static_cast<double>(points) / wall;
}

}  // namespace

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 300;
  std::vector<Scene> scenes = {{"elastic column (16 cells)", load("elastic-column")},
                               {"granular column, Mohr-Coulomb", granular_column()},
                               {"paper slope phi=20, n1648", load("paper-slope-phi20-n1648")},
                               {"paper slope phi=20, n8370", load("paper-slope-phi20")},
                               {"paper slope phi=20, n28724", load("paper-slope-phi20-n28724")},
                               {"paper slope phi=20, n67016", load("paper-slope-phi20-n67016")}};
  std::printf("about %d steps per run at the scene's Courant number, under full gravity, no frames\n",
              steps);
  std::printf("%-32s %8s %10s %14s %14s %16s\n", "scene", "points", "dt [s]",
              "1 thread Mpt/s", "2 thr. Mpt/s", "core-ns/pt-step");
  for (const Scene& scene : scenes) {
    std::size_t points = 0;
    double dt = 0;
    const double one = run(scene.scenario, 1, steps, points, dt);
    const double two = run(scene.scenario, 2, steps, points, dt);
    std::printf("%-32s %8zu %10.3e %14.2f %14.2f %12.1f\n", scene.label.c_str(), points, dt,
                one / 1e6, two / 1e6, 2e9 / two);
  }
  return 0;
}
