// The final state of the Bui et al. (2008) column against the experiment
// (tests/validation/README.md, "Bui et al. (2008) column"): reading the
// digitised curves of scenarios/validation/data/ and measuring the same
// quantities on the experiment's curves and on the simulation's points.
// x = 0 is the wall for both.
#pragma once

#include <string>
#include <vector>

#include "sim/physics/particles.hpp"

namespace app {

// A digitised curve: points (x, y) in metres, in file order.
struct Curve {
  std::vector<double> x, y;
};

// Reads a curve file: one "x,y" pair a line, '#' lines and blank lines
// skipped. Every value must be a finite number in [-1, 10] m, the x values
// must not decrease, and there must be at least min_points points. Throws
// sim::ScenarioError naming the file, the line, the value and what is allowed.
Curve read_curve(const std::string& path, std::size_t min_points);

// The toe of a free surface or thickness profile: walking from the wall along
// the curve (linear between points), the first x where its height falls below
// min_height; the last point's x when it never does (the data say nothing
// beyond it).
double curve_toe(const Curve& surface, double min_height);

// The simulation's free surface at x: the highest top y_p + a_p of the points
// whose centres lie within half_width of x, where a_p = sqrt(V_p) / 2 is half
// the side of the point's square (V_p = m_p / rho_p, as the painter draws
// it); 0 where there is none.
double surface_height(const sim::Particles& p, double x, double half_width);

// Points on a failure line.
struct Marks {
  std::vector<double> x, y;
};

// The boundary of the zone that did not move, in the initial configuration:
// in each initial row of points (spacing apart) whose centre height lies in
// [y_low, y_high], walking from the wall, the first point whose horizontal
// displacement x - x0 exceeds `moved`; the mark is half a spacing to its left
// (the edge of the unmoved points). Rows where every point moved are marked at
// the wall; rows where none moved are left out.
Marks unmoved_boundary(const sim::Particles& p, double spacing, double y_low, double y_high,
                       double moved);

// The points of a curve with y_low <= y <= y_high.
Marks curve_band(const Curve& c, double y_low, double y_high);

// Angle from the horizontal, in degrees, of the least-squares line
// x = a + b y through the marks (x as a function of height, so a steep line
// is fitted as well as a shallow one): atan(1 / |b|). NaN with fewer than 3.
double line_angle_deg(const Marks& m);

// x of a curve at height y, linear between its points taken in order of
// height (the failure line falls monotonically from the top to the base);
// clamped to the end points outside their range.
double curve_x_at_height(const Curve& c, double y);

// Root mean square of the horizontal distance between the marks and the
// curve at the marks' heights; NaN without marks.
double rms_offset_x(const Marks& m, const Curve& c);

// Root mean square of surface_height(p, x_i, half_width) - y_i over the
// surface curve's points.
double rms_surface_difference(const sim::Particles& p, const Curve& surface, double half_width);

}  // namespace app
