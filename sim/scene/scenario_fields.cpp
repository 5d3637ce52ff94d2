// Reading a random field of soil strength where a material-change stage
// would take a number (scenarios/README.md, "Random fields"):
//   "set": {"friction_angle": {"random_field": {"distribution": "truncated-normal",
//           "mean": 20, "cov": 0.15, "lower": 10, "upper": 30,
//           "scale_of_fluctuation": [20, 2], "seed": 7}}}
// Everything the generator (sim/scene/random_field.hpp) would refuse in the
// middle of a run is refused here, before step 0.
#include <cmath>
#include <sstream>

#include "sim/scene/memory_budget.hpp"
#include "sim/scene/scenario_parts.hpp"

namespace sim {

using namespace scenario_json;

namespace {

constexpr double kPi = 3.14159265358979323846;
// Seeds are whole numbers a double holds exactly, so any JSON tool keeps them.
constexpr double kMaxSeed = 9007199254740991.0;  // 2^53 - 1
// Their condition number is about theta / spacing; past this Cholesky fails.
constexpr double kMaxThetaOverSpacing = 1e6;

std::uint64_t seed_of(const Node& node) {
  const Json& v = node.value;
  const bool whole = v.is_number_unsigned() || (v.is_number_integer() && v.get<long long>() >= 0);
  if (!whole || v.get<double>() > kMaxSeed)
    fail(node, "a whole number in [0, 2^53 - 1] (the field's seed)");
  return v.get<std::uint64_t>();
}

// Probability that the parent normal of a truncated normal falls in
// [lower, upper]; bounds far out in one tail would leave none to sample.
double parent_mass(const RandomFieldSpec& f) {
  const double sigma = f.cov * std::abs(f.mean);
  const double a = (f.lower - f.mean) / sigma, b = (f.upper - f.mean) / sigma;
  const auto below = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
  const auto above = [](double x) { return 0.5 * std::erfc(x / std::sqrt(2.0)); };
  return a > 0 ? above(a) - above(b) : below(b) - below(a);
}

// lower and upper of a truncated normal, in the unit of the JSON (`scale` to SI).
void parse_bounds(const Node& node, RandomFieldSpec& f, double lo, double hi, double scale,
                  const std::string& why) {
  f.lower = number(required(node, "lower", "required for a truncated-normal field"), lo,
                   Bound::Closed, hi, Bound::Open) * scale;
  const Node upper = required(node, "upper", "required for a truncated-normal field");
  f.upper = number(upper, f.lower / scale, Bound::Open, hi, Bound::Open) * scale;
  if (!(parent_mass(f) >= 1e-9)) {
    std::ostringstream msg;
    msg << "bounds [" << f.lower / scale << ", " << f.upper / scale << "] holding at least 1e-9"
        << " of the parent normal (mean " << f.mean / scale << ", cov " << f.cov << ")" << why;
    fail(upper, msg.str());
  }
}

void parse_scales(const Node& node, RandomFieldSpec& f, const Scenario& s) {
  const Node theta = required(node, "scale_of_fluctuation");
  if (!theta.value.is_array() || theta.value.size() != 2)
    fail(theta, "[theta_x, theta_y] in m (the scales of fluctuation)");
  const double spacing = s.cell_size / s.points_per_cell;
  const double hi = kMaxThetaOverSpacing * spacing;
  f.theta_x = number(theta.at(0), 0, Bound::Open, hi, Bound::Closed);
  f.theta_y = number(theta.at(1), 0, Bound::Open, hi, Bound::Closed);
  const double nx = std::ceil((s.domain_max[0] - s.domain_min[0]) / spacing);
  const double ny = std::ceil((s.domain_max[1] - s.domain_min[1]) / spacing);
  if (nx > kMaxLatticeNodes || ny > kMaxLatticeNodes) {
    std::ostringstream msg;
    msg << "a scene whose field lattice (the point spacing " << spacing << " m over the domain) "
        << "has at most " << kMaxLatticeNodes << " nodes each way; it has " << nx << " by " << ny;
    fail(node, msg.str());
  }
}

}  // namespace

RandomFieldSpec parse_random_field(const Node& value, const std::string& property,
                                   const MaterialSpec& m, const Scenario& s) {
  require_object(value, {"random_field"});
  const Node node = required(value, "random_field");
  const bool angle = property == "friction_angle";
  RandomFieldSpec f;
  const std::string kind = one_of(required(node, "distribution"), {"lognormal", "truncated-normal"});
  f.distribution = kind == "lognormal" ? RandomFieldSpec::Distribution::LogNormal
                                       : RandomFieldSpec::Distribution::TruncatedNormal;
  if (f.distribution == RandomFieldSpec::Distribution::LogNormal) {
    if (angle)
      fail(node.at("distribution"), "\"truncated-normal\" for a friction angle (it must stay in "
                                    "(dilation_angle, 90) deg, which a log-normal does not)");
    require_object(node, {"distribution", "mean", "cov", "scale_of_fluctuation", "seed"},
                   "a lognormal field");
  } else {
    require_object(node, {"distribution", "mean", "cov", "lower", "upper", "scale_of_fluctuation",
                          "seed"}, "a truncated-normal field");
  }
  const double scale = angle ? kPi / 180 : 1.0;
  f.mean = (angle ? number(required(node, "mean"), 0, Bound::Open, 90, Bound::Open)
                  : positive(required(node, "mean"))) * scale;
  f.cov = number(required(node, "cov"), 0, Bound::Open, 10, Bound::Closed);
  if (f.distribution == RandomFieldSpec::Distribution::TruncatedNormal) {
    // Every point's friction angle must be at least the dilation angle (the
    // Mohr-Coulomb return needs psi <= phi), so the field's lowest value is.
    // Compared in degrees rounded to 1e-9, so that a bound equal to the
    // dilation angle as given is not lost to the round trip through radians.
    const double dilation = std::round(m.dilation_angle / scale * 1e9) / 1e9;
    const double lowest = angle ? std::max(dilation, 1e-9) : 0.0;
    parse_bounds(node, f, lowest, angle ? 90 : HUGE_VAL, scale,
                 angle ? " (friction angles at least materials." + m.name + "'s dilation_angle)" : "");
  }
  parse_scales(node, f, s);
  f.seed = seed_of(required(node, "seed"));
  return f;
}

}  // namespace sim
