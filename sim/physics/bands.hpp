// Who does what inside the step's one parallel region.
//
// The points are sorted into bands of kBandRows base-node rows (see
// locate.cpp). Each thread owns a contiguous run of bands, chosen so the
// threads take about equal time (partition_bands), and every
// phase of the step hands a thread the same points and the same node rows. What a
// thread writes in one phase it reads in the next from its own cache: with
// phases that handed points out in other ways (chunks of the point index,
// bands on demand) the two cores of this machine spent their time passing
// cache lines back and forth, and 2 threads ran 1.2 to 1.5 times as fast as
// one instead of 1.8 to 1.9 times (bench/README.md). Only the end of the last
// phase, G2P, is shared out on demand (gather_own_bands).
//
// Results never depend on the partition: a node's sums are taken band by
// band in a fixed order (even bands, then odd), and every reduction is summed
// per band and then over the bands in order.
#pragma once

#include <omp.h>
#include <sched.h>

#include <algorithm>
#include <chrono>

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

// The threads' pace. This machine's two cores differ at times: pinned to
// one, a step took 1.4 times as long per point as on the other
// (bench/README.md), and a split by equal points then leaves the faster
// thread waiting at every barrier. So each thread times its work in every
// phase the split shares out but G2P, less its waits for marks (WorkClock), and the
// next split gives it points in inverse proportion to its seconds per point.
// The grid rows count though they are not points: a thread that holds the
// air above a slope takes fewer points. The pace is smoothed over about
// 1 / kPaceWeight steps, as one step's time is too noisy to split by (a split
// by the last step's seconds per band ran slower, bench/README.md), and a
// step counts for at most kPaceJump times or 1 / kPaceJump of the pace so
// far: a thread taken off its core for a scheduler slice mid-step must not
// hand its partner most of the points for the next steps.
constexpr double kPaceWeight = 0.125;
constexpr double kPaceJump = 2.0;

// Folds the last step's times into each thread's pace; a new team size
// starts afresh, split by points alone.
inline void update_pace(World& w, int threads) {
  if (w.thread_pace.size() != static_cast<std::size_t>(threads)) {
    w.thread_pace.assign(static_cast<std::size_t>(threads), ThreadPace{});
    return;
  }
  bool measured = true;
  for (ThreadPace& p : w.thread_pace) {
    if (p.points > 0 && p.worked > 0) {
      const double now = p.worked / static_cast<double>(p.points);
      if (p.per_point == 0) p.per_point = now;
      const double counted = std::clamp(now, p.per_point / kPaceJump, p.per_point * kPaceJump);
      p.per_point += kPaceWeight * (counted - p.per_point);
    }
    p.worked = 0;
    measured = measured && p.per_point > 0;
  }
  for (ThreadPace& p : w.thread_pace) p.weight = measured ? p.per_point : 1.0;
}

// The part of the work that threads [0, t) of a team of `threads` take:
// their shares of the speed (1 / weight), equal shares on a team the paces
// are not for. Every thread computes the same figure.
inline double share_below(const World& w, int t, int threads) {
  if (t >= threads) return 1.0;
  if (w.thread_pace.size() != static_cast<std::size_t>(threads)) return static_cast<double>(t) / threads;
  double below = 0, all = 0;
  for (int u = 0; u < threads; ++u) {
    all += 1.0 / w.thread_pace[u].weight;
    if (u < t) below += 1.0 / w.thread_pace[u].weight;
  }
  return below / all;
}

