#include "sim/physics/team.hpp"

#include <dirent.h>
#include <omp.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <string>

namespace sim {

namespace {

std::atomic<bool> following{true};
std::atomic<int> held{0};  // cores kept by CoreHold

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

// This process's threads in state R (running or runnable): the one counting,
// and any worker still spinning at OpenMP's barrier.
int own_runnable_threads() {
  DIR* dir = opendir("/proc/self/task");
  if (!dir) return -1;
  int running = 0;
  while (const dirent* entry = readdir(dir)) {
    if (entry->d_name[0] == '.') continue;
    const std::string path = std::string("/proc/self/task/") + entry->d_name + "/stat";
    std::FILE* f = std::fopen(path.c_str(), "r");
    if (!f) continue;
    char line[512];
    if (std::fgets(line, sizeof line, f)) {
      // The state follows the command name, which is in parentheses.
      const std::string text = line;
      const std::size_t close = text.rfind(')');
      if (close != std::string::npos && close + 2 < text.size() && text[close + 2] == 'R') ++running;
    }
    std::fclose(f);
  }
  closedir(dir);
  return running;
}

// CPU time every core has spent on programs (user, nice, system, irq,
// softirq, and steal: time the hypervisor gave to others), from the first
// line of /proc/stat, seconds; -1 where it cannot be read.
double all_cpu_seconds() {
  std::FILE* f = std::fopen("/proc/stat", "r");
  if (!f) return -1;
  unsigned long long t[8] = {};
  const int read = std::fscanf(f, "cpu %llu %llu %llu %llu %llu %llu %llu %llu", &t[0], &t[1],
                               &t[2], &t[3], &t[4], &t[5], &t[6], &t[7]);
  std::fclose(f);
  const long ticks = sysconf(_SC_CLK_TCK);
  if (read != 8 || ticks <= 0) return -1;
  return static_cast<double>(t[0] + t[1] + t[2] + t[5] + t[6] + t[7]) / static_cast<double>(ticks);
}

double own_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The online cores less `others` that other programs keep busy and less the
// cores held, at least 1 and at most omp_get_max_threads(). With `others`
// unknown (negative) or the online cores unknown: the threads asked for less
// the cores held, as far as 1.
int cores_left(int others) {
  const int asked = omp_get_max_threads();
  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
  const int kept = held.load(std::memory_order_relaxed);
  if (others < 0 || cores < 1) return std::clamp(asked - kept, 1, asked);
  return static_cast<int>(std::clamp<long>(cores - others - kept, 1, asked));
}

}  // namespace

int busy_cores(double others) {
  return std::max(0, static_cast<int>(std::floor(others + 1.0 - kBusyShare)));
}

int averaged_free_cores(CpuUsage& since) {
  const CpuUsage now{all_cpu_seconds(), own_cpu_seconds(), std::chrono::steady_clock::now()};
  const CpuUsage before = since;
  since = now;
  const double seconds = std::chrono::duration<double>(now.at - before.at).count();
  if (now.all < 0 || before.all < 0 || now.at - before.at < kLeastAverage) return -1;
  const double others = ((now.all - before.all) - (now.own - before.own)) / seconds;
  return cores_left(busy_cores(others));
}

int free_cores() {
  const int all = runnable_tasks(), own = own_runnable_threads();
  if (all < 0 || own < 0) return cores_left(-1);
  return cores_left(std::max(0, all - own));
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
