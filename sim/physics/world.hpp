// Everything one GIMP step reads and writes: the points, the grid, the
// material constants, and scratch space reused every step (no allocation
// inside the step once the first step has sized it).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <new>
#include <stdexcept>
#include <vector>

#include "sim/physics/gimp.hpp"
#include "sim/physics/grid.hpp"
#include "sim/physics/material.hpp"
#include "sim/physics/particles.hpp"
#include "sim/physics/point_strength.hpp"
#include "sim/physics/spec.hpp"
#include "sim/physics/team.hpp"

namespace sim {

// The step found something it cannot go on from (a point leaving the grid, a
// non-finite value, a time step above the stable bound).
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The last mark a band took (sim/physics/bands.hpp: a scatter or the nodal
// update finished), as that mark's epoch, and the last step whose G2P a
// thread took the band for (gather_own_bands). A copied or assigned World
// starts with neither: its step count may be behind the band's.
struct BandDone {
  std::atomic<long> epoch{0};
  std::atomic<long> taken{0};
  BandDone() = default;
  BandDone(const BandDone&) {}
  BandDone& operator=(const BandDone&) {
    epoch.store(0, std::memory_order_relaxed);
    taken.store(0, std::memory_order_relaxed);
    return *this;
  }
};

// The points two threads of the team locate (locate.cpp), as runs of Lane8
// blocks that the one takes from the bottom and the other from the top:
// `claimed` counts the blocks taken this step, `low_blocks` those the
// bottom thread took. On a cache line of its own; a copied or assigned
// World starts with none taken.
struct alignas(64) BlockPool {
  std::atomic<int> claimed{0};
  int low_blocks = 0;
  BlockPool() = default;
  BlockPool(const BlockPool&) {}
  BlockPool& operator=(const BlockPool&) {
    claimed.store(0, std::memory_order_relaxed);
    low_blocks = 0;
    return *this;
  }
};

// One thread's pace (sim/physics/bands.hpp), on a cache line of its own:
// each thread adds to its `worked` while the others add to theirs.
struct alignas(64) ThreadPace {
  double worked = 0;     // seconds of work in the split's phases since the last split
  long points = 0;       // points the last split gave it
  double per_point = 0;  // smoothed seconds per point; 0 until measured
  double weight = 1;     // what the split reads: per_point once every thread has one, else 1
};

// Memory on 64-byte boundaries: locate can write a block of eight stencils
// as seven whole cache lines (stencil_stores.hpp).
template <class T>
struct CacheLineAligned {
  using value_type = T;
  CacheLineAligned() = default;
  template <class U>
  CacheLineAligned(const CacheLineAligned<U>&) {}
  T* allocate(std::size_t n) {
    return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t{64}));
  }
  void deallocate(T* p, std::size_t) { ::operator delete(p, std::align_val_t{64}); }
  template <class U>
  bool operator==(const CacheLineAligned<U>&) const { return true; }
  template <class U>
  bool operator!=(const CacheLineAligned<U>&) const { return false; }
};
using StencilArray = std::vector<StencilWeights, CacheLineAligned<StencilWeights>>;

// From this many points on, a step's arrays (about 225 bytes a point) are
// well past this machine's 260 MB last-level cache, and the phases that wait
// for memory touch it otherwise: locate writes the stencils with streaming
// stores, which do not first read each line they fill (stencil_stores.hpp),
// and P2G asks for each stencil ahead of its use (bands.hpp). Below it,
// ordinary stores leave the stencils in cache for the phases that read them
// next. For the streaming stores:
// `bench/phases REFINE N --threads 2 --whole-step`, six 2-thread runs each,
// in turns, streaming against ordinary stores (issue 17, thirty-second pass):
// 6,552,200 points 34.2-39.3 against 35.8-41.1 ns a point-step; 1,638,050
// and 920,000 points no difference beyond the runs' spread; 409,965 points
// 31.9-37.3 against 28.0-29.8, and 25,538 points 34.0-45.1 against 30.7-37.7.
constexpr long kMemoryBoundFrom = 2'000'000;

struct World {
  Particles points;
  Grid grid;
  GimpShape gimp;  // cell size and the l_p of every point (uGIMP keeps the initial size)
  TransferScheme transfer = TransferScheme::Flip;
  std::vector<MaterialSpec> material_specs;  // as they stand now (material changes edit them)
  std::vector<MaterialConstants> materials;
  PointStrength strength;  // per point, where a random field set it; empty otherwise
  // Per stored point, its index in the scene; empty while the points are
  // stored in scene order (sim/physics/point_order.hpp).
  std::vector<int> scene_index;

