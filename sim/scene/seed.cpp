#include "sim/scene/seed.hpp"

#include <cmath>
#include <sstream>

#include "sim/scene/scenario_geometry.hpp"

namespace sim {

World make_world(const Scenario& s) {
  World w;
  w.grid = make_grid(GridSpec{s.domain_min, s.domain_max, s.cell_size, s.padding_cells,
                              s.boundaries});
  w.material_specs = s.materials;
  for (const MaterialSpec& m : s.materials) w.materials.push_back(make_material_constants(m));

  // Sub-cell centres on the lattice anchored at the domain's lower-left
  // corner; a centre belongs to the first body that contains it, so the
  // characteristic functions stay a partition of unity (Eq. 6).
  const double spacing = s.cell_size / s.points_per_cell;
  w.gimp = GimpShape(w.grid.h, 0.5 * spacing);
  const long cols = std::lround(std::ceil((s.domain_max[0] - s.domain_min[0]) / spacing));
  const long rows = std::lround(std::ceil((s.domain_max[1] - s.domain_min[1]) / spacing));
  const double volume = spacing * spacing;  // per unit thickness (plane strain)
  Particles& pts = w.points;
  std::vector<std::size_t> seeded(s.bodies.size(), 0);
  for (long r = 0; r < rows; ++r) {
    for (long c = 0; c < cols; ++c) {
      const Vec2 centre{s.domain_min[0] + (c + 0.5) * spacing,
                        s.domain_min[1] + (r + 0.5) * spacing};
      for (std::size_t b = 0; b < s.bodies.size(); ++b) {
        const BodySpec& body = s.bodies[b];
        if (!point_in_polygon(body.polygon, centre)) continue;
        ++seeded[b];
        const MaterialSpec& m = s.materials[body.material];
        pts.x.push_back(centre[0]);
        pts.y.push_back(centre[1]);
        pts.mass.push_back(m.density * volume);  // Eq. (5)
        pts.density.push_back(m.density);
        pts.material.push_back(static_cast<std::uint8_t>(body.material));
        break;
      }
    }
  }
  // A body with no point would silently vanish from the run.
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    if (seeded[b] > 0) continue;
    std::ostringstream msg;
    msg << s.source_path << ": bodies[" << b << "] (" << s.bodies[b].name
        << "): no point falls inside it (point spacing " << spacing
        << " m = grid.cell_size / grid.points_per_cell, or an earlier body of the same "
           "material already holds its points): expected a body holding at least one "
           "sub-cell centre";
    throw ScenarioError(msg.str());
  }
  const std::size_t n = pts.x.size();
  for (auto* v : {&pts.vx, &pts.vy, &pts.sxx, &pts.syy, &pts.sxy, &pts.szz}) v->assign(n, 0.0);
  pts.x0 = pts.x;
  pts.y0 = pts.y;
  pts.ref_x = pts.x;
  pts.ref_y = pts.y;
  pts.yielded.assign(n, 0);
  w.transfer = s.transfer;
  if (s.transfer == TransferScheme::Apic)
    for (auto* v : {&pts.cxx, &pts.cxy, &pts.cyx, &pts.cyy}) v->assign(n, 0.0);
  return w;
}

}  // namespace sim
