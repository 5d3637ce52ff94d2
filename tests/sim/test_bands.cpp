// The scatters' order (sim/physics/bands.hpp). There is no barrier between
// the even and the odd bands: an odd band must still start only after both
// of its even neighbours have finished, whoever owns them and however long
// each takes, or two threads would add to one node at once and a node's sum
// would change its order.
#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <chrono>
#include <vector>

#include "sim/physics/bands.hpp"

namespace {

// One point per band; thread t owns bands [starts[t], starts[t + 1]).
sim::World banded_world(const std::vector<int>& starts) {
  sim::World w;
  const int bands = starts.back();
  for (int b = 0; b <= bands; ++b) w.band_start.push_back(b);
  w.band_done.resize(bands);
  w.thread_bands = starts;
  w.step_serial = 1;
  return w;
}

struct Visit {
  long start = -1, end = -1;  // ticks of one clock shared by the threads
  int thread = -1;
};

void spin_for(std::chrono::microseconds d) {
  const auto until = std::chrono::steady_clock::now() + d;
  while (std::chrono::steady_clock::now() < until) {
  }
}

// The mark a scatter waits for in the band above before it adds to that
// band's rows (step.cpp): the rows reset for the mass, the walls done for
// the forces.
sim::BandMark ready_for(sim::BandMark which) {
  return which == sim::BandMark::Mass ? sim::BandMark::Reset : sim::BandMark::Walls;
}

// One scatter on starts.size() - 1 threads. The last even band below each
// thread boundary is slow, so the odd band just above it is ready last.
std::vector<Visit> scatter_log(sim::World& w, sim::BandMark which, int& team) {
  const int threads = static_cast<int>(w.thread_bands.size()) - 1;
  std::vector<Visit> log(w.band_done.size());
  std::atomic<long> clock{0};
#pragma omp parallel num_threads(threads)
  {
#pragma omp single
    team = omp_get_num_threads();
    sim::mark_own_bands(w, ready_for(which));
    sim::scatter_own_bands(w, which, ready_for(which), [&](int b) {
      log[b].start = clock++;
      log[b].thread = omp_get_thread_num();
      bool slow = false;
      for (std::size_t t = 1; t + 1 < w.thread_bands.size(); ++t)
        slow = slow || b + 1 == w.thread_bands[t] || b + 2 == w.thread_bands[t];
      spin_for(std::chrono::microseconds(slow && b % 2 == 0 ? 3000 : 50 * (b % 3)));
      log[b].end = clock++;
    });
  }
  return log;
}

void expect_ordered(const std::vector<int>& starts) {
  sim::World w = banded_world(starts);
  // Two scatters of one step: the second must not take the first's marks
  // for its own.
  for (const sim::BandMark which : {sim::BandMark::Mass, sim::BandMark::Forces}) {
    int team = 0;
    const std::vector<Visit> log = scatter_log(w, which, team);
    const int bands = static_cast<int>(log.size());
    for (int b = 0; b < bands; ++b) {
      ASSERT_GE(log[b].start, 0) << "band " << b << " was not visited";
      if (team == static_cast<int>(starts.size()) - 1) {
        EXPECT_GE(b, starts[log[b].thread]) << "band " << b;
        EXPECT_LT(b, starts[log[b].thread + 1]) << "band " << b;
      }
      if (b % 2 == 0) continue;
      if (b > 0) {
        EXPECT_GT(log[b].start, log[b - 1].end) << "odd band " << b << " before " << b - 1;
      }
      if (b + 1 < bands) {
        EXPECT_GT(log[b].start, log[b + 1].end) << "odd band " << b << " before " << b + 1;
      }
    }
  }
}

TEST(Bands, OddBandsStartAfterBothEvenNeighboursTwoThreads) {
  expect_ordered({0, 5, 11});  // the upper thread begins on an odd band
  expect_ordered({0, 6, 11});  // and on an even one
}

TEST(Bands, OddBandsStartAfterBothEvenNeighboursFourThreads) {
  expect_ordered({0, 3, 7, 8, 14});  // one thread owns a single odd band
}

TEST(Bands, OneThreadVisitsEveryBandEvenThenOdd) {
  sim::World w = banded_world({0, 7});
  int team = 0;
  const std::vector<Visit> log = scatter_log(w, sim::BandMark::Mass, team);
  for (int b = 0; b < 7; ++b) {
    ASSERT_GE(log[b].start, 0);
    for (int e = 0; e < 7; e += 2) {
      if (b % 2 == 1) {
        EXPECT_GT(log[b].start, log[e].end);
      }
    }
  }
}

}  // namespace

