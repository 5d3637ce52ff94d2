#include "sim/run/watchdog.hpp"

#include "sim/physics/point_order.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sim {

bool step_sums_finite(const StepReport& r) {
  return std::isfinite(r.kinetic_energy) && std::isfinite(r.internal_work) &&
         std::isfinite(r.gravity_work) && std::isfinite(r.max_signal);
}

namespace {

// `slot`: where the point is stored; `scene`: its index in the scene, the
// name users see (sim/physics/point_order.hpp).
std::string describe(const World& w, std::size_t slot, int scene, const std::string& what) {
  const Particles& pts = w.points;
  std::ostringstream msg;
  msg.precision(6);
  msg << "point " << scene << " (material '" << w.material_specs[pts.material[slot]].name
      << "') at (" << pts.x[slot] << ", " << pts.y[slot] << ") m " << what;
  return msg.str();
}

bool finite_motion(const Particles& pts, std::size_t p) {
  return std::isfinite(pts.vx[p]) && std::isfinite(pts.vy[p]) && std::isfinite(pts.x[p]) &&
         std::isfinite(pts.y[p]);
}

bool finite_state(const Particles& pts, std::size_t p) {
  return finite_motion(pts, p) && std::isfinite(pts.sxx[p]) && std::isfinite(pts.syy[p]) &&
         std::isfinite(pts.sxy[p]) && std::isfinite(pts.szz[p]) && std::isfinite(pts.density[p]);
}

double initial_density(const World& w, std::size_t p) {
  return w.material_specs[w.points.material[p]].density;
}

bool over_compressed(const World& w, std::size_t p) {
  return w.points.density[p] > kMaxCompression * initial_density(w, p);
}

std::string wall_kind(const Wall& wall) {
  switch (wall.kind) {
    case BoundaryKind::Fixed: return "\"fixed\"";
    case BoundaryKind::Roller: return "\"roller\"";
    case BoundaryKind::Friction: {
      std::ostringstream mu;
      mu << "{\"friction\": " << wall.friction << "}";
      return mu.str();
    }
    case BoundaryKind::Free: break;
  }
  return "\"free\"";
}

}  // namespace

std::string left_grid_advice(const World& w, const Scenario& s) {
  if (w.bad_point >= static_cast<int>(w.points.size())) return "";
  const std::size_t p = static_cast<std::size_t>(slot_of_scene_index(w, w.bad_point));
  const double x = w.points.x[p], y = w.points.y[p];
  if (!std::isfinite(x) || !std::isfinite(y)) return "";
  struct Side {
    bool passed;
    const char* name;
    const Wall& wall;
    const char* axis;
    double line;
    const char* widen;
  };
  const Side sides[] = {
      {x < s.domain_min[0], "left", s.boundaries.left, "x", s.domain_min[0], "domain.min[0]"},
      {x > s.domain_max[0], "right", s.boundaries.right, "x", s.domain_max[0], "domain.max[0]"},
      {y < s.domain_min[1], "bottom", s.boundaries.bottom, "y", s.domain_min[1], "domain.min[1]"},
      {y > s.domain_max[1], "top", s.boundaries.top, "y", s.domain_max[1], "domain.max[1]"}};
  for (const Side& side : sides) {
    if (!side.passed) continue;
    std::ostringstream msg;
    msg << "; it passed the " << side.name << " wall (" << side.axis << " = " << side.line
        << " m), which is " << wall_kind(side.wall);
    if (side.wall.kind == BoundaryKind::Free)
      msg << ": material that leaves the domain past a free wall stops the run where the grid "
          << "ends, grid.padding_cells = " << s.padding_cells
          << " cells beyond it. Make boundaries." << side.name
          << " \"roller\", \"fixed\" or {\"friction\": mu} to hold it, or move "
          << side.widen << " far enough out for the material to come to rest inside";
    return msg.str();
  }
  return "";
}

// The points are read where they are stored, which may be cell order
// (point_order.hpp): the bad point named is the first by scene index, and
// "more points" are those after it in the scene. The scan runs on the last
// step's team, between two steps (see SceneOrderArrays in
// simulation_state.cpp): a minimum, the same whatever the number of threads.
std::string find_bad_point(const World& w) {
  const Particles& pts = w.points;
  const std::size_t n = pts.size();
  const long count = static_cast<long>(n);
  // Each thread's least scene index of a bad point in its slots. An
  // OpenMP min reduction here broke the link: ld's LLVM 14 plugin refused
  // the object ("Expected at most one ThinLTO module per bitcode file").
  const int threads = std::max(1, w.team.threads);
  std::vector<int> least(static_cast<std::size_t>(threads), static_cast<int>(n));
#pragma omp parallel for num_threads(threads) schedule(static)
  for (long s = 0; s < count; ++s)
    if (!finite_state(pts, s) || over_compressed(w, s)) {
      int& mine = least[static_cast<std::size_t>(omp_get_thread_num())];
      mine = std::min(mine, scene_index_of(w, static_cast<int>(s)));
    }
  const int first = *std::min_element(least.begin(), least.end());
  if (first == static_cast<int>(n)) return "";
  const std::size_t slot = static_cast<std::size_t>(slot_of_scene_index(w, first));
  if (!finite_state(pts, slot)) {
    // A value that turned non-finite in a step has spread through the grid
    // to its neighbours by the step's end: say how far.
    std::size_t others = 0;
    for (std::size_t s = 0; s < n; ++s)
      others += scene_index_of(w, static_cast<int>(s)) > first && !finite_motion(pts, s);
    std::ostringstream v;
    v << "has a non-finite value: velocity (" << pts.vx[slot] << ", " << pts.vy[slot]
      << ") m/s, stress (" << pts.sxx[slot] << ", " << pts.syy[slot] << ", " << pts.sxy[slot]
      << ", " << pts.szz[slot] << ") Pa, density " << pts.density[slot] << " kg/m^3 (and "
      << others << " more points with a non-finite position or velocity)";
    return describe(w, slot, first, v.str());
  }
  const double initial = initial_density(w, slot);
  std::ostringstream v;
  v << "was compressed to density " << pts.density[slot] << " kg/m^3, above the bound "
    << kMaxCompression << " x " << initial << " kg/m^3";
  return describe(w, slot, first, v.str());
}

}  // namespace sim
