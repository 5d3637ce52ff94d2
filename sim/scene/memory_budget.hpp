// What a run takes in memory, measured, and the scene sizes the reader
// accepts, worked out from it (issue 17). `landslide run`'s estimate uses
// the same figures (app/estimate.hpp, README.md "What a run will cost").
#pragma once

#include "sim/physics/mohr_coulomb.hpp"

namespace sim {

// Peak resident memory (VmHWM) of `landslide run`.
constexpr double kBaseMemoryBytes = 64e6;  // the process with nothing to simulate
// Per point: 360 B measured for a 9,999,392-point granular column on
// 2 threads (3.35 GiB peak, /usr/bin/time -v; bench/README.md, issue 17's
// nineteenth pass), the watchdog's saved state and the sort into cell order
// included (sim/physics/point_order.hpp: 12 B per point kept, 5 more while
// sorting).
constexpr double kBytesPerPoint = 370;
// Per point once a stage sets a random field: its own cohesion and friction
// angle, the 18 constants of its own Mohr-Coulomb surface that the step
// reads (point_strength.hpp) and the watchdog's saved cohesion and friction
// angle, 176 B held for the run, and for a while the field's values. Measured:
// a 4,000,000-point Mohr-Coulomb square (h = 0.01 m, a 2000 x 2000 lattice
// whose 160 MB draw is the smaller term) with a random friction angle peaked
// 198.5 B per point above the same run without it (2,176,896 against
// 1,401,636 KiB, `landslide run --threads 2` under /usr/bin/time -v, 55
// steps; bench/README.md, issue 17's twenty-second pass). Before the surface
// went into arrays it was held whole and again in the sort's scratch, 545 B
// measured. Counted as 210. Drawing the field takes up to
// field_draw_peak_bytes of its lattice (sim/scene/random_field.hpp), freed
// before the points' strengths are made: a run needs the larger of the two.
// With kMaxLatticeNodes each way, the draw holds both factors and three
// lattice arrays.
constexpr double kBytesPerPointWithField = 210;
// The lattice's correlation matrices are nx by nx and ny by ny doubles.
constexpr double kMaxLatticeNodes = 4000;
constexpr double kMaxFieldDrawBytes =
    sizeof(double) * (2 * kMaxLatticeNodes * kMaxLatticeNodes + 3 * kMaxLatticeNodes * kMaxLatticeNodes);
// Per grid node a step has written: the 11 nodal arrays and 2 flags, 90 B
// (sim/physics/grid.hpp); nodes no point has reached take almost nothing
// (sim/physics/node_array.hpp), so this bounds the grid from above.
constexpr double kBytesPerNode = 100;

// Per point of a run that paints frames, on top of kBytesPerPoint: the frame
// being captured and its bytes on their way to the spill file, then while
// painting the frame read back and the painter's copy of its positions,
// sizes and one field (output/frame_recorder.cpp; the splat's vertex
// buffers hold a fixed batch, render/splat.hpp), and per field painted its
// values. Measured: the 4,000,000-point square above painting 6 frames
// peaked 72.4 B per point above the same run without frames with one field,
// and 90.0 with three (1,679,388 and 1,747,908 against 1,396,392 KiB,
// `landslide run --threads 2` under /usr/bin/time -v; bench/README.md, issue
// 17's twenty-third pass: 152.9 with one field before the frames were read
// in one piece and splatted in batches). Counted as 64 and 9 a field.
constexpr double kBytesPerPaintedPoint = 64;
constexpr double kBytesPerPaintedFieldPoint = 9;
constexpr int kMaxPaintedFields = 8;  // each field of output/frames.hpp once
constexpr double kMostBytesPerPaintedPoint =
    kBytesPerPaintedPoint + kMaxPaintedFields * kBytesPerPaintedFieldPoint;

// The largest scene the reader accepts fits a 24 GB machine at both limits,
// painting every field: the grid at its limit takes 5 GB, and the points the
// rest, rounded down to a whole million. Larger scenes are refused as input
// errors before anything is allocated; the estimate then checks each run
// against the memory the machine has free.
constexpr double kMemoryOfLargestMachine = 24e9;
constexpr double kMaxGridNodes = 50e6;
constexpr double kMaxPoints = 37e6;
static_assert(kBaseMemoryBytes + (kBytesPerPoint + kMostBytesPerPaintedPoint) * kMaxPoints +
                      kBytesPerNode * kMaxGridNodes <=
                  kMemoryOfLargestMachine,
              "the largest scene must fit the machine");
static_assert(kBaseMemoryBytes +
                      (kBytesPerPoint + kMostBytesPerPaintedPoint) * (kMaxPoints + 1e6) +
                      kBytesPerNode * kMaxGridNodes >
                  kMemoryOfLargestMachine,
              "kMaxPoints: the largest whole million that fits");
// A scene with a random field has at most one point per lattice node
// (each starts on a node of its own), kMaxLatticeNodes^2 = 16 M; their own
// strengths outweigh the largest draw, and it all fits the machine too.
constexpr double kMaxPointsWithField = kMaxLatticeNodes * kMaxLatticeNodes;
static_assert(kBytesPerPointWithField * kMaxPointsWithField >= kMaxFieldDrawBytes,
              "a field's largest scene: its points' strengths outweigh its draw");
static_assert(kBaseMemoryBytes +
                      (kBytesPerPoint + kBytesPerPointWithField + kMostBytesPerPaintedPoint) *
                          kMaxPointsWithField +
                      kBytesPerNode * kMaxGridNodes <=
                  kMemoryOfLargestMachine,
              "the largest scene with a field must fit the machine");

}  // namespace sim