// Runs body(t) on each thread of a team of two; false where no team of two
// threads was had (the caller skips its checks).
template <class Body>
bool on_two_threads(Body body) {
  int team = 0;
#pragma omp parallel num_threads(2)
  {
#pragma omp single
    team = omp_get_num_threads();
    body(omp_get_thread_num());
  }
  return team == 2;
}

// On two threads: thread 1 marks its bands `mark` 3 ms late, thread 0 at
// once, and then each runs `phase` (a scatter or the gather), which logs the
// start of each band's visit. `marked[t]`: when thread t marked its bands.
// Returns false where no team of two threads was had.
template <class Phase>
bool late_mark_log(sim::World& w, sim::BandMark mark, Phase phase, std::vector<Visit>& log,
                   long marked[2]) {
  std::atomic<long> clock{0};
  const bool two = on_two_threads([&](int t) {
    if (t == 1) spin_for(std::chrono::microseconds(3000));
    marked[t] = clock++;
    sim::mark_own_bands(w, mark);
    phase([&](int b) {
      log[b].start = clock++;
      log[b].thread = t;
    });
  });
  for (std::size_t b = 0; b < log.size(); ++b)
    EXPECT_GE(log[b].start, 0) << "band " << b << " was not visited";
  return two;
}

// No barrier before a scatter: the band below a thread boundary adds to the
// two lowest rows of the band above, so it starts only once the thread above
// has marked those rows ready (reset, for the mass), however late that is.
TEST(Bands, ScatterWaitsForTheRowsAboveToBeReady) {
  sim::World w = banded_world({0, 5, 9});  // thread 0's highest band, 4, is even
  std::vector<Visit> log(9);
  long reset[2] = {-1, -1};
  const auto scatter = [&](auto visit) {
    sim::scatter_own_bands(w, sim::BandMark::Mass, sim::BandMark::Reset, visit);
  };
  if (!late_mark_log(w, sim::BandMark::Reset, scatter, log, reset)) GTEST_SKIP() << "no team of 2 threads";
  EXPECT_GT(log[4].start, reset[1]) << "band 4 added to rows the thread above had not reset";
}

// Nor after one: a thread leaves the scatter for the next phase on its own
// rows (walls, nodal update) only once the band below its lowest, which adds
// to its lowest rows, has finished, however slow that band is.
TEST(Bands, ScatterEndsOnceTheBandBelowIsDone) {
  for (const int boundary : {4, 5}) {  // the thread above begins on an even band, an odd one
    sim::World w = banded_world({0, boundary, 9});
    std::vector<Visit> log(9);
    long left[2] = {-1, -1};  // when each thread left the scatter
    std::atomic<long> clock{0};
    const bool two = on_two_threads([&](int t) {
      sim::mark_own_bands(w, sim::BandMark::Walls);
      sim::scatter_own_bands(w, sim::BandMark::Forces, sim::BandMark::Walls, [&](int b) {
        log[b].start = clock++;
        if (b == boundary - 1) spin_for(std::chrono::microseconds(3000));
        log[b].end = clock++;
      });
      left[t] = clock++;
    });
    if (!two) GTEST_SKIP() << "no team of 2 threads";
    EXPECT_GT(left[1], log[boundary - 1].end)
        << "the thread above left before band " << boundary - 1 << " below it was done";
  }
}

// After the nodal update no barrier either: a thread's highest band reads the
// two lowest node rows of the band above, so it goes once the thread above
// has marked its rows updated; the thread's other bands need only its own.
TEST(Bands, HighestBandWaitsForTheRowsAboveToBeUpdated) {
  sim::World w = banded_world({0, 4, 9});
  std::vector<Visit> log(9);
  long updated[2] = {-1, -1};
  const auto gather = [&](auto visit) { sim::gather_own_bands(w, visit); };
  if (!late_mark_log(w, sim::BandMark::NodalUpdate, gather, log, updated))
    GTEST_SKIP() << "no team of 2 threads";
  EXPECT_GT(log[3].start, updated[1]) << "band 3 read rows the thread above had not updated";
}

