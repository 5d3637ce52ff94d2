// Point states as VTK XML UnstructuredGrid (.vtu) files that ParaView opens,
// and a .pvd collection that lists them with their times. Values are written
// with 17 significant digits so a re-read state is the same state.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sim/physics/world.hpp"

namespace sim {

// Writes the points of `world` at simulated time `time` (atomically).
// Point data: displacement (from the initial position), velocity, stress
// (xx, yy, xy, zz), density, volume, material, yielded; and where a random
// field set the strength point by point (sim/physics/point_strength.hpp),
// cohesion [Pa] and friction_angle [rad].
void write_vtu(const std::string& path, const World& world, double time);

// Writes a ParaView collection of (time, relative file name) pairs.
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& files);

// What `landslide render` needs back from a .vtu file.
struct PointState {
  double time = 0;
  std::vector<double> x, y, ux, uy, vx, vy, sxx, syy, sxy, szz, density, volume;
  std::vector<int> material, yielded;
  std::vector<double> cohesion, friction_angle;  // empty: each material's own
};

// Reads a file written by write_vtu; throws std::runtime_error naming the
// file and what is wrong.
PointState read_vtu(const std::string& path);

}  // namespace sim
