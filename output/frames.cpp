#include "output/frames.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "sim/physics/mohr_coulomb.hpp"
#include "sim/scene/memory_budget.hpp"

namespace app {

namespace fs = std::filesystem;

static_assert(static_cast<int>(Field::FrictionAngle) + 1 == sim::kMaxPaintedFields,
              "sim/scene/memory_budget.hpp counts the memory of painting every field");

namespace {

// A live world: displacement from ref_x/ref_y, volume = mass / density.
struct WorldPoints {
  const sim::World& w;
  std::size_t size() const { return w.points.size(); }
  double x(std::size_t i) const { return w.points.x[i]; }
  double y(std::size_t i) const { return w.points.y[i]; }
  double ux(std::size_t i) const { return w.points.x[i] - w.points.ref_x[i]; }
  double uy(std::size_t i) const { return w.points.y[i] - w.points.ref_y[i]; }
  double vx(std::size_t i) const { return w.points.vx[i]; }
  double vy(std::size_t i) const { return w.points.vy[i]; }
  double syy(std::size_t i) const { return w.points.syy[i]; }
  sim::Stress stress(std::size_t i) const {
    const sim::Particles& p = w.points;
    return sim::Stress{p.sxx[i], p.syy[i], p.sxy[i], p.szz[i]};
  }
  double volume(std::size_t i) const { return w.points.volume(i); }
  int material(std::size_t i) const { return w.points.material[i]; }
  bool yielded(std::size_t i) const { return w.points.yielded[i] != 0; }
  const std::vector<sim::MaterialConstants>& materials() const { return w.materials; }
  // Its own where a random field set it, else its material's (plastic points).
  sim::MohrCoulomb mohr_coulomb(std::size_t i) const { return sim::point_mohr_coulomb(w, i); }
};

// A state read back from a .vtu file.
struct StatePoints {
  const sim::PointState& s;
  const std::vector<sim::MaterialConstants>& m;
  std::size_t size() const { return s.x.size(); }
  double x(std::size_t i) const { return s.x[i]; }
  double y(std::size_t i) const { return s.y[i]; }
  double ux(std::size_t i) const { return s.ux[i]; }
  double uy(std::size_t i) const { return s.uy[i]; }
  double vx(std::size_t i) const { return s.vx[i]; }
  double vy(std::size_t i) const { return s.vy[i]; }
  double syy(std::size_t i) const { return s.syy[i]; }
  sim::Stress stress(std::size_t i) const {
    return sim::Stress{s.sxx[i], s.syy[i], s.sxy[i], s.szz[i]};
  }
  double volume(std::size_t i) const { return s.volume[i]; }
  int material(std::size_t i) const { return s.material[i]; }
  bool yielded(std::size_t i) const { return s.yielded[i] != 0; }
  const std::vector<sim::MaterialConstants>& materials() const { return m; }
  sim::MohrCoulomb mohr_coulomb(std::size_t i) const {
    const sim::MohrCoulomb& own = m[s.material[i]].mohr_coulomb;
    return s.cohesion.empty() ? own : own.with_strength(s.cohesion[i], s.friction_angle[i]);
  }
};

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

// A Mohr-Coulomb property of each plastic point; NaN (painted grey) elsewhere.
template <class P, class T, class Property>
void strength_values(const P& p, std::vector<T>& v, Property property) {
  const auto& materials = p.materials();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int m = p.material(i);
    const bool plastic = m >= 0 && std::size_t(m) < materials.size() && materials[m].plastic;
    v[i] = plastic ? property(p.mohr_coulomb(i)) : std::numeric_limits<double>::quiet_NaN();
  }
}

// Field f of every point into v (doubles, or the floats of a frame: each
// value is taken in double and rounded once either way).
template <class P, class T>
void values_into(Field f, const P& p, std::vector<T>& v) {
  const std::size_t n = p.size();
  v.resize(n);
  switch (f) {
    case Field::DisplacementX:
      for (std::size_t i = 0; i < n; ++i) v[i] = p.ux(i);
      break;
    case Field::DisplacementY:
      for (std::size_t i = 0; i < n; ++i) v[i] = p.uy(i);
      break;
    case Field::StressYY:
      for (std::size_t i = 0; i < n; ++i) v[i] = p.syy(i) / 1000.0;
      break;
    case Field::Velocity:
      for (std::size_t i = 0; i < n; ++i) v[i] = std::hypot(p.vx(i), p.vy(i));
      break;
    case Field::Material:
      for (std::size_t i = 0; i < n; ++i) v[i] = p.material(i);
      break;
    case Field::Cohesion:
      strength_values(p, v, [](const sim::MohrCoulomb& mc) { return mc.cohesion / 1000.0; });
      break;
    case Field::FrictionAngle:
      strength_values(p, v, [](const sim::MohrCoulomb& mc) {
        return mc.friction_angle * kDegreesPerRadian;
      });
      break;
    case Field::RelativeYield: {
      const auto& materials = p.materials();
      for (std::size_t i = 0; i < n; ++i) {
        const int m = p.material(i);
        if (m < 0 || std::size_t(m) >= materials.size()) {
          v[i] = std::numeric_limits<double>::quiet_NaN();  // painted grey
        } else if (p.yielded(i)) {
          v[i] = 2.0;
        } else if (materials[m].plastic) {
          v[i] = sim::relative_yield(p.mohr_coulomb(i), p.stress(i));
        } else {
          v[i] = 0.0;  // linear elastic: no yield surface
        }
      }
      break;
    }
  }
}

template <class P>
std::vector<double> values_of(Field f, const P& p) {
  std::vector<double> v;
  values_into(f, p, v);
  return v;
}

// Into `fr`, whose arrays keep their memory: a run capturing frame after
// frame of millions of points then does not fault in fresh pages for each.
template <class P>
void capture(const P& p, const std::vector<Field>& fields, int number, double time,
             const std::string& stage, Frame& fr) {
  fr.number = number;
  fr.time = time;
  fr.stage = stage;
  const std::size_t n = p.size();
  fr.x.resize(n);
  fr.y.resize(n);
  fr.half.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    fr.x[i] = float(p.x(i));
    fr.y[i] = float(p.y(i));
    fr.half[i] = float(half_size(p.volume(i)));
  }
  fr.material.clear();
  if (p.materials().size() > 1) {
    fr.material.resize(n);
    for (std::size_t i = 0; i < n; ++i) fr.material[i] = std::uint8_t(std::clamp(p.material(i), 0, 255));
  }
  fr.values.resize(fields.size());
  for (std::size_t k = 0; k < fields.size(); ++k) values_into(fields[k], p, fr.values[k]);
}

}  // namespace

