#include "sim/run/watchdog.hpp"

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

}  // namespace

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
