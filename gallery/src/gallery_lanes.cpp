#include "gallery/src/gallery_lanes.hpp"

#include <omp.h>

#include <exception>
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
  // A lane that fails stops the other's run between two steps, so its error
  // is reported at once, not after the other lane's run (up to a minute and
  // a half for the finest scene) has ended.
  const auto lane = [&](const std::vector<const Job*>& list) {
    try {
      for (const Job* j : list)
        if (!g.stopping()) g.run(j->scenario, j->animate);
    } catch (const RunsStopped&) {
      // the other lane's error is the one to report
    } catch (...) {
      g.stop_runs();
      throw;
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
    lane(second);
  });
  std::exception_ptr failed;
  try {
    lane(first);
  } catch (...) {
    failed = std::current_exception();
  }
  try {
    beside.get();
  } catch (...) {
    if (!failed) failed = std::current_exception();
  }
  if (failed) std::rethrow_exception(failed);
  return "two lanes: h = " + fmt(jobs[finest].scenario.cell_size, 3) + " m on " +
         std::to_string(threads) + " threads, one less while the other scenes ran on one";
}

}  // namespace app::gallery