// The split follows each thread's seconds per point (bands.hpp): a new team
// splits by points, a step's times fold into each thread's smoothed pace,
// and a thread three times as slow per point gets about a quarter of them.
TEST(Bands, SplitFollowsTheThreadsPace) {
  sim::World w;
  for (int b = 0; b <= 40; ++b) w.band_start.push_back(10 * b);  // 40 bands of 10 points
  w.band_done.resize(40);
  sim::partition_bands(w, 2);
  EXPECT_EQ(w.thread_bands, (std::vector<int>{0, 20, 40}));
  const auto step_took = [&](double per_point0, double per_point1) {
    w.thread_pace[0].worked = per_point0 * w.thread_pace[0].points;
    w.thread_pace[1].worked = per_point1 * w.thread_pace[1].points;
    sim::partition_bands(w, 2);
  };
  step_took(3e-8, 1e-8);
  EXPECT_DOUBLE_EQ(w.thread_pace[0].per_point, 3e-8);
  EXPECT_DOUBLE_EQ(w.thread_pace[1].per_point, 1e-8);
  EXPECT_GE(w.thread_bands[1], 8);
  EXPECT_LE(w.thread_bands[1], 12);
  EXPECT_EQ(w.thread_pace[0].points, 10 * w.thread_bands[1]);
  EXPECT_EQ(w.thread_pace[0].worked, 0.0) << "a step's time counted twice";
  step_took(2e-8, 1e-8);  // one step moves the pace by kPaceWeight of the change only
  EXPECT_DOUBLE_EQ(w.thread_pace[0].per_point, 3e-8 + sim::kPaceWeight * (2e-8 - 3e-8));
  EXPECT_LT(w.thread_bands[1], 20);
  const double before = w.thread_pace[1].per_point;
  step_took(1e-8, 1e-6);  // thread 1 held off its core: counted as kPaceJump times its pace
  EXPECT_DOUBLE_EQ(w.thread_pace[1].per_point, before + sim::kPaceWeight * (sim::kPaceJump - 1) * before);
  sim::partition_bands(w, 3);  // a new team size forgets the pace
  for (const sim::ThreadPace& p : w.thread_pace) EXPECT_EQ(p.per_point, 0.0);
  EXPECT_EQ(w.thread_pace[0].points + w.thread_pace[1].points + w.thread_pace[2].points, 400);
}

// A boundary goes to the band start nearest the pace's share, not the first
// one at or above it: with equal paces thread 0 should take 65 of these 130
// points, and 20 is nearer 65 than 120 is.
TEST(Bands, SplitAtTheNearestBandStart) {
  sim::World w;
  w.band_start = {0, 10, 20, 120, 130};
  w.band_done.resize(4);
  sim::partition_bands(w, 2);
  EXPECT_EQ(w.thread_bands, (std::vector<int>{0, 2, 4}));
  EXPECT_EQ(w.thread_pace[0].points, 20);
}

// A thread done with its own bands takes the others' G2P bands from the top
// of their ranges down, each range's highest included, and each band is
// visited once. Thread 0 holds its first band until thread 1 has left the
// phase, so what thread 1 takes is fixed.
TEST(Bands, GatherSharesTheBandsOfAThreadBehind) {
  sim::World w = banded_world({0, 6, 9});
  std::vector<std::atomic<int>> visits(9), visitor(9);
  std::atomic<bool> holding{false}, left{false};
  const bool two = on_two_threads([&](int t) {
    sim::mark_own_bands(w, sim::BandMark::NodalUpdate);
    if (t == 1)
      while (!holding) sim::spin_pause();
    sim::gather_own_bands(w, [&](int b) {
      ++visits[b];
      visitor[b] = t;
      if (b == 0 && t == 0 && omp_get_num_threads() == 2) {
        holding = true;
        while (!left) sim::spin_pause();
      }
    });
    if (t == 1) left = true;
  });
  if (!two) GTEST_SKIP() << "no team of 2 threads";
  const int expected[9] = {0, 1, 1, 1, 1, 1, 1, 1, 1};
  for (int b = 0; b < 9; ++b) {
    EXPECT_EQ(visits[b], 1) << "band " << b;
    EXPECT_EQ(visitor[b], expected[b]) << "band " << b;
  }
}
