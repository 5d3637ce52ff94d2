#include "gallery/src/gallery_lanes.hpp"

#include <omp.h>

#include <atomic>
#include <future>

#include "sim/physics/team.hpp"

namespace app::gallery {

std::string run_in_lanes(Gallery& g, const std::vector<Job>& jobs) {
  if (jobs.empty()) return "no runs";
  std::vector<std::uint64_t> keys;
  std::size_t finest = 0;
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    sim::Scenario s = jobs[k].scenario;
    use_gallery_output(s, g.quick());  // as Gallery::run will run it
    keys.push_back(shared_stages_key(s));
    if (jobs[k].scenario.cell_size < jobs[finest].scenario.cell_size) finest = k;
  }
  std::vector<const Job*> first, second;
  for (std::size_t k = 0; k < jobs.size(); ++k)
    (keys[k] == keys[finest] ? first : second).push_back(&jobs[k]);
  const int threads = omp_get_max_threads();
  std::atomic<bool> stop{false};
  const auto lane = [&](const std::vector<const Job*>& list) {
    for (const Job* j : list) {
      if (stop) return;
      g.run(j->scenario, j->animate);
    }
  };
  if (threads < 2 || second.empty()) {
    lane(first);
    lane(second);
    return "one lane";
  }
  std::future<void> beside = std::async(std::launch::async, [&] {
    omp_set_num_threads(1);  // this thread's own setting: the first lane keeps its own
    const sim::CoreHold hold(1);
    try {
      lane(second);
    } catch (...) {
      stop = true;
      throw;
    }
  });
  try {
    lane(first);
  } catch (...) {
    stop = true;
    beside.wait();
    throw;
  }
  beside.get();
  return "two lanes: h = " + fmt(jobs[finest].scenario.cell_size, 3) + " m on " +
         std::to_string(threads) + " threads, one less while the other scenes ran on one";
}

}  // namespace app::gallery
