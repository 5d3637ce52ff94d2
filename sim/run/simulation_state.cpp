// Saving and restoring a Simulation between steps (checkpoints, and the
// gravity stage one scenario can reuse from another), and the key that says
// when a saved state belongs to a scenario.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include <omp.h>

#include "sim/io/binary_io.hpp"
#include "sim/run/simulation.hpp"

namespace sim {

namespace {

// "LSSTATE" and a format version; bump the version whenever the layout below
// changes, so an old file is refused rather than misread.
constexpr std::uint64_t kMagic = 0x4c53535441544503ULL;  // 03: per-point strength
// Read back as another number on a machine of the other byte order.
constexpr std::uint64_t kByteOrder = 0x0102030405060708ULL;

static_assert(std::is_trivially_copyable<EnergyBalance>::value, "EnergyBalance is raw bytes");

void put_material(BinaryWriter& w, const MaterialSpec& m) {
  w.put_string(m.name);
  w.put(m.model);
  for (double v : {m.density, m.youngs_modulus, m.poisson_ratio, m.cohesion, m.friction_angle,
                   m.dilation_angle, m.critical_density})
    w.put(v);
}

MaterialSpec get_material(BinaryReader& r) {
  MaterialSpec m;
  m.name = r.get_string();
  m.model = r.get<MaterialModel>();
  for (double* v : {&m.density, &m.youngs_modulus, &m.poisson_ratio, &m.cohesion,
                    &m.friction_angle, &m.dilation_angle, &m.critical_density})
    *v = r.get<double>();
  return m;
}

void put_result(BinaryWriter& w, const StageResult& r) {
  w.put_string(r.name);
  w.put(r.type);
  for (double v : {r.simulated_time, r.wall_time, r.kinetic_energy, r.moving_kinetic_energy,
                   r.gravity_work})
    w.put(v);
  w.put(r.steps);
  w.put(r.ended_at_rest);
  w.put(r.energy);
  const StageMetrics& m = r.metrics;
  for (double v : {m.max_soil_ux, m.initial_toe, m.toe, m.runout, m.main_body_fraction, m.packed_fraction, m.disconnected_fraction,
                   m.yielding_fraction, m.deposit_slope_deg})
    w.put(v);
  w.put(std::uint64_t(m.materials.size()));
  for (const MaterialMotion& mm : m.materials) {
    w.put_string(mm.material);
    for (double v : {mm.mean_ux, mm.mean_uy, mm.max_displacement}) w.put(v);
  }
}

StageResult get_result(BinaryReader& rd) {
  StageResult r;
  r.name = rd.get_string();
  r.type = rd.get<StageType>();
  for (double* v : {&r.simulated_time, &r.wall_time, &r.kinetic_energy, &r.moving_kinetic_energy,
                    &r.gravity_work})
    *v = rd.get<double>();
  r.steps = rd.get<long>();
  r.ended_at_rest = rd.get<bool>();
  r.energy = rd.get<EnergyBalance>();
  StageMetrics& m = r.metrics;
  for (double* v : {&m.max_soil_ux, &m.initial_toe, &m.toe, &m.runout,
                    &m.main_body_fraction, &m.packed_fraction, &m.disconnected_fraction, &m.yielding_fraction, &m.deposit_slope_deg})
    *v = rd.get<double>();
  const auto n = rd.get<std::uint64_t>();
  if (n > 256) rd.fail("a stage result lists " + std::to_string(n) + " materials");
  m.materials.resize(n);
  for (MaterialMotion& mm : m.materials) {
    mm.material = rd.get_string();
    for (double* v : {&mm.mean_ux, &mm.mean_uy, &mm.max_displacement}) *v = rd.get<double>();
  }
  return r;
}

// The arrays of the points, in one fixed order for writing and reading.
template <class P>
auto point_arrays(P& p) {
  return std::array<decltype(&p.x), 14>{&p.x,   &p.y,   &p.vx,  &p.vy,  &p.mass,
                                        &p.density, &p.sxx, &p.syy, &p.sxy, &p.szz,
                                        &p.x0,  &p.y0,  &p.ref_x, &p.ref_y};
}

// APIC's affine velocities, saved after the point arrays where the scene
// takes that transfer.
template <class P>
auto affine_arrays(P& p) {
  return std::array<decltype(&p.cxx), 4>{&p.cxx, &p.cxy, &p.cyx, &p.cyy};
}

// A random field's strength of each point, saved where one was drawn; the
// returns are rebuilt from it.
template <class S>
auto strength_arrays(S& s) {
  return std::array<decltype(&s.cohesion), 2>{&s.cohesion, &s.friction_angle};
}

// The size of a saved state, within its header and stage results: the
// point arrays it holds (save_state below) and the two bytes of each point.
std::size_t state_bytes_about(const World& w) {
  constexpr std::size_t kHeaderBytes = 64 * 1024;
  const std::size_t doubles =
      point_arrays(w.points).size() +
      (w.transfer == TransferScheme::Apic ? affine_arrays(w.points).size() : 0) +
      (w.strength.active() ? strength_arrays(w.strength).size() : 0);
  return w.points.size() * (doubles * sizeof(double) + 2) + kHeaderBytes;
}

// The point arrays of a state, each in scene order: their room is taken as
// the state is written (add), then the last step's team gathers them there
// (fill), each thread one run of the points in every array. The watchdog
// saves the state between two steps (every kWatchdogSaveSteps steps), while
// the team's other threads wait: one thread took 2.1 ms a save on the
// 66,787-point slope; two threads 1.35 ms (a throw-away timer, issue 17,
// thirty-ninth pass). Copies, so the same bytes.
class SceneOrderArrays {
 public:
  explicit SceneOrderArrays(std::size_t points) : n_(points) {}

