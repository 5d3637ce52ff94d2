// The one check before a run: `landslide check` runs it and stops, `run` and
// `resume` run it and go on with what it set up, so whatever `run` would
// refuse, `check` refuses first with the same message (exit 2).
#pragma once

#include <filesystem>
#include <memory>
#include <ostream>
#include <string>

#include "output/checkpoint.hpp"
#include "app/estimate.hpp"
#include "output/frames.hpp"
#include "sim/run/simulation.hpp"

namespace app {

struct PreflightRequest {
  // Must outlive the result: the recorder keeps a reference to it.
  const sim::Scenario* scenario = nullptr;
  std::string scenario_file;
  std::filesystem::path out;          // "": not checked (`check` without --out)
  std::filesystem::path state_cache;  // "": none
  const Checkpoint* checkpoint = nullptr;  // `resume`: restore it (out holds the run)
  bool overwrite = false;   // an earlier run's outputs in out are to be removed
  bool allow_long = false;  // run past the estimate's limits (app/estimate.hpp)
  int threads = 1;          // OpenMP threads, for the estimate's step rate
};

// What the run goes on with.
struct Prepared {
  std::unique_ptr<FrameRecorder> recorder;      // null: the scene paints nothing
  std::unique_ptr<sim::Simulation> simulation;  // seeded, restored where asked
  std::size_t reused_stages = 0;                // from the state cache
  Estimate estimate;
};

// What the preflight found, unprinted: a sweep (sweep/) names its member in
// front of the message, so the message is handed back rather than printed.
struct Verdict {
  std::string refusal;  // "": the run may go on; else the one-line message
  std::string warning;  // the limit --allow-long let the estimate pass ("" if none)
};

// In order: the output folder (a file, not writable, or an earlier run's
// outputs without --overwrite) and the state cache; ffmpeg and the painter,
// and frames of image_size laid out (too small for their annotations);
// seeding (a body holding no point) and the checkpoint or cached state;
// the first time step (a fixed one above the stable bound); the estimate,
// printed to `estimate_out`, against its limits. Writes nothing, prints
// nothing but the estimate. `prepared` is emptied on a refusal.
Verdict preflight_verdict(const PreflightRequest& request, Prepared& prepared,
                          std::ostream& estimate_out);

// preflight_verdict, its warning printed as "warning: ..." and its refusal as
// "error: ..." (one line each) on stderr; false on a refusal.
bool preflight(const PreflightRequest& request, Prepared& prepared, std::ostream& estimate_out);

// Puts the OpenMP threads asked for (0: OpenMP's default) in force before the
// preflight calibrates the step rate with them; returns the threads now in force.
int use_threads(int asked);

}  // namespace app
