// Locate's stencils (locate_stencils.hpp): eight points at a time, in runs
// of Lane8 blocks that the threads of a pair take from the two ends of
// their pool.
#include "sim/physics/locate_stencils.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstring>

#include "sim/physics/bands.hpp"
#include "sim/physics/point_order.hpp"
#include "sim/physics/stencil_stores.hpp"

namespace sim {

namespace {

// Eight points' bins, all inside the grid and on the bins (nearly every
// group): their keys in one store and their counts without a branch. The
// lane-by-lane loop in compute_stencils tests each point for both, and perf
// put 9 % of locate on it.
void count_eight(const Int32x8& bin, int* keys, int* counts) {
  std::memcpy(keys, &bin, sizeof bin);
  for (int l = 0; l < 8; ++l) ++counts[bin[l]];
}

// What the chunks of compute_stencils a thread takes add up to: the
// window's bounds lane by lane, the first point off the grid (its scene
// index) and the points off the bins.
struct StencilTally {
  Int32x8 i_lo, i_hi, j_lo, j_hi;
  int bad, off_bins = 0;

  explicit StencilTally(const World& w)
      : i_lo(Int32x8{} + w.grid.nx),
        i_hi(Int32x8{} - 1),
        j_lo(Int32x8{} + w.grid.ny),
        j_hi(Int32x8{} - 1),
        bad(static_cast<int>(w.points.size())) {}

