// The step's team (sim/physics/team.hpp): never more threads than asked for,
// never fewer than one, and one core fewer while another process spins or
// this one holds a core.
#include <gtest/gtest.h>
#include <omp.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "sim/physics/team.hpp"

namespace {

// A process that spins until stopped, on CPU `cpu` alone where one is
// named; -1 where it cannot be forked.
pid_t start_spinning(int cpu = -1) {
  const pid_t busy = fork();
  if (busy == 0) {
    if (cpu >= 0) {
      cpu_set_t only;
      CPU_ZERO(&only);
      CPU_SET(cpu, &only);
      sched_setaffinity(0, sizeof only, &only);
    }
    volatile unsigned long spin = 0;
    for (;;) ++spin;
  }
  return busy;
}

// Runs `work` with the calling thread's affinity mask set to `cpus`, then
// gives the thread its mask back.
template <typename Work>
void on_cpus(std::initializer_list<int> cpus, Work work) {
  cpu_set_t before, only;
  ASSERT_EQ(sched_getaffinity(0, sizeof before, &before), 0);
  CPU_ZERO(&only);
  for (const int c : cpus) CPU_SET(c, &only);
  ASSERT_EQ(sched_setaffinity(0, sizeof only, &only), 0);
  work();
  sched_setaffinity(0, sizeof before, &before);
}

void stop(pid_t busy) {
  kill(busy, SIGKILL);
  waitpid(busy, nullptr, 0);
}

TEST(Team, OneThreadAskedForIsOne) {
  omp_set_num_threads(1);
  sim::Team team;
  EXPECT_EQ(sim::team_size(team), 1);
}

TEST(Team, BetweenOneAndTheThreadsAskedFor) {
  for (int asked : {2, 3, 8}) {
    omp_set_num_threads(asked);
    const int free = sim::free_cores();
    EXPECT_GE(free, 1) << asked;
    EXPECT_LE(free, asked) << asked;
  }
}

TEST(Team, ABusyProcessTakesACore) {
  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
  if (cores < 2) GTEST_SKIP() << "one core: nothing to give up";
  omp_set_num_threads(static_cast<int>(cores));
  const pid_t busy = start_spinning();
  ASSERT_GE(busy, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const int free = sim::free_cores();
  stop(busy);
  EXPECT_LT(free, cores) << "a process spinning beside this one left all " << cores
                         << " cores counted free";
}

// The averaged count (team.hpp): a process that spins through the interval
// used a core's worth of CPU time, and takes a core.
TEST(Team, ABusyProcessTakesACoreOnAverage) {
  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
  if (cores < 2) GTEST_SKIP() << "one core: nothing to give up";
  omp_set_num_threads(static_cast<int>(cores));
  sim::CpuUsage since;
  EXPECT_EQ(sim::averaged_free_cores(since), -1) << "no interval before the first reading";
  EXPECT_EQ(sim::averaged_free_cores(since), -1) << "an interval shorter than kLeastAverage";
  const pid_t busy = start_spinning();
  ASSERT_GE(busy, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const int free = sim::averaged_free_cores(since);
  stop(busy);
  EXPECT_GE(free, 1);
  EXPECT_LT(free, cores) << "a process spinning for 300 ms left all " << cores
                         << " cores counted free";
}

// `taskset -c 0` (or a batch system's cpuset of one CPU) leaves one core,
// however many the machine has online and however many threads are asked:
// two threads there took turns on it at 0.67 of one's rate.
TEST(Team, TheAffinityMaskBoundsTheTeam) {
  omp_set_num_threads(2);
  on_cpus({sched_getcpu()}, [] {
    EXPECT_EQ(sim::free_cores(), 1);
    sim::CpuUsage since;
    EXPECT_EQ(sim::averaged_free_cores(since), -1);
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    EXPECT_EQ(sim::averaged_free_cores(since), 1);
    sim::Team team;
    EXPECT_EQ(sim::team_size(team), 1);
  });
}

// Within a mask, only the processes on its CPUs take a core: a busy loop on
// a CPU outside it takes none. Needs three CPUs (a mask of two and one
// outside it).
TEST(Team, OnlyBusyCpusInTheMaskCount) {
  if (sysconf(_SC_NPROCESSORS_ONLN) < 3) GTEST_SKIP() << "fewer than three CPUs";
  omp_set_num_threads(2);
  on_cpus({0, 1}, [] {
    for (const int cpu : {1, 2}) {
      const pid_t busy = start_spinning(cpu);
      ASSERT_GE(busy, 0);
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      sim::CpuUsage since;
      sim::averaged_free_cores(since);
      const int instant = sim::free_cores();
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
      const int averaged = sim::averaged_free_cores(since);
      stop(busy);
      const int expected = cpu == 1 ? 1 : 2;
      EXPECT_EQ(instant, expected) << "a busy loop on CPU " << cpu << ", the mask {0, 1}";
      EXPECT_EQ(averaged, expected) << "a busy loop on CPU " << cpu << ", the mask {0, 1}";
    }
  });
}

// Other programs' average use, in cores, to the cores they take: a core
// only from kBusyShare of one on.
TEST(Team, BusyCoresFromAverageUse) {
  EXPECT_EQ(sim::busy_cores(-0.05), 0) << "round-off of the ticks";
  EXPECT_EQ(sim::busy_cores(0.10), 0) << "tasks of a moment";
  EXPECT_EQ(sim::busy_cores(sim::kBusyShare - 0.01), 0);
  EXPECT_EQ(sim::busy_cores(sim::kBusyShare), 1);
  EXPECT_EQ(sim::busy_cores(0.67), 1) << "a busy loop sharing two cores with two threads";
  EXPECT_EQ(sim::busy_cores(1.0), 1) << "a busy loop on a core of its own";
  EXPECT_EQ(sim::busy_cores(1.0 + sim::kBusyShare), 2);
}

// A core this process holds for other work (the gallery's second lane) is
// a busy core to every team of the process, however idle the machine.
TEST(Team, AHeldCoreIsBusy) {
  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
  if (cores < 2) GTEST_SKIP() << "one core: nothing to hold";
  omp_set_num_threads(static_cast<int>(cores));
  const sim::CoreHold hold(1);
  EXPECT_LE(sim::free_cores(), cores - 1);
  const sim::CoreHold all_but_one(static_cast<int>(cores) - 2);
  EXPECT_EQ(sim::free_cores(), 1);
}

// A busy core seen at one count alone (a short-lived process) leaves the
// team as it was; seen at two counts in a row it takes a thread away; a
// core found free again gives it back at once.
TEST(Team, GivesUpACoreOnlyToTwoCountsInARow) {
  sim::Team team;
  EXPECT_EQ(sim::settle_team(team, 2, 2), 2);
  EXPECT_EQ(sim::settle_team(team, 2, 1), 2) << "one count of a busy core";
  EXPECT_EQ(sim::settle_team(team, 2, 2), 2);
  EXPECT_EQ(sim::settle_team(team, 2, 1), 2);
  EXPECT_EQ(sim::settle_team(team, 2, 1), 1) << "two counts in a row";
  EXPECT_EQ(sim::settle_team(team, 2, 1), 1);
  EXPECT_EQ(sim::settle_team(team, 2, 2), 2) << "the core free again";
}

// The first count after the threads asked for change has no count before:
// it is taken as it is, and counted again soon where it found a core busy,
// so that a short-lived process costs a thread only until then.
TEST(Team, FirstCountIsTakenAsItIs) {
  sim::Team team;
  EXPECT_EQ(sim::settle_team(team, 2, 1), 1) << "the first count of a busy core";
  EXPECT_TRUE(team.check_soon) << "a first count short of the threads asked is checked soon";
  EXPECT_EQ(sim::settle_team(team, 2, 2), 2) << "free at the next count: a short-lived process";
  EXPECT_FALSE(team.check_soon);
  EXPECT_EQ(sim::settle_team(team, 3, 1), 1) << "the first count at another size";
  EXPECT_EQ(sim::settle_team(team, 3, 1), 1) << "confirmed";
  EXPECT_FALSE(team.check_soon) << "a confirmed count waits kRecount";
  EXPECT_EQ(sim::settle_team(team, 3, 3), 3) << "the cores free again";
  EXPECT_EQ(sim::settle_team(team, 3, 2), 3) << "one count of a busy core";
  EXPECT_TRUE(team.check_soon) << "is confirmed soon";
}

TEST(Team, FixedWhenNotFollowingFreeCores) {
  omp_set_num_threads(2);
  sim::follow_free_cores(false);
  sim::Team team;
  EXPECT_EQ(sim::team_size(team), 2);
  sim::follow_free_cores(true);
}

}  // namespace
