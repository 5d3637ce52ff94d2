// Who does what inside the step's one parallel region.
//
// The points are sorted into bands of kBandRows base-node rows (see
// locate.cpp). Each thread owns a contiguous run of bands, chosen so the
// threads hold about equal numbers of points (partition_bands), and every
// phase of the step hands a thread the same points and the same node rows. What a
// thread writes in one phase it reads in the next from its own cache: with
// phases that handed points out in other ways (chunks of the point index,
// bands on demand) the two cores of this machine spent their time passing
// cache lines back and forth, and 2 threads ran 1.2 to 1.5 times as fast as
// one instead of 1.8 to 1.9 times (bench/README.md).
//
// Results never depend on the partition: a node's sums are taken band by
// band in a fixed order (even bands, then odd), and every reduction is summed
// per band and then over the bands in order.
#pragma once

#include <omp.h>
#include <sched.h>

#include <algorithm>

#include "sim/physics/world.hpp"

namespace sim {

struct BandRange {
  int begin = 0, end = 0;  // bands [begin, end)
};

// The bands of the calling thread. Outside a parallel region (tests calling
// one phase) the one thread owns them all.
inline BandRange own_bands(const World& w) {
  const int bands = static_cast<int>(w.band_start.size()) - 1;
  const int threads = omp_get_num_threads();
  if (threads == 1) return {0, bands};
  const int t = omp_get_thread_num();
  return {w.thread_bands[t], w.thread_bands[t + 1]};
}

// Points in bands [first, end) of one parity.
inline long parity_points(const World& w, int first, int end, int parity) {
  long n = 0;
  for (int b = first + ((first & 1) != parity); b < end; b += 2)
    n += w.band_start[b + 1] - w.band_start[b];
  return n;
}

// The time of a scatter phase, in points: each parity takes as long as its
// busiest thread (the threads meet at a barrier after each).
inline long scatter_cost(const World& w) {
  long cost = 0;
  for (int parity = 0; parity < 2; ++parity) {
    long busiest = 0;
    for (std::size_t t = 0; t + 1 < w.thread_bands.size(); ++t)
      busiest = std::max(busiest, parity_points(w, w.thread_bands[t], w.thread_bands[t + 1], parity));
    cost += busiest;
  }
  return cost;
}

// Splits the bands among `threads` threads: first about equal points each,
// then each boundary moves by a band or two while that shortens the scatter
// phases (scatter_cost). Equal totals can hide a thread with most of its
// points in even bands: it works on while the other waits at the barrier.
inline void partition_bands(World& w, int threads) {
  const int bands = static_cast<int>(w.band_start.size()) - 1;
  const long points = w.band_start[bands];
  w.thread_bands.assign(static_cast<std::size_t>(threads) + 1, bands);
  w.thread_bands[0] = 0;
  int b = 0;
  for (int t = 1; t < threads; ++t) {
    while (b < bands && static_cast<long>(w.band_start[b]) * threads < points * t) ++b;
    w.thread_bands[t] = b;
  }
  long cost = scatter_cost(w);
  for (bool better = true; better;) {
    better = false;
    for (int t = 1; t < threads; ++t) {
      for (const int move : {-2, -1, 1, 2}) {
        const int was = w.thread_bands[t], to = was + move;
        if (to < w.thread_bands[t - 1] || to > w.thread_bands[t + 1]) continue;
        w.thread_bands[t] = to;
        const long c = scatter_cost(w);
        if (c < cost) {
          cost = c;
          better = true;
        } else {
          w.thread_bands[t] = was;
        }
      }
    }
  }
}

// The node rows [first, last) the calling thread resets and updates: band b
// owns rows j_begin + [b, b + 1) kBandRows of the window (the last band the
// rest of it).
inline void own_rows(const World& w, int& first, int& last) {
  const BandRange r = own_bands(w);
  const Grid& g = w.grid;
  last = std::min(g.j_begin + r.end * kBandRows, g.j_end);
  first = std::min(g.j_begin + r.begin * kBandRows, last);
}

// What a band's mark in band_done says it has finished: one of the step's
// two scatters, or the nodal update of its node rows. The mark is
// 4 x the step's serial number + this, an epoch nothing else takes.
enum class BandMark { Mass = 1, Forces = 2, NodalUpdate = 3 };

inline long mark_epoch(const World& w, BandMark m) {
  return 4 * w.step_serial + static_cast<long>(m);
}

// A thread waiting for a mark pauses this many times, then yields its core
// at every try: a partner that another process took off its core would
// otherwise wait for a time slice while the waiter spins.
constexpr int kSpinsBeforeYield = 4000;

// One turn of a spin: the processor's hint that this is a wait loop (x86
// PAUSE), or nothing where the build has no such hint.
inline void spin_pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

// Whether band b has the mark `epoch`; a band past either end has it.
inline bool has_mark(const World& w, int b, long epoch) {
  const int bands = static_cast<int>(w.band_done.size());
  return b < 0 || b >= bands || w.band_done[b].epoch.load(std::memory_order_acquire) == epoch;
}

inline void wait_for_mark(const World& w, int b, long epoch) {
  for (int spins = 0; !has_mark(w, b, epoch); ++spins) {
    if (spins < kSpinsBeforeYield) spin_pause();
    else sched_yield();
  }
}

inline void mark_band(World& w, int b, long epoch) {
  w.band_done[b].epoch.store(epoch, std::memory_order_release);
}

// Marks each of the calling thread's bands.
inline void mark_own_bands(World& w, BandMark m) {
  const BandRange r = own_bands(w);
  const long epoch = mark_epoch(w, m);
  for (int b = r.begin; b < r.end; ++b) mark_band(w, b, epoch);
}

// Runs visit(band) for each of the calling thread's bands; the band's points
// are order[band_start[band] .. band_start[band + 1]). For the phase that
// reads the nodes after the nodal update and writes only its own points: a
// band's stencils reach the two lowest node rows of the band above, so the
// thread's highest band goes last, once the thread above has marked its rows
// updated (update_nodal_momentum); the others need only the thread's own
// rows. No barrier.
template <class Visit>
void gather_own_bands(World& w, Visit visit) {
  const BandRange r = own_bands(w);
  if (r.begin == r.end) return;
  for (int b = r.begin; b + 1 < r.end; ++b) visit(b);
  wait_for_mark(w, r.end, mark_epoch(w, BandMark::NodalUpdate));
  visit(r.end - 1);
}

// For visits that add to grid nodes: even bands first, then odd bands. Two
// bands of one parity are a band apart and a stencil spans three node rows,
// so no two threads add to one node at once, and each node receives its
// sums in the same order whatever the number of threads: an odd band starts
// once its two even neighbours are marked done. A thread's odd bands need
// only its own even bands, but where its bands begin on an odd one: that one
// waits for the thread below's last even band, and goes last. Without a
// barrier between the parities, a thread slower on its even bands and one
// slower on its odd bands even out (bench/README.md). Ends with a barrier.
template <class Visit>
void scatter_own_bands(World& w, BandMark which, Visit visit) {
  const BandRange r = own_bands(w);
  const long epoch = mark_epoch(w, which);
  for (int b = r.begin + (r.begin & 1); b < r.end; b += 2) {
    visit(b);
    mark_band(w, b, epoch);
  }
  const auto when_ready = [&](int b) {
    wait_for_mark(w, b - 1, epoch);
    wait_for_mark(w, b + 1, epoch);
    visit(b);
  };
  const int lowest = r.begin + !(r.begin & 1);
  for (int b = lowest + 2; b < r.end; b += 2) when_ready(b);
  if (lowest < r.end) when_ready(lowest);
#pragma omp barrier
}

}  // namespace sim
