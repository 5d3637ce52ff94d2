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
//
// A count is one instant: a short-lived process (a shell's grep, a kernel
// thread) caught running there cost the whole next kRecount on one thread.
// The team therefore takes the larger of the last two counts, so that it
// gives up a core only to a process seen at two counts in a row (kConfirm
// apart) and takes it back at the first count that finds it free. A
// departure of this program's own, not a published rule. In the gallery's
// paper figures with a shell polling its log twice a second, 4.7 and 6.2 %
// of the steps ran on one thread under the single count and 1.5 % under
// this rule; with a busy loop on one core 2 threads still ran at 0.96-0.99
// of 1 thread (issue 17, nineteenth pass, bench/README.md).
//
// Those counts still see tasks of a moment. On this project's machine (a
// Firecracker VM) /proc/loadavg counted one runnable task more than /proc
// held in state R at many counts beside a 6.5 M-point step, and the rule
// above put 5 to 10 of the 20 steps of `throughput --sizes`' 2-thread run at
// that size on one thread (three runs), at 60 to 106 ns a point-step where
// two threads took 33 to 61. So every count after a team's first (and its
// confirmation) reads the CPU time other programs used since the count
// before instead (averaged_free_cores): a busy loop uses a core's worth of
// it, a task of a moment next to nothing. Also a departure of this program's
// own.
//
// The first count of a team has no count before it, and is taken as it is:
// a core found busy there is given up at once and counted again kConfirm
// later, in case the process was short-lived. Settled with the threads
// asked for instead (until issue 17's thirty-third pass), a run started
// beside a busy loop took its first kConfirm on two threads, one of them
// waiting for the core the loop held, and OpenMP's idle worker then spun
// for its block time beside both: the first 200 steps of the 25 k-point
// column took 7.7 to 26.4 ms more than on one thread, and about as long
// after (throughput --busy-start, bench/README.md).
#pragma once

#include <chrono>

namespace sim {

constexpr std::chrono::milliseconds kRecount{200};
// How soon a count that found a core busy is checked by the next: the team
// keeps the core this long while a new process is confirmed, not kRecount.
constexpr std::chrono::milliseconds kConfirm{20};
// The shortest interval an averaged count reads: /proc/stat counts CPU time
// in ticks of 10 ms, so that a count over 100 ms on 2 cores is good to about
// 0.1 of a core.
constexpr std::chrono::milliseconds kLeastAverage{100};
// The share of a core that other programs must use on average over a count's
// interval for it to count as theirs. On this project's 2-core machine, over
// 200 ms: 2 threads alone read -0.03 to 0.10 cores used by others; beside a
// busy loop of the same session, which takes a third of each core, 0.44 to
// 1.00; 1 thread beside it 0.95 to 1.09 (issue 17, forty-third pass).
constexpr double kBusyShare = 0.35;

// The CPU time every program and this process had used at one instant: the
// start of the interval an averaged count reads.
struct CpuUsage {
  double all = -1, own = 0;  // seconds; all < 0: none taken yet
  std::chrono::steady_clock::time_point at{};
  int cpus = 0;  // the usable CPUs `all` sums over
};

struct Team {
  int asked = 0;    // omp_get_max_threads() when last counted
  int threads = 0;  // the team's size since then: the last step's
  int last_count = 0;  // free_cores() at the count before
  bool check_soon = false;  // count again after kConfirm, not kRecount
  std::chrono::steady_clock::time_point counted{};
  CpuUsage usage;  // at the last count
};

// The CPUs this process may run on (its affinity mask: taskset, a batch
// system's cpuset) less the runnable threads of other processes there and
// less the cores held (CoreHold), at least 1 and at most
// omp_get_max_threads(). Where the mask holds every online CPU, the
// runnable threads are the running-task count of /proc/loadavg less this
// process's threads in state R; where it leaves some out, the other
// processes' threads in state R that last ran on one of its CPUs. Where
// /proc cannot be read, the usable CPUs less the cores held.
int free_cores();

// The CPUs this process may run on: its affinity mask's (taskset, a batch
// system's cpuset), or every OpenMP place's where OpenMP binds its threads.
// The team never has more threads than these.
int usable_cpus();

// The cores other programs take, from the cores' worth of CPU time they
// used on average (kBusyShare above): 0.3 is none, 0.67 one.
int busy_cores(double others);

// The usable CPUs less the cores other programs kept busy on average since
// `since` (the CPU time of those CPUs in /proc/stat less this process's),
// less the cores held, at least 1 and at most omp_get_max_threads(); -1
// where /proc/stat cannot be read or less than kLeastAverage has passed.
// `since` becomes now.
int averaged_free_cores(CpuUsage& since);

// The team's size after a count that found `free` of `asked` cores: the
// larger of it and the count before (see above), or `free` itself where the
// threads asked for changed.
int settle_team(Team& team, int asked, int free);

// free_cores(), counted again when kRecount has passed (kConfirm after a
// count that found fewer cores than the team has) or the threads asked for
// changed, and settled with the count before; 1 without counting when 1
// thread is asked for. With follow_free_cores(false), omp_get_max_threads()
// always.
int team_size(Team& team);

// Cores this process keeps busy beside the team: while a CoreHold lives,
// every team that follows the free cores counts its cores as taken by
// another program. The gallery runs its finest scene on one lane and the
// others on a second of one thread; that thread is one of this process's,
// which free_cores() leaves out of its count, so without the hold the finest
// scene would take both cores beside it.
class CoreHold {
 public:
  explicit CoreHold(int cores);
  ~CoreHold();
  CoreHold(const CoreHold&) = delete;
  CoreHold& operator=(const CoreHold&) = delete;

 private:
  int cores_;
};

// For the whole process (default true). The tests that compare thread
// counts turn it off, so that "2 threads" means two even on a loaded machine.
void follow_free_cores(bool follow);

}  // namespace sim
