#include "sim/physics/team.hpp"

#include <dirent.h>
#include <omp.h>
#include <sched.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace sim {

namespace {

std::atomic<bool> following{true};
std::atomic<int> held{0};  // cores kept by CoreHold

// The CPUs this process may run on: its affinity mask, which `taskset` and a
// batch system's cpuset narrow. Counting the machine's online cores instead,
// `taskset -c 0` with 2 threads asked for ran both on one core, at 0.67 of
// one thread's rate (throughput --sizes, 25 k points, issue 17, forty-fifth
// pass). Where OpenMP binds its threads (OMP_PROC_BIND), the calling thread's
// mask is one place, so the CPUs are those of all of OpenMP's places.
struct Cpus {
  cpu_set_t set;
  int count = 0;
  bool every_online = true;  // the mask leaves out no online CPU
};

Cpus usable_cpu_set() {
  Cpus c;
  CPU_ZERO(&c.set);
  if (omp_get_proc_bind() != omp_proc_bind_false && omp_get_num_places() > 0) {
    for (int place = 0; place < omp_get_num_places(); ++place) {
      std::vector<int> ids(static_cast<std::size_t>(omp_get_place_num_procs(place)));
      omp_get_place_proc_ids(place, ids.data());
      for (const int id : ids)
        if (id >= 0 && id < CPU_SETSIZE) CPU_SET(id, &c.set);
    }
  } else if (sched_getaffinity(0, sizeof c.set, &c.set) != 0) {
    c.count = static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
    return c;  // unknown: every online CPU
  }
  c.count = CPU_COUNT(&c.set);
  c.every_online = c.count >= sysconf(_SC_NPROCESSORS_ONLN);
  return c;
}

// Runnable tasks on the whole machine: the fourth field of /proc/loadavg,
// "running/total". -1 where it cannot be read.
int runnable_tasks() {
  std::FILE* f = std::fopen("/proc/loadavg", "r");
  if (!f) return -1;
  double one, five, fifteen;
  int running = -1, total = 0;
  if (std::fscanf(f, "%lf %lf %lf %d/%d", &one, &five, &fifteen, &running, &total) != 5)
    running = -1;
  std::fclose(f);
  return running;
}

// Whether the thread whose /proc stat file is `path` is in state R (running
// or runnable), and the CPU it last ran on (-1 where the file is not read).
bool runnable_thread(const std::string& path, int& cpu) {
  cpu = -1;
  std::FILE* f = std::fopen(path.c_str(), "r");
  if (!f) return false;
  char line[1024];
  const bool read = std::fgets(line, sizeof line, f) != nullptr;
  std::fclose(f);
  if (!read) return false;
  // The state follows the command name, which is in parentheses; the CPU is
  // the 39th field, 36 fields after the state (proc(5)).
  const char* close = std::strrchr(line, ')');
  if (!close || close[1] == '\0' || close[2] == '\0') return false;
  const char* field = close + 2;
  const bool running = *field == 'R';
  for (int k = 0; k < 36 && field; ++k) {
    field = std::strchr(field, ' ');
    if (field) ++field;
  }
  if (field) cpu = std::atoi(field);
  return running;
}

// The threads in state R under /proc/`pid`/task; with `on`, only those that
// last ran on one of its CPUs. -1 where the folder cannot be read.
int runnable_threads(const std::string& pid, const cpu_set_t* on) {
  const std::string tasks = "/proc/" + pid + "/task/";
  DIR* dir = opendir(tasks.c_str());
  if (!dir) return -1;
  int running = 0;
  while (const dirent* entry = readdir(dir)) {
    if (entry->d_name[0] == '.') continue;
    int cpu = -1;
    if (runnable_thread(tasks + entry->d_name + "/stat", cpu) &&
        (!on || (cpu >= 0 && cpu < CPU_SETSIZE && CPU_ISSET(cpu, on))))
      ++running;
  }
  closedir(dir);
  return running;
}

// This process's threads in state R: the one counting, and any worker still
// spinning at OpenMP's barrier.
int own_runnable_threads() { return runnable_threads("self", nullptr); }

// Other processes' threads in state R on the CPUs of `cpus`: every process's
// stat file read, for a mask that leaves out some of the machine, whose
// /proc/loadavg counts tasks this process cannot be held up by. -1 where
// /proc cannot be read. It reads a file a thread: 2.1 ms a count under
// `taskset -c 0` on this project's 2-core VM (88 threads), against 36 us for
// the whole machine's count, so only a team's first count and its
// confirmation take it (team_size); the counts after them are averaged.
int others_runnable_on(const Cpus& cpus) {
  DIR* dir = opendir("/proc");
  if (!dir) return -1;
  const std::string self = std::to_string(getpid());
  int running = 0;
  while (const dirent* entry = readdir(dir)) {
    if (entry->d_name[0] < '0' || entry->d_name[0] > '9' || entry->d_name == self) continue;
    running += std::max(0, runnable_threads(entry->d_name, &cpus.set));
  }
  closedir(dir);
  return running;
}

// CPU time the CPUs of `cpus` have spent on programs (user, nice, system,
// irq, softirq, and steal: time the hypervisor gave to others), from the
// per-CPU lines of /proc/stat, seconds; -1 where it cannot be read.
double cpu_seconds_on(const Cpus& cpus) {
  std::FILE* f = std::fopen("/proc/stat", "r");
  if (!f) return -1;
  unsigned long long sum = 0;
  int found = 0;
  char line[512];
  while (std::fgets(line, sizeof line, f)) {
    int cpu = -1;
    unsigned long long t[8] = {};
    if (std::sscanf(line, "cpu%d %llu %llu %llu %llu %llu %llu %llu %llu", &cpu, &t[0], &t[1],
                    &t[2], &t[3], &t[4], &t[5], &t[6], &t[7]) != 9)
      continue;  // the first line, "cpu  ...", and the lines after the CPUs'
    if (cpu < 0 || cpu >= CPU_SETSIZE || !CPU_ISSET(cpu, &cpus.set)) continue;
    sum += t[0] + t[1] + t[2] + t[5] + t[6] + t[7];
    ++found;
  }
  std::fclose(f);
  const long ticks = sysconf(_SC_CLK_TCK);
  if (found == 0 || ticks <= 0) return -1;
  return static_cast<double>(sum) / static_cast<double>(ticks);
}

double own_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The usable CPUs less `others` that other programs keep busy on them and
// less the cores held, at least 1 and at most omp_get_max_threads(). With
// `others` unknown (negative): the usable CPUs less the cores held, within
// the same bounds.
int cores_left(const Cpus& cpus, int others) {
  const int asked = omp_get_max_threads();
  const int kept = held.load(std::memory_order_relaxed);
  if (cpus.count < 1) return std::clamp(asked - kept, 1, asked);
  return std::clamp(cpus.count - std::max(others, 0) - kept, 1, asked);
}

}  // namespace