  // Scratch, rebuilt every step.
  StencilArray weights;  // per point: its stencil's S_ip and base node
  // From this many points on, locate streams the stencils to memory and P2G
  // fetches them ahead (kMemoryBoundFrom); tests lower it to compare the two
  // ways.
  long memory_bound_from = kMemoryBoundFrom;
  std::vector<int> bin_key;       // per point: the bin of its stencil's base node
  std::vector<int> order;         // points sorted by their stencil's base node
  std::vector<int> band_start;    // order[band_start[b] .. band_start[b+1]) is band b
  std::vector<int> thread_counts; // counting sort: per thread, points per bin (base node)
  std::vector<int> thread_window; // per thread: touched window, first point off the grid, points off the bins
  std::vector<int> thread_totals; // per thread: points in its run of bins
  std::vector<BlockPool> block_pools;  // per pair of threads: locate's shared blocks
  // Per base row of the window: the first and last base node i with points
  // (the first > the last for a row without), from the counting sort.
  std::vector<int> base_row_span;
  // The counting sort's bins: base nodes [bin_i0, bin_i0 + bin_width) x
  // [bin_j0, bin_j0 + bins / bin_width), row-major (locate.cpp).
  int bins = 0, bin_i0 = 0, bin_j0 = 0, bin_width = 0;
  int bad_point = 0;              // scene index of the first point off the grid (the number of points if none)
  std::vector<int> thread_bands;  // thread t owns bands [thread_bands[t], thread_bands[t+1])
  std::vector<ThreadPace> thread_pace;  // per thread of the team: what sets its share (bands.hpp)
  std::vector<BandDone> band_done;  // per band: its last mark (bands.hpp)
  long step_serial = 0;           // steps located so far (prepare_locate)
  std::vector<double> band_sums;  // per band partial sums of the step's reductions
  Team team;                      // the step's threads (sim/physics/team.hpp)
  // One per-point array of each kind, for sort_points_by_cell: kept from sort
  // to sort so that a sort allocates nothing (point_order.cpp).
  std::vector<double> sort_scratch;
  std::vector<std::uint8_t> sort_scratch_bytes;
  std::vector<int> sort_scratch_ints;
};

// Whether the world's points are past kMemoryBoundFrom: locate then streams
// the stencils and P2G fetches them ahead.
inline bool memory_bound(const World& w) {
  return static_cast<long>(w.points.size()) >= w.memory_bound_from;
}

// Visits every per-point array of the world that is in use (APIC's and the
// per-point strengths are empty in scenes without them), for whatever must
// reach them all: the sort into cell order (point_order.cpp), the count of
// memory (bench/memory_use.hpp). W is World or const World. The asserts
// count the arrays, so that a new one cannot be left out.
template <class W, class Visit>
void for_each_point_array(W& w, Visit visit) {
  auto& p = w.points;
  static_assert(sizeof(Particles) == 20 * sizeof(std::vector<double>),
                "a per-point array was added to Particles: visit it here");
  for (auto* v : {&p.x, &p.y, &p.vx, &p.vy, &p.mass, &p.density, &p.sxx, &p.syy, &p.sxy, &p.szz,
                  &p.cxx, &p.cxy, &p.cyx, &p.cyy, &p.x0, &p.y0, &p.ref_x, &p.ref_y})
    if (!v->empty()) visit(*v);
  visit(p.material);
  visit(p.yielded);
  auto& s = w.strength;
  static_assert(sizeof(PointStrength) == sizeof(SurfaceArrays) + 2 * sizeof(std::vector<double>),
                "a per-point array was added to PointStrength: visit it here");
  if (s.active()) {
    visit(s.cohesion);
    visit(s.friction_angle);
    for_each_surface_array(s.surfaces, visit);
  }
}

// Rows of base nodes per band. Two bands apart never share a node (a stencil
// spans 3 rows), so every other band can be scattered to the grid at once.
constexpr int kBandRows = 4;

// Partial sums per band, band_sums[band * kBandSums + which] (the StepReport
// fields of the same names). Summed band by band in order, so they do not
// depend on the number of threads.
enum BandSum : int {
  kInternalWork,
  kGravityWork,
  kKineticEnergy,
  kMovingKineticEnergy,
  kDampingLoss,
  kMaxSignal,  // a maximum, not a sum
  kWallChangeOnPoints,
  kKineticBeforeGrid,  // APIC: the points' kinetic energy at the start of the step
  kBandSums  // how many
};

// What a velocity update (grid to points) sums over one band's points.
struct PointSums {
  double gravity_work, kinetic, moving, damped, signal, walled;
};

// Whether point p is soil, of a Mohr-Coulomb material: what the diagnostics
// and the runout measure, leaving the house and other elastic bodies out.
inline bool is_soil(const World& w, std::size_t p) {
  return w.materials[w.points.material[p]].plastic;
}

inline void store_point_sums(World& w, int band, const PointSums& s) {
  double* sums = &w.band_sums[band * kBandSums];
  sums[kGravityWork] = s.gravity_work;
  sums[kKineticEnergy] = s.kinetic;
  sums[kMovingKineticEnergy] = s.moving;
  sums[kDampingLoss] = s.damped;
  sums[kMaxSignal] = s.signal;
  sums[kWallChangeOnPoints] = s.walled;
}

}  // namespace sim