  // The thread's window partials (kWindowInts), the lanes reduced.
  void write(const Grid& g, int* window) const {
    int partial[kWindowInts] = {g.nx, -1, g.ny, -1, bad, off_bins};
    for (int l = 0; l < 8; ++l) {
      partial[0] = std::min(partial[0], static_cast<int>(i_lo[l]));
      partial[1] = std::max(partial[1], static_cast<int>(i_hi[l]));
      partial[2] = std::min(partial[2], static_cast<int>(j_lo[l]));
      partial[3] = std::max(partial[3], static_cast<int>(j_hi[l]));
    }
    std::copy(partial, partial + kWindowInts, window);
  }
};

// Stencils of the points of Lane8 blocks [first_block, end_block), eight
// points at a time (gimp.hpp; the last block repeats its last point where the
// points run out), each point counted in its bin (`counts`, the thread's)
// while its base node is at hand, and added to the thread's `tally`.
void compute_stencils(World& w, int first_block, int end_block, int* counts, StencilTally& tally) {
  const Particles& pts = w.points;
  const Grid& g = w.grid;
  const int n = static_cast<int>(pts.size());
  // Locals for the loop: the tally's fields would be stored at every block.
  Int32x8 i_lo = tally.i_lo, i_hi = tally.i_hi, j_lo = tally.j_lo, j_hi = tally.j_hi;
  int bad = tally.bad, off_bins = tally.off_bins;
  const bool stream = memory_bound(w);
  for (int blk = first_block; blk < end_block; ++blk) {
    const int first = 8 * blk, count = std::min(8, n - first);
    Lane8 x, y;
    if (count == 8) {
      x = load8(&pts.x[first]);
      y = load8(&pts.y[first]);
    } else {
      for (int l = 0; l < 8; ++l) {
        x[l] = pts.x[first + std::min(l, count - 1)];
        y[l] = pts.y[first + std::min(l, count - 1)];
      }
    }
    Int32x8 base_i, base_j;
    // The derivatives are not kept: the stress phase makes them again from
    // the positions (point_update.cpp), and the compiler drops them here.
    Lane8 lanes[6], slopes[3];
    gimp_axis(x, g.origin_x, w.gimp, base_i, &lanes[0], slopes);
    gimp_axis(y, g.origin_y, w.gimp, base_j, &lanes[3], slopes);
    store_stencils(&w.weights[first], count, lanes, base_i, base_j, stream);
    // x - x is 0 for a finite x and NaN otherwise. The lanes past count
    // repeat a point, so they change no bound.
    // The base nodes are 32-bit lanes (no 64-bit multiplication in AVX2's
    // bin_of, no 64-bit conversion from doubles): node indices fit (the scene
    // reader's limit on nodes), and the tests below overflow for none.
    const Int32x8 finite = __builtin_convertvector((x - x == 0) & (y - y == 0), Int32x8);
    const Int32x8 inside = finite & (base_i >= 0) & (base_j >= 0) & (base_i < g.nx - 2) &
                           (base_j < g.ny - 2);
    // Bins of the points inside only (the others' base nodes may be anything).
    const Int32x8 bin = bin_of(w, inside & base_i, inside & base_j);
    if (count == 8 && every(inside & (bin >= 0))) {
      count_eight(bin, &w.bin_key[first], counts);
    } else {
      for (int l = 0; l < count; ++l) {
        if (!inside[l]) {
          bad = std::min(bad, scene_index_of(w, first + l));
          continue;
        }
        if (bin[l] < 0) {
          ++off_bins;
          continue;
        }
        w.bin_key[first + l] = static_cast<int>(bin[l]);
        ++counts[bin[l]];
      }
    }
    // Points off the grid stay out of the window.
    i_lo = (inside & (base_i < i_lo)) ? base_i : i_lo;
    i_hi = (inside & (base_i > i_hi)) ? base_i : i_hi;
    j_lo = (inside & (base_j < j_lo)) ? base_j : j_lo;
    j_hi = (inside & (base_j > j_hi)) ? base_j : j_hi;
  }
  tally.i_lo = i_lo;
  tally.i_hi = i_hi;
  tally.j_lo = j_lo;
  tally.j_hi = j_hi;
  tally.bad = bad;
  tally.off_bins = off_bins;
}

// Locate's points go out in pools of Lane8 blocks, one to each pair of
// threads (bands.hpp sets the pools' sizes by the threads' pace), and the
// two threads of a pair take runs of blocks from its two ends until they
// meet, each a quarter of what is left (at least kLeastRun), so that they
// meet within a few hundred points having claimed about twenty runs a step.
// Split once by the pace (until issue 17's thirty-ninth pass), the two
// threads of the 66,787-point slope each waited 23 to 66 us a step at the
// barrier after the stencils (3.5 to 5.6 us now), of about 305 us of
// work each: the pace is right on average, and each step's time is not (a
// throw-away timer, 2 threads, `landslide run`). A thread keeps its points in index order, the
// bottom thread's below the top thread's, as the counting sort needs.
constexpr int kLeastRun = 8;

// The blocks of thread t's pool: threads 2p and 2p + 1 share pool p.
BlockRange pool_blocks(const World& w, int t, int threads) {
  const int blocks = (static_cast<int>(w.points.size()) + 7) / 8;
  const auto below = [&](int u) {
    return static_cast<int>(share_below(w, std::min(u, threads), threads) * blocks + 0.5);
  };
  return {below(t - t % 2), below(t - t % 2 + 2)};
}

// Thread t's runs of its pool, with the thread's counts zeroed first.
void take_own_runs(World& w, int t, int threads, StencilTally& tally) {
  const BlockRange pool = pool_blocks(w, t, threads);
  BlockPool& claims = w.block_pools[static_cast<std::size_t>(t / 2)];
  const bool bottom = t % 2 == 0;
  const int size = pool.end - pool.first;
  int* counts = counts_of(w, t);
  std::fill(counts, counts + w.bins, 0);
  int mine = 0;  // blocks this thread has taken, from its end of the pool
  for (int taken = claims.claimed.load(std::memory_order_relaxed); taken < size;) {
    const int run = std::min(size - taken, std::max(kLeastRun, (size - taken) / 4));
    if (!claims.claimed.compare_exchange_weak(taken, taken + run, std::memory_order_relaxed))
      continue;  // `taken` now holds the other thread's claim too
    const int first = bottom ? pool.first + mine : pool.end - mine - run;
    compute_stencils(w, first, first + run, counts, tally);
    mine += run;
    taken = claims.claimed.load(std::memory_order_relaxed);
  }
  if (bottom) claims.low_blocks = mine;
  if (memory_bound(w)) _mm_sfence();  // the streamed lines before the barrier that hands them on
}

}  // namespace

void locate_own_stencils(World& w, int t, int threads) {
  StencilTally tally(w);
  take_own_runs(w, t, threads, tally);
  tally.write(w.grid, &w.thread_window[static_cast<std::size_t>(t) * kWindowInts]);
}

BlockRange own_blocks(const World& w, int t, int threads) {
  const BlockRange pool = pool_blocks(w, t, threads);
  const int met = pool.first + w.block_pools[static_cast<std::size_t>(t / 2)].low_blocks;
  return t % 2 == 0 ? BlockRange{pool.first, met} : BlockRange{met, pool.end};
}

}  // namespace sim
