// The free surface of the soil after a slide, as a profile over x: for each
// bin of width `bin` metres across the domain, the highest top of a soil point
// (y + sqrt(V) / 2, the top of its square as the painter draws it, V its
// current volume), so a coarse run is not biased low by its larger points.
// Soil means points of Mohr-Coulomb (plastic) materials; the house is left out.
#pragma once

#include <vector>

#include "sim/scene/scenario.hpp"
#include "sim/physics/world.hpp"

namespace bench {

struct SurfaceProfile {
  double x0 = 0, bin = 1;   // bin k covers [x0 + k bin, x0 + (k + 1) bin)
  double floor = 0;         // the domain's bottom, the height of a bin without soil
  std::vector<double> top;  // per bin, NaN where the bin holds no soil
};

SurfaceProfile soil_surface(const sim::Scenario& scenario, const sim::World& world, double bin);

// RMS of the bin-by-bin height difference over the bins where either profile
// has soil (an empty bin counts as the floor), m. Both profiles must come from
// scenarios with the same domain and bin width.
double surface_rms_difference(const SurfaceProfile& a, const SurfaceProfile& b);

}  // namespace bench
