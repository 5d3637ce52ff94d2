// What a run takes in memory, measured, and the scene sizes the reader
// accepts, worked out from it (issue 17). `landslide run`'s estimate uses
// the same figures (app/estimate.hpp, README.md "What a run will cost").
#pragma once

namespace sim {

// Peak resident memory (VmHWM) of `landslide run`.
constexpr double kBaseMemoryBytes = 64e6;  // the process with nothing to simulate
// Per point: 389 B measured for a 10,000,000-point granular column on
// 2 threads (3.86 GB peak, /usr/bin/time -v; bench/README.md), the
// watchdog's saved state included. Points with a random field hold their
// own Mohr-Coulomb surface on top (sim/physics/point_strength.hpp).
constexpr double kBytesPerPoint = 400;
// Per grid node a step has written: the 11 nodal arrays and 2 flags, 90 B
// (sim/physics/grid.hpp); nodes no point has reached take almost nothing
// (sim/physics/node_array.hpp), so this bounds the grid from above.
constexpr double kBytesPerNode = 100;

// The largest scene the reader accepts fits a 24 GB machine at both limits:
// the grid at its limit takes 5 GB, and the points the rest, rounded down to
// a whole million. Larger scenes are refused as input errors before anything
// is allocated; the estimate then checks each run against the memory the
// machine has free.
constexpr double kMemoryOfLargestMachine = 24e9;
constexpr double kMaxGridNodes = 50e6;
constexpr double kMaxPoints = 47e6;
static_assert(kBaseMemoryBytes + kBytesPerPoint * kMaxPoints + kBytesPerNode * kMaxGridNodes <=
                  kMemoryOfLargestMachine,
              "the largest scene must fit the machine");
static_assert(kBaseMemoryBytes + kBytesPerPoint * (kMaxPoints + 1e6) +
                      kBytesPerNode * kMaxGridNodes > kMemoryOfLargestMachine,
              "kMaxPoints: the largest whole million that fits");

}  // namespace sim
