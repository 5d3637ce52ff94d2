#include "sim/physics/point_strength.hpp"

#include "sim/physics/world.hpp"

namespace sim {

namespace {

// Point p's entries of the surface arrays: the constants of `mc`.
void put_surface(SurfaceArrays& a, std::size_t p, const MohrCoulomb& mc) {
  pair_surface_constants(a, mc, [p](std::vector<double>& v, double c) { v[p] = c; });
}

// n entries in every surface array, each point's a default surface (the
// linear-elastic points keep it; it is never used).
void size_surfaces(SurfaceArrays& a, std::size_t n) {
  const MohrCoulomb none{};
  pair_surface_constants(a, none, [n](std::vector<double>& v, double c) { v.assign(n, c); });
}

// First field of the run: every point starts from its material's values.
void start_point_strength(World& w) {
  PointStrength& s = w.strength;
  const std::size_t n = w.points.size();
  s.cohesion.assign(n, 0.0);
  s.friction_angle.assign(n, 0.0);
  size_surfaces(s.surfaces, n);
  for (std::size_t p = 0; p < n; ++p) {
    const MaterialSpec& m = w.material_specs[w.points.material[p]];
    if (m.model != MaterialModel::MohrCoulomb) continue;
    s.cohesion[p] = m.cohesion;
    s.friction_angle[p] = m.friction_angle;
    put_surface(s.surfaces, p, w.materials[w.points.material[p]].mohr_coulomb);
  }
}

void rebuild_material(World& w, int material) {
  PointStrength& s = w.strength;
  const MaterialConstants& m = w.materials[material];
  if (!m.plastic) return;
  for (std::size_t p = 0; p < w.points.size(); ++p)
    if (w.points.material[p] == material)
      put_surface(s.surfaces, p, m.mohr_coulomb.with_strength(s.cohesion[p], s.friction_angle[p]));
}

std::vector<double>& values_of(PointStrength& s, const std::string& property) {
  return property == "cohesion" ? s.cohesion : s.friction_angle;
}

}  // namespace

void set_point_strength(World& w, int material, const std::string& property,
                        const std::vector<double>& values) {
  if (!w.strength.active()) start_point_strength(w);
  std::vector<double>& own = values_of(w.strength, property);
  for (std::size_t p = 0; p < w.points.size(); ++p)
    if (w.points.material[p] == material) own[p] = values[p];
  rebuild_material(w, material);
}

void follow_material_change(World& w, int material, const std::string& property) {
  if (!w.strength.active()) return;
  const MaterialSpec& m = w.material_specs[material];
  if (property == "cohesion" || property == "friction_angle") {
    std::vector<double>& own = values_of(w.strength, property);
    const double value = property == "cohesion" ? m.cohesion : m.friction_angle;
    for (std::size_t p = 0; p < w.points.size(); ++p)
      if (w.points.material[p] == material) own[p] = value;
  }
  rebuild_material(w, material);
}

void rebuild_point_strength(World& w) {
  if (!w.strength.active()) return;
  size_surfaces(w.strength.surfaces, w.points.size());
  for (std::size_t m = 0; m < w.material_specs.size(); ++m)
    rebuild_material(w, static_cast<int>(m));
}

// A point whose strength is its material's takes the material's surface
// itself, bit for bit what the step holds for it (start_point_strength).
MohrCoulomb point_mohr_coulomb(const World& w, std::size_t p) {
  const int material = w.points.material[p];
  const MaterialConstants& m = w.materials[material];
  const MaterialSpec& spec = w.material_specs[material];
  const PointStrength& s = w.strength;
  if (!s.active() || !m.plastic ||
      (s.cohesion[p] == spec.cohesion && s.friction_angle[p] == spec.friction_angle))
    return m.mohr_coulomb;
  return m.mohr_coulomb.with_strength(s.cohesion[p], s.friction_angle[p]);
}

}  // namespace sim