  template <class T>
  void add(BinaryWriter& w, const std::vector<T>& v) {
    if (v.size() != n_) throw std::logic_error("a point array of another length than the points");
    copies(v).push_back({w.put_space<T>(n_), v.data()});
  }

  // `from[i]`: the slot of the point of scene index i; empty where the
  // points are stored in scene order.
  void fill(BinaryWriter& w, const std::vector<int>& from, int threads) const {
    const std::size_t n = n_;
#pragma omp parallel num_threads(threads)
    {
      const std::size_t k = static_cast<std::size_t>(omp_get_num_threads());
      const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
      const std::size_t lo = n * t / k, hi = n * (t + 1) / k;
      gather(w, doubles_, from, lo, hi);
      gather(w, bytes_, from, lo, hi);
    }
  }

 private:
  template <class T>
  struct Copy {
    std::size_t offset;
    const T* source;
  };
  std::vector<Copy<double>>& copies(const std::vector<double>&) { return doubles_; }
  std::vector<Copy<std::uint8_t>>& copies(const std::vector<std::uint8_t>&) { return bytes_; }

  template <class T>
  static void gather(BinaryWriter& w, const std::vector<Copy<T>>& list,
                     const std::vector<int>& from, std::size_t lo, std::size_t hi) {
    for (const Copy<T>& c : list) {
      char* out = w.at(c.offset);
      if (from.empty()) {
        std::memcpy(out + lo * sizeof(T), c.source + lo, (hi - lo) * sizeof(T));
        continue;
      }
      for (std::size_t i = lo; i < hi; ++i)
        std::memcpy(out + i * sizeof(T), &c.source[from[i]], sizeof(T));
    }
  }

