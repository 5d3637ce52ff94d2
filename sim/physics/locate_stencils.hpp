// Locate's first part (locate.cpp): every point's GIMP stencil (Eqs. 12,
// 13), each point counted in the bin of its base node, by the threads of
// the step's team, and what the counting sort after it shares with it.
#pragma once

#include "sim/physics/world.hpp"

namespace sim {

// Window partials per thread: i_lo, i_hi, j_lo, j_hi, first point off the
// grid, points off the bins.
constexpr int kWindowInts = 6;

// The bin of base node (i, j): row-major from (bin_i0, bin_j0); -1 off the
// bins. For one node (I = int) or eight, a node a lane (I = Int32x8: AVX2
// has no multiplication of 64-bit lanes).
template <class I>
I bin_of(const World& w, const I& i, const I& j) {
  const I bi = i - w.bin_i0, bj = j - w.bin_j0;
  const auto on = (bi >= 0) & (bi < w.bin_width) & (bj >= 0) & (bj * w.bin_width < w.bins);
  return on ? bj * w.bin_width + bi : I{} - 1;
}

// Thread t's counts, one per bin.
inline int* counts_of(World& w, int t) {
  return w.thread_counts.data() + static_cast<std::size_t>(t) * w.bins;
}

struct BlockRange {
  int first = 0, end = 0;  // Lane8 blocks [first, end)
};

// Thread t's share of the stencils, the counts of its points (counts_of)
// and its window partials (World::thread_window, kWindowInts of them).
void locate_own_stencils(World& w, int t, int threads);

// After the barrier that follows locate_own_stencils: the blocks thread t
// took, in index order. Threads of a team take runs of blocks in the order
// of their numbers, as the counting sort needs.
BlockRange own_blocks(const World& w, int t, int threads);

}  // namespace sim
