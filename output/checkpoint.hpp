// A run's checkpoint, DIR/checkpoint.lsck: everything `landslide resume DIR`
// needs to finish the run as if it had never stopped. One file, written
// under a temporary name and renamed, so a kill at any moment leaves either
// the previous checkpoint or the new one.
//
//   the scenario's text and file name   (the run does not depend on the file
//                                        still being there, or unchanged)
//   the run's own bookkeeping (JSON)    VTK files listed so far, PNGs written
//   the simulation state                sim::Simulation::save_state()
//   the frames captured but not painted: their numbers and stages, and the
//                                        extent of all captured frames (the
//                                        frames themselves are the files in
//                                        DIR/.frames-pending/, which a run
//                                        keeps until it paints them)
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "output/frames.hpp"

namespace app {

struct Checkpoint {
  std::string scenario_text;
  std::string scenario_file;  // as given to `landslide run`, for messages
  nlohmann::json run;         // the observer's bookkeeping
  std::string state;          // sim::Simulation::save_state()
  std::vector<PendingFrame> frames;  // captured and spilled, not yet painted
  Extent extent;                     // of every frame captured so far
};

std::filesystem::path checkpoint_path(const std::filesystem::path& out_dir);

void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c);
// Throws sim::StateError naming the file if it is missing, truncated or not
// a checkpoint of this build.
Checkpoint read_checkpoint(const std::filesystem::path& file);

}  // namespace app
