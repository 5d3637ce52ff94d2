// Sums and extremes over the points for the diagnostics (series rows, the
// energy balance, the runout), on the threads of the run but with results
// that do not depend on how many there are.
//
// The points are cut into chunks of a fixed kChunkPoints, whatever the
// thread count; each chunk is reduced in point order into its own
// accumulator, and the accumulators are combined in chunk order. A scene of
// at most kChunkPoints points is one chunk: its sums are the serial loop's
// bit for bit (0 + s is s), so every shipped scene, regression file and
// gallery figure keeps its numbers. Larger scenes sum chunk by chunk, a
// different order from a single loop, the same at any number of threads.
//
// Why: one row of series.csv measured the 6.5 M-point column in 412 ms on
// one thread's loops while the other waited, 63 ns per point, more than the
// step itself (31 ns per point on 2 threads), and a stage without frames
// takes a row every 1/100 of its duration (bench/series_rows.cpp, issue 17).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace sim {

constexpr std::size_t kChunkPoints = std::size_t(1) << 17;  // 131,072

inline std::size_t point_chunks(std::size_t points) {
  return (points + kChunkPoints - 1) / kChunkPoints;
}

// visit(acc, begin, end) reduces points [begin, end) into `acc`, a copy of
// `start` per chunk; combine(total, acc) adds a chunk's result to the total,
// which starts as `start`. Both run on the calling process's OpenMP threads.
template <class Acc, class Visit, class Combine>
Acc reduce_points(std::size_t points, const Acc& start, Visit visit, Combine combine) {
  const long chunks = static_cast<long>(point_chunks(points));
  std::vector<Acc> partial(static_cast<std::size_t>(chunks), start);
#pragma omp parallel for schedule(dynamic, 1) if (chunks > 1)
  for (long c = 0; c < chunks; ++c) {
    const std::size_t begin = static_cast<std::size_t>(c) * kChunkPoints;
    visit(partial[static_cast<std::size_t>(c)], begin, std::min(points, begin + kChunkPoints));
  }
  Acc total = start;
  for (const Acc& a : partial) combine(total, a);
  return total;
}

// A sum of f(p) over the points, in chunks as above.
template <class F>
double sum_over_points(std::size_t points, F f) {
  return reduce_points(
      points, 0.0,
      [&](double& sum, std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) sum += f(p);
      },
      [](double& total, double part) { total += part; });
}

// f(p) for every point p, in parallel: a map, whose result does not depend
// on the order.
template <class F>
void for_each_point(std::size_t points, F f) {
  const long n = static_cast<long>(points);
#pragma omp parallel for schedule(static) if (points > kChunkPoints)
  for (long p = 0; p < n; ++p) f(static_cast<std::size_t>(p));
}

}  // namespace sim
