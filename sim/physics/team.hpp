// How many threads the step's team gets.
//
// The step's phases meet at barriers (sim/physics/bands.hpp). A thread that
// another program has pushed off its core holds every other thread at the
// next barrier for a whole scheduler slice, so on a 2-core machine with one
// busy core a 2-thread run fell to 0.54-0.91 of the same binary's 1-thread
// rate (bench/throughput --sizes --busy, issue 17). The team therefore takes
// no more threads than the cores other programs leave free, counted from
// the kernel's runnable tasks, and looks again every kRecount of wall time.
// Results do not depend on the number of threads (bands.hpp), so the count
// may change from step to step.
#pragma once

#include <chrono>

namespace sim {

constexpr std::chrono::milliseconds kRecount{200};

struct Team {
  int asked = 0;    // omp_get_max_threads() when last counted
  int threads = 0;  // the team's size since then
  std::chrono::steady_clock::time_point counted{};
};

// Online cores less the runnable threads of other processes (the
// running-task count of /proc/loadavg less this process's threads in state
// R), at least 1 and at most omp_get_max_threads(). Where /proc cannot be
// read, omp_get_max_threads().
int free_cores();

// free_cores(), counted again when kRecount has passed or the threads asked
// for changed; 1 without counting when 1 thread is asked for. With
// follow_free_cores(false), omp_get_max_threads() always.
int team_size(Team& team);

// For the whole process (default true). The tests that compare thread
// counts turn it off, so that "2 threads" means two even on a loaded machine.
void follow_free_cores(bool follow);

}  // namespace sim
