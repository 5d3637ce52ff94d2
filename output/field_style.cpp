// Per-field presentation of the painted frames: names, titles, units and
// the colour range of each field (fixed, from the scenario, or over a stage).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "output/frames.hpp"

namespace app {

namespace {

// A field's name in files and options, and its words on a frame: the title,
// the colour bar's label and unit (as painted: stresses in kPa).
struct FieldInfo {
  Field field;
  const char* name;
  const char* title;
  const char* label;
  const char* unit;  // "" for none
};

constexpr FieldInfo kFields[] = {
    {Field::DisplacementX, "displacement-x", "horizontal displacement", "horizontal displacement",
     "m"},
    {Field::DisplacementY, "displacement-y", "vertical displacement", "vertical displacement",
     "m"},
    // At the start of a slide the trigger has just removed the cohesion, so
    // every soil point sits on the yield surface (1) until the first return.
    {Field::RelativeYield, "relative-yield", "relative yield",
     "relative yield (1: at yield, 2: yielded this step)", ""},
    {Field::StressYY, "stress-yy", "vertical normal stress", "vertical normal stress", "kPa"},
    {Field::Velocity, "velocity", "speed", "speed |v|", "m/s"},
    {Field::Material, "material", "material", "material", ""},
    {Field::Cohesion, "cohesion", "cohesion", "cohesion c", "kPa"},
    {Field::FrictionAngle, "friction-angle", "friction angle", "friction angle phi", "deg"},
};

// The table's row of field f; null for none.
const FieldInfo* info_of(Field f) {
  for (const FieldInfo& i : kFields)
    if (i.field == f) return &i;
  return nullptr;
}

}  // namespace

const std::vector<std::string>& field_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const FieldInfo& f : kFields) v.emplace_back(f.name);
    return v;
  }();
  return names;
}

Field parse_field(const std::string& name) {
  for (const FieldInfo& f : kFields)
    if (name == f.name) return f.field;
  std::string known;
  for (const std::string& n : field_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown field '" + name + "' (expected one of: " + known + ")");
}

std::string field_name(Field f) {
  const FieldInfo* i = info_of(f);
  return i ? i->name : "?";
}

FieldStyle field_style(Field f, const sim::Scenario& scenario) {
  FieldStyle s;
  s.field = f;
  if (const FieldInfo* i = info_of(f)) {
    s.title = i->title;
    s.label = i->label;
    s.unit = i->unit;
  }
  if (f == Field::RelativeYield) {
    s.fixed_range = true;
    s.lo = 0;
    s.hi = 2;
  } else if (f == Field::Material) {
    for (const sim::MaterialSpec& m : scenario.materials) s.names.push_back(m.name);
    s.categorical = true;
    s.fixed_range = true;
    s.lo = 0;
    s.hi = std::max<double>(1, double(scenario.materials.size()) - 1);
  }
  // A range the scenario gives (SI units) holds for every frame of the run.
  const auto given = scenario.output.ranges.find(field_name(f));
  if (given != scenario.output.ranges.end() && !s.categorical) {
    // Painted in kPa; ranges are given in SI units (angles in degrees).
    const double scale = f == Field::StressYY || f == Field::Cohesion ? 1e-3 : 1.0;
    s.fixed_range = true;
    s.lo = given->second[0] * scale;
    s.hi = given->second[1] * scale;
  }
  return s;
}


Range field_range(const FieldStyle& style, const std::vector<Frame>& frames, std::size_t k) {
  std::vector<const std::vector<float>*> values;
  for (const Frame& fr : frames)
    if (k < fr.values.size()) values.push_back(&fr.values[k]);
  return field_range(style, values);
}

namespace {

// The p-quantile (0..1) of the values (reordered), nearest rank.
double quantile(std::vector<float>& finite, double p) {
  const std::size_t k = std::min(finite.size() - 1, std::size_t(p * double(finite.size())));
  std::nth_element(finite.begin(), finite.begin() + std::ptrdiff_t(k), finite.end());
  return finite[k];
}

constexpr double kLowQuantile = 0.01, kHighQuantile = 0.99;

}  // namespace

void RangeAccumulator::add(const std::vector<float>& values) {
  finite_.clear();
  for (const float v : values)
    if (std::isfinite(v)) finite_.push_back(v);
  if (finite_.empty()) return;
  lo_ = std::min(lo_, quantile(finite_, kLowQuantile));
  hi_ = std::max(hi_, quantile(finite_, kHighQuantile));
}

Range RangeAccumulator::range(const FieldStyle& style) const {
  if (style.fixed_range) return Range{style.lo, style.hi};
  double lo = lo_, hi = hi_;
  if (!(lo <= hi)) {  // no finite value at all
    lo = 0;
    hi = 1;
  }
  if (style.field == Field::DisplacementX || style.field == Field::DisplacementY) {
    // Keep 0 in view: a slide moving one way still shows where nothing moved.
    lo = std::min(lo, 0.0);
    hi = std::max(hi, 0.0);
  } else if (style.field == Field::Velocity) {
    lo = 0;
  }
  const double scale = std::max({1.0, std::fabs(lo), std::fabs(hi)});
  if (hi - lo <= 1e-9 * scale) {
    if (lo == 0) {
      hi = 1;
    } else {
      const double mid = 0.5 * (lo + hi), half = 0.5 * scale;
      lo = mid - half;
      hi = mid + half;
    }
  }
  return Range{lo, hi};
}

Range field_range(const FieldStyle& style, const std::vector<const std::vector<float>*>& values) {
  RangeAccumulator acc;
  for (const std::vector<float>* array : values) acc.add(*array);
  return acc.range(style);
}

DisplayUnit display_unit(const FieldStyle& style, const Range& range) {
  const bool displacement =
      style.field == Field::DisplacementX || style.field == Field::DisplacementY;
  if (displacement && std::max(std::fabs(range.lo), std::fabs(range.hi)) < 0.5)
    return DisplayUnit{"mm", 1000};
  return DisplayUnit{style.unit, 1};
}

}  // namespace app