  std::size_t n_;
  std::vector<Copy<double>> doubles_;
  std::vector<Copy<std::uint8_t>> bytes_;
};

// 64-bit FNV-1a.
std::uint64_t hash_bytes(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ULL;
  for (const unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

}  // namespace

std::uint64_t stage_prefix_key(const Scenario& s, std::size_t stages) {
  BinaryWriter w;
  for (double v : {s.domain_min[0], s.domain_min[1], s.domain_max[0], s.domain_max[1],
                   s.cell_size, s.gravity[0], s.gravity[1], s.time_step.courant,
                   s.time_step.fixed_dt})
    w.put(v);
  w.put(s.padding_cells);
  w.put(s.points_per_cell);
  for (const Wall& wall : {s.boundaries.left, s.boundaries.right, s.boundaries.bottom,
                          s.boundaries.top}) {
    w.put(wall.kind);
    w.put(wall.friction);
  }
  w.put(s.time_step.mode);
  w.put(s.transfer);
  for (const MaterialSpec& m : s.materials) put_material(w, m);
  for (const BodySpec& b : s.bodies) {
    w.put_string(b.name);
    w.put(b.material);
    w.put_vector(b.polygon);
  }
  w.put_string(s.output.displacement_reference);
  w.put(s.output.frame_interval);
  for (std::size_t k = 0; k < std::min(stages, s.stages.size()); ++k) {
    const StageSpec& st = s.stages[k];
    w.put_string(st.name);
    w.put(st.type);
    for (double v : {st.duration, st.ramp_fraction, st.damping, st.rest.kinetic_ratio,
                     st.rest.min_time})
      w.put(v);
    w.put(st.rest.enabled);
    for (const MaterialChange& c : st.changes) {
      w.put(c.material);
      w.put_string(c.property);
      w.put(c.value);
      if (!c.has_field) continue;  // keys of scenes without fields stay as they were
      const RandomFieldSpec& f = c.field;
      w.put(f.distribution);
      for (double v : {f.mean, f.cov, f.lower, f.upper, f.theta_x, f.theta_y}) w.put(v);
      w.put(f.seed);
    }
    w.put(stage_is_painted(s, st));
  }
  return hash_bytes(w.bytes());
}

std::size_t reusable_stages(const Scenario& s) {
  for (std::size_t k = 0; k < s.stages.size(); ++k) {
    const StageSpec& st = s.stages[k];
    if (stage_is_painted(s, st)) return 0;
    if (s.output.vtk == "interval") return 0;  // nor writes the states of its steps
    if (st.type == StageType::Gravity) return k + 1;
  }
  return 0;
}

std::string Simulation::save_state() const { return save_state(std::string()); }

// A state holds the points in scene order; they are written in that order
// where they are stored (point_order.hpp), not moved there: the watchdog saves
// the state every kWatchdogSaveSteps steps, and moving the points back and
// forth cost two permutations of every point array each time.
std::string Simulation::save_state(std::string buffer) const {
  const std::vector<int> from = slots_in_scene_order(world_);
  BinaryWriter w(std::move(buffer));
  w.reserve(state_bytes_about(world_));
  w.put(kMagic);
  w.put(kByteOrder);
  const std::size_t defined = stage_index_ + (progress_.started ? 1 : 0);
  w.put(std::uint64_t(defined));
  w.put(stage_prefix_key(scenario_, defined));
  w.put(time_);
  w.put(stage_time_);
  w.put(gravity_factor_);
  w.put(frames_);
  w.put(std::uint64_t(stage_index_));
  w.put(std::uint64_t(results_.size()));
  for (const StageResult& r : results_) put_result(w, r);
  const StageProgress& p = progress_;
  w.put(p.started);
  if (p.started) {
    StageResult r = p.result;
    r.wall_time +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
    put_result(w, r);
    for (double v : {p.max_signal, p.kinetic_start, p.elastic_start}) w.put(v);
    w.put(p.next_frame);
  }
  w.put(std::uint64_t(world_.material_specs.size()));
  for (const MaterialSpec& m : world_.material_specs) put_material(w, m);
  const Particles& pts = world_.points;
  w.put(std::uint64_t(pts.size()));
  SceneOrderArrays arrays(pts.size());
  for (const std::vector<double>* a : point_arrays(pts)) arrays.add(w, *a);
  arrays.add(w, pts.material);
  arrays.add(w, pts.yielded);
  if (world_.transfer == TransferScheme::Apic)
    for (const std::vector<double>* a : affine_arrays(pts)) arrays.add(w, *a);
  w.put(world_.strength.active());
  if (world_.strength.active())
    for (const std::vector<double>* a : strength_arrays(world_.strength)) arrays.add(w, *a);
  arrays.fill(w, from, std::max(1, world_.team.threads));
  return w.take();
}

void Simulation::restore_state(const std::string& bytes, const std::string& label) {
  restore_scene_order(world_);  // the state's points are in scene order
  BinaryReader rd(bytes, label);
  if (bytes.size() < 16 || rd.get<std::uint64_t>() != kMagic)
    rd.fail("not a state saved by this version of landslide");
  if (rd.get<std::uint64_t>() != kByteOrder) rd.fail("saved on a machine of another byte order");
  const auto defined = rd.get<std::uint64_t>();
  if (defined > scenario_.stages.size() ||
      rd.get<std::uint64_t>() != stage_prefix_key(scenario_, defined))
    rd.fail("saved from another scenario: its first " + std::to_string(defined) +
            " stages, materials, bodies, grid or time step differ from " + scenario_.source_path);
  time_ = rd.get<double>();
  stage_time_ = rd.get<double>();
  gravity_factor_ = rd.get<double>();
  frames_ = rd.get<int>();
  stage_index_ = rd.get<std::uint64_t>();
  const auto results = rd.get<std::uint64_t>();
  if (results != stage_index_) rd.fail("the stage results do not match the stage index");
  results_.clear();
  for (std::uint64_t k = 0; k < results; ++k) results_.push_back(get_result(rd));
  progress_ = StageProgress{};
  progress_.started = rd.get<bool>();
  if (progress_.started) {
    progress_.result = get_result(rd);
    for (double* v : {&progress_.max_signal, &progress_.kinetic_start, &progress_.elastic_start})
      *v = rd.get<double>();
    progress_.next_frame = rd.get<long>();
  }
  if (rd.get<std::uint64_t>() != world_.material_specs.size()) rd.fail("material count differs");
  for (std::size_t m = 0; m < world_.material_specs.size(); ++m) {
    world_.material_specs[m] = get_material(rd);
    world_.materials[m] = make_material_constants(world_.material_specs[m]);
  }
  Particles& pts = world_.points;
  const std::size_t n = pts.size();
  if (rd.get<std::uint64_t>() != n) rd.fail("point count differs from the seeded scenario");
  for (std::vector<double>* a : point_arrays(pts)) *a = rd.get_vector<double>(n, "a point array");
  pts.material = rd.get_vector<std::uint8_t>(n, "the material array");
  pts.yielded = rd.get_vector<std::uint8_t>(n, "the yielded array");
  if (world_.transfer == TransferScheme::Apic)
    for (std::vector<double>* a : affine_arrays(pts))
      *a = rd.get_vector<double>(n, "an affine velocity array");
  PointStrength& strength = world_.strength;
  strength = PointStrength{};
  if (rd.get<bool>()) {
    for (std::vector<double>* a : strength_arrays(strength))
      *a = rd.get_vector<double>(n, "a per-point strength array");
    rebuild_point_strength(world_);
  }
  if (!rd.at_end()) rd.fail("bytes after the end of the state");
}

}  // namespace sim