// Splits the bands among `threads` threads by the threads' paces: each
// boundary at the band start nearest to the points the threads below it
// should take. Until issue 17's thirty-seventh pass a boundary then moved by
// up to two bands while that evened out the points of each parity, for
// scatter phases whose parities met at a barrier; those barriers went at the
// fourteenth pass, and on the 66,787-point slope (2 threads) the moves held
// the split one band above the pace's for most steps: in 8 of 9 runs thread
// 0 worked 1.3 to 4 ns a point-step more than thread 1, which waited 0.04 to
// 0.11 ms a step (of about 2.5) at the end of the force scatter for thread
// 0's top band. Split by the pace alone, the two threads' work differed by
// at most 1.3 ns a point-step in 9 runs and that wait took 0.001 to 0.027 ms
// (a throw-away timer, `bench/phases ... --threads 2 --whole-step`).
inline void partition_bands(World& w, int threads) {
  update_pace(w, threads);
  const int bands = static_cast<int>(w.band_start.size()) - 1;
  const long points = w.band_start[bands];
  w.thread_bands.assign(static_cast<std::size_t>(threads) + 1, bands);
  w.thread_bands[0] = 0;
  int b = 0;
  for (int t = 1; t < threads; ++t) {
    const double below = share_below(w, t, threads) * static_cast<double>(points);
    while (b < bands && w.band_start[b] < below) ++b;
    if (b > w.thread_bands[t - 1] && below - w.band_start[b - 1] < w.band_start[b] - below) --b;
    w.thread_bands[t] = b;
  }
  for (int t = 0; t < threads; ++t)
    w.thread_pace[t].points = w.band_start[w.thread_bands[t + 1]] - w.band_start[w.thread_bands[t]];
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

// What a band's mark in band_done says it has finished, in the order its
// thread does them: the reset of its node rows, the mass scatter, the walls
// on its rows, the force scatter, the nodal update of its rows. The mark is
// 8 x the step's serial number + this, so a band's marks only grow, and a
// mark says that every phase before it is done too.
enum class BandMark { Reset = 1, Mass = 2, Walls = 3, Forces = 4, NodalUpdate = 5 };

inline long mark_epoch(const World& w, BandMark m) {
  return 8 * w.step_serial + static_cast<long>(m);
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

// Whether band b has the mark `epoch` or a later one; a band past either end has it.
inline bool has_mark(const World& w, int b, long epoch) {
  const int bands = static_cast<int>(w.band_done.size());
  return b < 0 || b >= bands || w.band_done[b].epoch.load(std::memory_order_acquire) >= epoch;
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

// Times the calling thread's work in one phase into its pace, less the
// waits for marks, until finish(). Not on a team of one, nor on a team whose
// bands were not split by partition_bands (tests that set them).
class WorkClock {
 public:
  explicit WorkClock(World& w) {
    const int t = omp_get_thread_num();
    if (omp_get_num_threads() > 1 && static_cast<std::size_t>(t) < w.thread_pace.size()) {
      pace_ = &w.thread_pace[t];
      since_ = Clock::now();
    }
  }
  void wait_for(const World& w, int b, long epoch) {
    if (has_mark(w, b, epoch)) return;
    finish();
    wait_for_mark(w, b, epoch);
    if (pace_) since_ = Clock::now();
  }
  void finish() {
    if (pace_) pace_->worked += std::chrono::duration<double>(Clock::now() - since_).count();
  }

 private:
  using Clock = std::chrono::steady_clock;
  ThreadPace* pace_ = nullptr;
  Clock::time_point since_{};
};

// Marks each of the calling thread's bands.
inline void mark_own_bands(World& w, BandMark m) {
  const BandRange r = own_bands(w);
  const long epoch = mark_epoch(w, m);
  for (int b = r.begin; b < r.end; ++b) mark_band(w, b, epoch);
}

// Whether the calling thread is the first to take band b's gather in this
// step (gather_own_bands): each band is visited by exactly one thread. A
// team of one takes every band without asking, so that a test may call the
// phase twice in one step.
inline bool take_band(World& w, int b) {
  if (omp_get_num_threads() == 1) return true;
  return w.band_done[b].taken.exchange(w.step_serial, std::memory_order_relaxed) != w.step_serial;
}

// Runs visit(band) once for every band, each band's points
// order[band_start[band] .. band_start[band + 1]). For the phase that reads
// the nodes after the nodal update and writes only the band's points (G2P),
// the step's last phase. A band's stencils reach the two lowest node rows of
// the band above, so a band is visited once both carry the nodal update's
// mark (update_nodal_momentum).
//
// Each thread first takes its own bands from the bottom up, its highest last
// (the one that waits for the thread above). A thread done with them then
// takes bands of the others, from the top of each one's range down, until it
// meets a band its owner has taken. Without this, the split by whole bands
// left one thread waiting for the other at the step's end: on the
// 66,787-point slope on 2 threads, 0.8 to 2.8 ns a point-step at the join of
// each thread, against 30 to 31 of work (a throw-away timer, issue 17,
// thirty-fourth pass). The highest band of a range is taken too: left to its
// owner (until the thirty-seventh pass), it was the owner's last, done while
// the other thread had nothing left, and the join took 0.047 to 0.090 ms of
// a 2.5 ms step, summed over both threads; 0.045 on average now (the same
// timer). Which thread visits a band changes no result: each band's points
// and sums are its own (store_point_sums). Not timed into the pace: a thread
// that takes others' bands would otherwise look slow, and be given fewer
// points for the phases that cannot share so.
template <class Visit>
void gather_own_bands(World& w, Visit visit) {
  const BandRange r = own_bands(w);
  const long updated = mark_epoch(w, BandMark::NodalUpdate);
  for (int b = r.begin; b < r.end && take_band(w, b); ++b) {
    if (b + 1 == r.end) wait_for_mark(w, r.end, updated);
    visit(b);
  }
  const int threads = omp_get_num_threads(), t = omp_get_thread_num();
  for (int k = 1; k < threads; ++k) {
    const int u = (t + k) % threads;
    const int lowest = w.thread_bands[u], highest = w.thread_bands[u + 1] - 1;
    for (int b = highest; b >= lowest && take_band(w, b); --b) {
      wait_for_mark(w, b, updated);
      wait_for_mark(w, b + 1, updated);
      visit(b);
    }
  }
}

// For visits that add to grid nodes: even bands first, then odd bands. Two
// bands of one parity are a band apart and a stencil spans three node rows,
// so no two threads add to one node at once, and each node receives its
// sums in the same order whatever the number of threads: an odd band starts
// once its two even neighbours are marked done. A thread's odd bands need
// only its own even bands, but where its bands begin on an odd one: that one
// waits for the thread below's last even band, and goes last. Without a
// barrier between the parities, a thread slower on its even bands and one
// slower on its odd bands even out (bench/README.md).
//
// No barrier before or after either: a band's points reach the two lowest
// node rows of the band above, so an even band starts once the band above
// carries `ready` (its rows reset, or its walls done: what the visit reads
// or adds to there), and the thread goes on to its own rows once the band
// below, which adds to its lowest rows, is marked done too. Only the bands
// at a boundary between threads ever wait; a barrier made every thread wait
// for the slowest at each of four phases. On 2 threads the 8,370-point
// slope's `landslide run` took 4.01 s against 4.22 s with the barriers
// (medians of 6 in turns); at 25 k and 67 k points the runs in turns did
// not separate (bench/README.md, issue 17's fourteenth pass).
template <class Visit>
void scatter_own_bands(World& w, BandMark which, BandMark ready, Visit visit) {
  const BandRange r = own_bands(w);
  const long epoch = mark_epoch(w, which), ready_epoch = mark_epoch(w, ready);
  WorkClock clock(w);
  for (int b = r.begin + (r.begin & 1); b < r.end; b += 2) {
    clock.wait_for(w, b + 1, ready_epoch);
    visit(b);
    mark_band(w, b, epoch);
  }
  const auto when_ready = [&](int b) {
    clock.wait_for(w, b - 1, epoch);
    clock.wait_for(w, b + 1, epoch);
    visit(b);
    mark_band(w, b, epoch);
  };
  const int lowest = r.begin + !(r.begin & 1);
  for (int b = lowest + 2; b < r.end; b += 2) when_ready(b);
  if (lowest < r.end) when_ready(lowest);
  if (r.begin < r.end) clock.wait_for(w, r.begin - 1, epoch);
  clock.finish();
}

// The points of `band` in runs of one base node, as the sorted points of a
// band come (locate.cpp): the 3x3 nodes of N nodal arrays (three stencil
// rows, each with its fourth lane) are read once a run into `rows`, add(p,
// rows) adds each point's terms in the band's order, and the rows are
// written back at the run's end. Each node still receives its terms one by
// one in the points' order, so its sum has the bits of a node read and
// written per point. The rows are a local array: held as the member array of
// a struct (NodeSums, until issue 17's twenty-fifth pass), g++ 12 kept them
// on the stack and P2G took 9.1 ns a point instead of 7.0.
// The next run's base node is most often the next node of the row (the
// next cell): the rows then slide one node along (slide_row, gimp.hpp)
// instead of being written back and read again. Read again, each row
// overlapped the one just written by three nodes, a load the processor
// cannot serve from its pending stores, so it waited for them to reach the
// cache: P2G took 5.8 ns a point on the 66,787-point slope, 4.8 with the
// slide (one thread, issue 17, twenty-ninth pass).
// In a scene too big for the cache (kMemoryBoundFrom, world.hpp) each point
// waited for its stencil to come from memory: `perf` put half of P2G's
// samples at 6.5 M points on the load of its base node. The stencil
// kFetchAhead points on is asked for first.
constexpr int kFetchAhead = 32;
template <int N, class Add>
void scatter_band_in_runs(World& w, int band, double* const (&arrays)[N], Add add) {
  const Grid& g = w.grid;
  const auto base_of = [&](int p) { return g.node(w.weights[p].base_i, w.weights[p].base_j); };
  const int end = w.band_start[band + 1];
  int s = w.band_start[band];
  int base = s < end ? base_of(w.order[s]) : -1;
  const bool ahead = memory_bound(w);
  Lane4 rows[N][3];
  const auto each_row = [&](auto visit) {
    for (int k = 0; k < N; ++k)
      for (int b = 0; b < 3; ++b) visit(arrays[k] + base + b * g.stride, rows[k][b]);
  };
  if (base >= 0) each_row([](double* row, Lane4& held) { held = load4(row); });
  while (base >= 0) {
    for (; s < end && base_of(w.order[s]) == base; ++s) {
      if (ahead && s + kFetchAhead < end) __builtin_prefetch(&w.weights[w.order[s + kFetchAhead]]);
      add(w.order[s], rows);
    }
    const int next = s < end ? base_of(w.order[s]) : -1;
    if (next == base + 1) {
      each_row([](double* row, Lane4& held) { held = slide_row(row, held); });
      base = next;
      continue;
    }
    each_row([](double* row, Lane4& held) { store4(row, held); });
    base = next;
    if (base >= 0) each_row([](double* row, Lane4& held) { held = load4(row); });
  }
}

}  // namespace sim