std::vector<double> field_values(Field f, const sim::World& world) {
  return values_of(f, WorldPoints{world});
}

std::vector<double> field_values(Field f, const sim::PointState& state,
                                 const std::vector<sim::MaterialConstants>& materials) {
  return values_of(f, StatePoints{state, materials});
}

double half_size(double volume) {
  if (!(volume > 0) || !std::isfinite(volume)) return std::numeric_limits<double>::quiet_NaN();
  return 0.5 * std::sqrt(volume);
}

std::size_t Frame::bytes() const {
  std::size_t b = (x.size() + y.size() + half.size()) * sizeof(float);
  for (const auto& v : values) b += v.size() * sizeof(float);
  return b + material.size();
}

Frame capture_frame(const sim::World& world, const std::vector<Field>& fields, int number,
                    double time, const std::string& stage) {
  Frame fr;
  capture_frame_into(fr, world, fields, number, time, stage);
  return fr;
}

void capture_frame_into(Frame& into, const sim::World& world, const std::vector<Field>& fields,
                        int number, double time, const std::string& stage) {
  capture(WorldPoints{world}, fields, number, time, stage, into);
}

Frame capture_frame(const sim::PointState& state,
                    const std::vector<sim::MaterialConstants>& materials,
                    const std::vector<Field>& fields, int number, double time,
                    const std::string& stage) {
  for (const auto* a : {&state.y, &state.ux, &state.uy, &state.vx, &state.vy, &state.sxx,
                        &state.syy, &state.sxy, &state.szz, &state.volume})
    if (a->size() != state.x.size()) throw std::invalid_argument("point state arrays differ in size");
  if (state.material.size() != state.x.size() || state.yielded.size() != state.x.size())
    throw std::invalid_argument("point state arrays differ in size");
  Frame fr;
  capture(StatePoints{state, materials}, fields, number, time, stage, fr);
  return fr;
}


FramePainter::FramePainter(int width, int height)
    : painter_(std::make_unique<render::Painter>(width, height)) {}

const render::Image& FramePainter::paint(const render::FrameSpec& spec, const Frame& frame,
                                         std::size_t k) {
  const std::size_t n = frame.x.size();
  if (k >= frame.values.size() || frame.values[k].size() != n)
    throw std::invalid_argument("frame has no values for field " + std::to_string(k));
  x_.assign(frame.x.begin(), frame.x.end());
  y_.assign(frame.y.begin(), frame.y.end());
  half_.resize(n);
  for (std::size_t i = 0; i < n; ++i) half_[i] = kSquareFill * double(frame.half[i]);
  value_.assign(frame.values[k].begin(), frame.values[k].end());
  render::PointsView view{n, x_.data(), y_.data(), half_.data(), half_.data(), value_.data()};
  if (frame.material.size() == n) view.material = frame.material.data();
  painter_->paint_into(image_, spec, view);
  return image_;
}

render::VideoOptions video_options(double frame_interval) {
  render::VideoOptions o;
  o.fps = frame_interval > 0 ? int(std::clamp(std::lround(2.0 / frame_interval), 2L, 30L)) : 25;
  o.play_fps = std::max(kPlayFps, o.fps);
  return o;
}

bool paints_frames(const sim::Scenario& s) {
  for (const sim::StageSpec& st : s.stages)
    if (st.type != sim::StageType::MaterialChange && sim::stage_is_painted(s, st)) return true;
  return false;
}

std::vector<sim::MaterialConstants> materials_at_stage(const sim::Scenario& scenario,
                                                       const std::string& stage) {
  std::vector<sim::MaterialSpec> specs = scenario.materials;
  for (const sim::StageSpec& st : scenario.stages) {
    if (!stage.empty() && st.name == stage) break;
    if (st.type != sim::StageType::MaterialChange) continue;
    for (const sim::MaterialChange& c : st.changes)
      sim::apply_material_change(specs[c.material], c.property, c.value);
  }
  std::vector<sim::MaterialConstants> out;
  for (const sim::MaterialSpec& m : specs) out.push_back(sim::make_material_constants(m));
  return out;
}

}  // namespace app
