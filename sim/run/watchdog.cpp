#include "sim/run/watchdog.hpp"

#include "sim/physics/point_order.hpp"

#include <cmath>
#include <sstream>

namespace sim {

bool step_sums_finite(const StepReport& r) {
  return std::isfinite(r.kinetic_energy) && std::isfinite(r.internal_work) &&
         std::isfinite(r.gravity_work) && std::isfinite(r.max_signal);
}

namespace {

std::string describe(const World& w, std::size_t p, const std::string& what) {
  const Particles& pts = w.points;
  std::ostringstream msg;
  msg.precision(6);
  msg << "point " << p << " (material '" << w.material_specs[pts.material[p]].name << "') at ("
      << pts.x[p] << ", " << pts.y[p] << ") m " << what;
  return msg.str();
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

std::string find_bad_point(const World& w) {
  const Particles& pts = w.points;
  const std::size_t n = pts.size();
  for (std::size_t p = 0; p < n; ++p) {
    const bool finite = std::isfinite(pts.x[p]) && std::isfinite(pts.y[p]) &&
                        std::isfinite(pts.vx[p]) && std::isfinite(pts.vy[p]) &&
                        std::isfinite(pts.sxx[p]) && std::isfinite(pts.syy[p]) &&
                        std::isfinite(pts.sxy[p]) && std::isfinite(pts.szz[p]) &&
                        std::isfinite(pts.density[p]);
    if (!finite) {
      // A value that turned non-finite in a step has spread through the grid
      // to its neighbours by the step's end: say how far.
      std::size_t others = 0;
      for (std::size_t q = p + 1; q < n; ++q)
        others += !(std::isfinite(pts.vx[q]) && std::isfinite(pts.vy[q]) &&
                    std::isfinite(pts.x[q]) && std::isfinite(pts.y[q]));
      std::ostringstream v;
      v << "has a non-finite value: velocity (" << pts.vx[p] << ", " << pts.vy[p]
        << ") m/s, stress (" << pts.sxx[p] << ", " << pts.syy[p] << ", " << pts.sxy[p] << ", "
        << pts.szz[p] << ") Pa, density " << pts.density[p] << " kg/m^3 (and " << others
        << " more points with a non-finite position or velocity)";
      return describe(w, p, v.str());
    }
    const double initial = w.material_specs[pts.material[p]].density;
    if (pts.density[p] > kMaxCompression * initial) {
      std::ostringstream v;
      v << "was compressed to density " << pts.density[p] << " kg/m^3, above the bound "
        << kMaxCompression << " x " << initial << " kg/m^3";
      return describe(w, p, v.str());
    }
  }
  return "";
}

}  // namespace sim
