// The first phase of the step: every point's GIMP stencil (Eqs. 12, 13), the
// window of nodes the points touch, and the points sorted into bands
// (sim/physics/bands.hpp). Run by every thread of the step's team, or by one thread
// outside it (tests).
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

#include "sim/physics/bands.hpp"
#include "sim/physics/locate_stencils.hpp"
#include "sim/physics/point_order.hpp"
#include "sim/physics/step.hpp"

namespace sim {

namespace {

// The bins a step counts its points in while it computes their stencils are
// the last step's base nodes and this margin around them: a step moves a point
// by at most about half a cell (the scene reader and the time loop keep the
// Courant number at or below 0.5). A point off them sends the step back to
// count again in bins fitted to its window.
constexpr int kBinMargin = 1;

}  // namespace

// Names the first point off the grid, its material, where it is and the grid.
void throw_point_left_grid(const World& w) {
  const int p = slot_of_scene_index(w, w.bad_point);
  std::ostringstream msg;
  msg.precision(6);
  msg << "point " << w.bad_point << " (material '" << w.material_specs[w.points.material[p]].name
      << "') at (" << w.points.x[p] << ", " << w.points.y[p] << ") m ";
  if (!std::isfinite(w.points.x[p]) || !std::isfinite(w.points.y[p]))
    msg << "has a non-finite position";
  else
    msg << "left the grid [" << w.grid.origin_x << ", "
        << w.grid.origin_x + (w.grid.nx - 1) * w.grid.h << "] x [" << w.grid.origin_y << ", "
        << w.grid.origin_y + (w.grid.ny - 1) * w.grid.h << "]";
  throw SimulationError(msg.str());
}

namespace {

// Within one base node the counting sort leaves points by slot; where the
// points are stored in cell order (point_order.hpp) that is not scene order,
// so an insertion sort of the calling thread's bands puts each base node's
// points in scene order: the order of the points, and so every sum of the
// step, then does not depend on where they are stored.
void order_ties_by_scene_index(World& w) {
  if (w.scene_index.empty()) return;
  const BandRange r = own_bands(w);
  const int *key = w.bin_key.data(), *scene = w.scene_index.data();
  int* order = w.order.data();
  const int first = w.band_start[r.begin], end = w.band_start[r.end];
  if (first == end) return;
  // The key and scene index of the point at s - 1, held from the turn before:
  // most points come in order, and their test then reads nothing of another
  // point. A point moved down leaves that point at s, so they hold still.
  int last_key = key[order[first]], last_scene = scene[order[first]];
  for (int s = first + 1; s < end; ++s) {
    const int p = order[s], kp = key[p], sp = scene[p];
    if (kp != last_key || sp > last_scene) {
      last_key = kp;
      last_scene = sp;
      continue;
    }
    int t = s;
    for (; t > first && key[order[t - 1]] == kp && scene[order[t - 1]] > sp; --t)
      order[t] = order[t - 1];
    order[t] = p;
  }
}

// Bins for the counting sort: base nodes [i0, i0 + width) x [j0, j0 + rows).
void set_bins(World& w, int i0, int j0, int width, int rows, int threads) {
  w.bin_i0 = i0;
  w.bin_j0 = j0;
  w.bin_width = width;
  w.bins = width * rows;
  const std::size_t size = static_cast<std::size_t>(threads) * w.bins;
  if (w.thread_counts.size() < size) w.thread_counts.resize(size);
}

// Whether every point was counted in the bins (none off them, none off the
// grid), from the threads' partials: the same answer on every thread.
bool counted_in_bins(const World& w, int threads) {
  const int n = static_cast<int>(w.points.size());
  for (int t = 0; t < threads; ++t) {
    const int* p = &w.thread_window[static_cast<std::size_t>(t) * kWindowInts];
    if (p[4] < n || p[5] > 0) return false;
  }
  return true;
}

// The window of nodes the points touch, from the threads' partials (min and
// max: the same whatever the number of threads), so a scene pays for the
// nodes near its material, not for the whole mesh.
void set_window(World& w, int threads) {
  Grid& g = w.grid;
  const int n = static_cast<int>(w.points.size());
  int i_lo = g.nx, i_hi = -1, j_lo = g.ny, j_hi = -1;
  w.bad_point = n;
  for (int t = 0; t < threads; ++t) {
    const int* p = &w.thread_window[static_cast<std::size_t>(t) * kWindowInts];
    i_lo = std::min(i_lo, p[0]);
    i_hi = std::max(i_hi, p[1]);
    j_lo = std::min(j_lo, p[2]);
    j_hi = std::max(j_hi, p[3]);
    w.bad_point = std::min(w.bad_point, p[4]);
  }
  if (n == 0) i_lo = i_hi = j_lo = j_hi = 0;
  g.i_begin = i_lo;
  g.i_end = i_hi + 3;
  g.j_begin = j_lo;
  g.j_end = j_hi + 3;
  w.order.resize(n);
  w.base_row_span.resize(2 * static_cast<std::size_t>(std::max(0, g.j_end - 2 - g.j_begin)));
  g.row_span.resize(2 * static_cast<std::size_t>(g.j_end - g.j_begin));
  const int bands = (g.j_end - g.j_begin + kBandRows - 1) / kBandRows;
  w.band_start.resize(static_cast<std::size_t>(bands) + 1);
  w.band_done.resize(static_cast<std::size_t>(bands));
}

// Counts the points of [lo, hi) in bins fitted to the window: the step's
// first count, or one where a point moved off the last step's bins.
void count_in_window_bins(World& w, int t, int lo, int hi) {
  int* counts = counts_of(w, t);
  std::fill(counts, counts + w.bins, 0);
  for (int p = lo; p < hi; ++p) {
    const StencilWeights& st = w.weights[p];
    w.bin_key[p] = bin_of(w, st.base_i, st.base_j);
    ++counts[w.bin_key[p]];
  }
}

// The bins [k0, k0 + width) of one row, each thread's count of each replaced
// by the points before it, from `running` on; returns the points up to the
// row's end. `lo` and `hi` become the row's first and last bin with points
// (width and -1 where none has). One thread's counts have a loop of their
// own: in the loop over the threads, clang unrolled the bins and kept the
// loop over one thread in each, about 34 instructions a bin where this takes
// about 10 (callgrind, bench/instructions.sh: locate_and_sort 36.4 -> 27.2
// instructions a point-step on the 8,370-point slope, issue 17, forty-third
// pass). The same counts, so the same order.
int prefix_row(int* counts, long bins, long k0, int width, int threads, int running, int& lo,
               int& hi) {
  lo = width;
  hi = -1;
  const auto note = [&](int i, bool any) {
    hi = any ? i : hi;
    lo = std::min(lo, any ? i : width);
  };
  if (threads == 1) {
    for (int i = 0; i < width; ++i) {
      const int here = counts[k0 + i];
      counts[k0 + i] = running;
      running += here;
      note(i, here != 0);
    }
    return running;
  }
  for (int i = 0; i < width; ++i) {
    const int before = running;
    for (int u = 0; u < threads; ++u) {
      const int here = counts[u * bins + k0 + i];
      counts[u * bins + k0 + i] = running;
      running += here;
    }
    note(i, running != before);
  }
  return running;
}

// Exclusive prefix of the counts, bin by bin and within a bin thread by
// thread: thread t's points of bin k go after those of threads < t, and each
// thread takes its points in index order, so the sort is stable by point
// index, the same order whatever the number of threads. Each thread does the
// prefix over its own run of bin rows, from the totals of the runs before
// it, and notes where each band starts: band b starts at the first point
// whose base node is in its rows, the window's base rows [b, b + 1)
// kBandRows. It notes too each base row's span, its first and last base
// node with points (base_row_span), for the grid's row spans (step.cpp).
void prefix_own_bins(World& w, int t, int threads) {
  // Locals: a store through an int* could otherwise be a store to w.bins or
  // w.bin_width, which the loops would then read again at every bin.
  int* const counts = w.thread_counts.data();
  const long bins = w.bins;
  const int width = w.bin_width;
  const int rows = width > 0 ? static_cast<int>(bins / width) : 0;
  const int first_row = rows * t / threads, end_row = rows * (t + 1) / threads;
  int total = 0;
  for (int u = 0; u < threads; ++u)
    for (long k = long{first_row} * width; k < long{end_row} * width; ++k) total += counts[u * bins + k];
  w.thread_totals[t] = total;
#pragma omp barrier
  int running = 0;
  for (int u = 0; u < t; ++u) running += w.thread_totals[u];
  const int base_rows = w.grid.j_end - 2 - w.grid.j_begin;
  // The bins a row at a time, from locals: with a division per bin to find
  // the rows' starts and w.bins read again after every store, the prefix
  // took 2.0 to 2.6 ns a point on the 66,787-point slope, whose window is
  // mostly air; 0.8 to 1.1 without (one thread, issue 17, thirtieth pass).
  for (int r = first_row; r < end_row; ++r) {
    const int row = w.bin_j0 + r - w.grid.j_begin;  // the window's base row
    const bool in_window = row >= 0 && row < base_rows;
    if (in_window && row % kBandRows == 0) w.band_start[row / kBandRows] = running;
    int lo, hi;
    running = prefix_row(counts, bins, long{r} * width, width, threads, running, lo, hi);
    if (in_window) {
      w.base_row_span[2 * row] = w.bin_i0 + lo;
      w.base_row_span[2 * row + 1] = w.bin_i0 + hi;
    }
  }
}

// After the prefix: the bands past the last base row start (and end) at the
// last point; the threads' bands and the step's partial sums.
void finish_bands(World& w, int threads) {
  const Grid& g = w.grid;
  const int bands = static_cast<int>(w.band_start.size()) - 1;
  const int filled = (g.j_end - 2 - g.j_begin + kBandRows - 1) / kBandRows;
  for (int b = filled; b <= bands; ++b) w.band_start[b] = static_cast<int>(w.points.size());
  partition_bands(w, threads);
  w.band_sums.assign(static_cast<std::size_t>(bands) * kBandSums, 0.0);
  w.grid.row_sums.assign(static_cast<std::size_t>(g.j_end - g.j_begin) * kRowSums, 0.0);
}

}  // namespace

bool locate_and_sort(World& w) {
  const int t = omp_get_thread_num(), threads = omp_get_num_threads();
  const int n = static_cast<int>(w.points.size());
  // Each thread takes a run of whole Lane8 blocks in index order, for the
  // stencils and for both passes of the counting sort: how many, the two
  // threads of its pool settle as they go (locate_stencils.cpp). Not timed
  // into the pace, which the split of the bands is for.
  locate_own_stencils(w, t, threads);
#pragma omp barrier
  const BlockRange mine = own_blocks(w, t, threads);
  const int lo = std::min(n, 8 * mine.first), hi = std::min(n, 8 * mine.end);
  if (counted_in_bins(w, threads)) {
    // The prefix's first part reads only the counts; its barrier puts the
    // window before the band starts of its second part.
    if (t == 0) set_window(w, threads);
  } else {
#pragma omp single
    {
      set_window(w, threads);
      const Grid& g = w.grid;
      set_bins(w, g.i_begin, g.j_begin, g.i_end - 2 - g.i_begin, g.j_end - 2 - g.j_begin, threads);
    }
    if (w.bad_point < n) return false;  // every thread reads the same value
    count_in_window_bins(w, t, lo, hi);
#pragma omp barrier
  }
  prefix_own_bins(w, t, threads);
#pragma omp barrier
#pragma omp single nowait
  finish_bands(w, threads);
  int* counts = counts_of(w, t);
  // A run of points of one bin (most points, stored in cell order) keeps the
  // bin's count in a register: incremented in memory point by point, each
  // point's store of the count waited for the one before, and perf put 18 %
  // of locate there on an AMD EPYC. Locate went from 12.2/12.4 to 11.1/11.2
  // ns a point on the 66,787-point slope (one thread, least/median of 6 in
  // turns; issue 17, thirty-sixth pass). The same slots, so the same order.
  const int* key = w.bin_key.data();
  int* order = w.order.data();
  for (int p = lo; p < hi;) {
    const int k = key[p];
    int at = counts[k];
    do order[at++] = p++; while (p < hi && key[p] == k);
    counts[k] = at;
  }
#pragma omp barrier
  order_ties_by_scene_index(w);  // the thread's own bands, which only it reads next
  return true;
}

// Outside the team: sizes the per-point scratch and sets the bins from the
// last step's window (none before the first step).
void prepare_locate(World& w) {
  const std::size_t n = w.points.size();
  const int threads = omp_get_max_threads();
  ++w.step_serial;
  w.weights.resize(n);
  w.bin_key.resize(n);
  w.thread_window.resize(static_cast<std::size_t>(threads) * kWindowInts);
  w.thread_totals.resize(static_cast<std::size_t>(threads));
  w.block_pools.resize(static_cast<std::size_t>(threads + 1) / 2);
  for (BlockPool& p : w.block_pools) p.claimed.store(0, std::memory_order_relaxed);
  const Grid& g = w.grid;
  if (g.i_end <= g.i_begin) {
    set_bins(w, 0, 0, 0, 0, threads);
    return;
  }
  const int i0 = std::max(0, g.i_begin - kBinMargin), j0 = std::max(0, g.j_begin - kBinMargin);
  const int i1 = std::min(g.nx - 2, g.i_end - 2 + kBinMargin);
  const int j1 = std::min(g.ny - 2, g.j_end - 2 + kBinMargin);
  set_bins(w, i0, j0, i1 - i0, j1 - j0, threads);
}

void locate_points(World& w) {
  prepare_locate(w);
  if (!locate_and_sort(w)) throw_point_left_grid(w);
}

}  // namespace sim
