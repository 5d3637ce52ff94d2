// The gallery's runs on two lanes at once (issue 17, forty-first pass).
//
// The paper's study is one scene of 66,787 points and six of 1,661 to 28,711.
// Run one after another on 2 threads, the small ones took the second core
// for little: the 8,370-point slope ran 1.4 to 1.6 times as fast on 2
// threads as on one, the 66,787-point slope 1.7 to 1.9 times (bench/phases
// --whole-step, three rounds). So the finest scene and the scenes that
// share its gravity stage take the first lane, on the process's threads,
// and the rest take a second, one thread, one scene after another. While
// the second lane has work it holds a core (sim::CoreHold), so the first
// lane's team runs one thread beside it and takes the second core back
// within a count (sim/physics/team.hpp) of the lane's end. The runs' results do not depend on their thread counts, so
// every figure is byte for byte what runs one after another paint.
//
// Measured before it was written, with `landslide run` in two processes of
// the scenes the gallery runs (no frames; the two processes' teams count
// each other), 2 threads, in turns: one after another 159.9 and 149.6 s,
// two lanes 140.4 and 140.5 s (bench/README.md, forty-first pass).
#pragma once

#include <vector>

#include "gallery/src/gallery_runs.hpp"

namespace app::gallery {

struct Job {
  sim::Scenario scenario;
  bool animate = false;  // as Gallery::run
};

// Runs every job through g.run(), in the order given within each lane; a
// later g.run() of any of them returns the kept result. One lane, in order,
// where the process has one thread or every job shares the finest one's
// gravity stage (every scene under --quick). A run that throws stops the
// other lane's run at its next step and is rethrown. Returns what it
// printed of the lanes, for the gallery's timing line.
std::string run_in_lanes(Gallery& g, const std::vector<Job>& jobs);

}  // namespace app::gallery
