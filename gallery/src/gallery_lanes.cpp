#include "gallery/src/gallery_lanes.hpp"

#include <omp.h>

#include <atomic>
#include <future>

#include "sim/physics/team.hpp"

namespace app::gallery {

namespace {

// The key of the stages a scene shares with others (its gravity stage, as
// Gallery::share_gravity_stage shares it), or of all its stages where it
// shares none: scenes of one key must run on one lane, in order.
std::uint64_t shared_key(sim::Scenario s, bool quick) {
  use_gallery_output(s, quick);
  const std::size_t shared = sim::reusable_stages(s);
  return sim::stage_prefix_key(s, shared > 0 ? shared : s.stages.size());
}

}  // namespace

std::string run_in_lanes(Gallery& g, const std::vector<Job>& jobs) {
  if (jobs.empty()) return "no runs";
  std::vector<std::uint64_t> keys;
  std::size_t finest = 0;
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    keys.push_back(shared_key(jobs[k].scenario, g.quick()));
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