int usable_cpus() { return usable_cpu_set().count; }

int busy_cores(double others) {
  return std::max(0, static_cast<int>(std::floor(others + 1.0 - kBusyShare)));
}

int averaged_free_cores(CpuUsage& since) {
  const Cpus cpus = usable_cpu_set();
  const CpuUsage now{cpu_seconds_on(cpus), own_cpu_seconds(), std::chrono::steady_clock::now(),
                     cpus.count};
  const CpuUsage before = since;
  since = now;
  const double seconds = std::chrono::duration<double>(now.at - before.at).count();
  if (now.all < 0 || before.all < 0 || now.at - before.at < kLeastAverage ||
      now.cpus != before.cpus)
    return -1;
  const double others = ((now.all - before.all) - (now.own - before.own)) / seconds;
  return cores_left(cpus, busy_cores(others));
}

int free_cores() {
  const Cpus cpus = usable_cpu_set();
  if (!cpus.every_online) return cores_left(cpus, others_runnable_on(cpus));
  const int all = runnable_tasks(), own = own_runnable_threads();
  if (all < 0 || own < 0) return cores_left(cpus, -1);
  return cores_left(cpus, all - own);
}

int settle_team(Team& team, int asked, int free) {
  const bool first = asked != team.asked;  // no count before at this size
  const int threads = first ? free : std::max(free, team.last_count);
  // Counted again soon: a first count that found a core busy, for a
  // short-lived process, and a busy core seen once, to confirm it.
  team.check_soon = free < (first ? asked : threads);
  team.asked = asked;
  team.last_count = free;
  return threads;
}

CoreHold::CoreHold(int cores) : cores_(cores) { held += cores_; }
CoreHold::~CoreHold() { held -= cores_; }

void follow_free_cores(bool follow) { following = follow; }

int team_size(Team& team) {
  const int asked = omp_get_max_threads();
  if (asked == 1 || !following) return team.threads = asked;
  const auto now = std::chrono::steady_clock::now();
  const auto wait = team.check_soon ? kConfirm : kRecount;
  if (asked != team.asked || now - team.counted >= wait) {
    // A team's first count and its confirmation are instants; the counts
    // after them read the interval since the count before.
    const bool instant = asked != team.asked || team.check_soon;
    const int averaged = averaged_free_cores(team.usage);
    if (instant || averaged < 0) {
      team.threads = settle_team(team, asked, free_cores());
    } else {
      team.threads = team.last_count = averaged;
      team.check_soon = false;
    }
    team.counted = now;
  }
  return team.threads;
}

}  // namespace sim
