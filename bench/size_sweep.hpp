// Issue 17's size sweep of bench/throughput (`throughput --sizes`): the
// granular column from 25 k to 6.5 M points, 1 and 2 threads, against a
// STREAM-like triad measured in the same run.
#pragma once

#include <sys/types.h>

#include "sim/physics/step.hpp"

namespace bench {

// One row of the sweep: the granular column at `refine` (granular_column.hpp)
// and its step input, the time step the Courant number gives at rest.
struct Row {
  sim::World world;
  sim::StepInput input;
};
Row make_row(int refine);
// Two untimed steps on one thread that size the scratch arrays, and the time
// loop's first sort into cell order (sim/physics/point_order.hpp), which sizes
// its own.
void warm_up(Row& row);

// argv after "--sizes"; returns the exit status.
int size_sweep(int argc, char** argv);
// The child of one row's peak-RSS measurement: prints its VmHWM in bytes.
int size_sweep_rss_child(int refine);
// A child process that spins on one core until killed (--busy, --busy-start).
pid_t start_busy_loop();
// argv after "--busy-start" (bench/busy_start.cpp); returns the exit status.
int busy_start(int argc, char** argv);

}  // namespace bench
