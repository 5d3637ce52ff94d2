// What a run will cost, worked out before it starts (`landslide check` prints
// it, `landslide run` prints it at its start): points, grid nodes, the first
// time step, steps, frames, disk, memory and wall time, and the limits past
// which a run is refused unless --allow-long. README.md ("What a run will
// cost") documents every figure and how it was measured.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "sim/run/simulation.hpp"
#include "sim/scene/memory_budget.hpp"

namespace app {

// Measured figures the estimate is built on (README.md, "What a run will
// cost"): peak resident memory of `landslide run` against points and nodes
// (sim/scene/memory_budget.hpp), and the bytes and painting time of a frame.
using sim::kBaseMemoryBytes;
using sim::kBytesPerNode;
using sim::kBytesPerPoint;
constexpr double kVtkBytesPerPoint = 280;      // 268 measured (ASCII .vtu)
constexpr double kFrameBytesPerPixel = 0.3;    // PNG 0.08 measured; GIF copy and videos
constexpr double kPaintSecondsPerPixel = 0.1e-6;  // 0.076-0.084 us measured, painting and encoding
// And per point of a painted frame and field: 61-63 ns measured (a 4 M-point
// square against a 160,000-point one, 18 frames and fields of 1280 x 1180
// px; bench/README.md, "What the estimate is built on").
constexpr double kPaintSecondsPerPoint = 65e-9;
// And per point of a VTK state (ASCII .vtu, 244 bytes a point): 1.3-1.9 us
// measured, a 4 M-point state written in 5.3-7.5 s on 2 threads, most of it
// the kernel's copy of the file into the page cache (bench/README.md, issue
// 17's twenty-fourth pass).
constexpr double kVtkSecondsPerPoint = 2e-6;

// The limits a run is refused past unless --allow-long.
constexpr double kMaxWallSeconds = 4 * 3600.0;
constexpr double kMaxSteps = 2e6;         // 18 times the finest shipped scene's 112,000
constexpr double kMaxDiskBytes = 1024.0 * 1024 * 1024;

struct StageSteps {
  std::string name;
  double steps = 0;
  bool may_end_early = false;  // stop_at_rest: fewer if it comes to rest
};

struct Estimate {
  std::size_t points = 0, nodes = 0;
  double dt = 0;  // the first step's
  std::vector<StageSteps> stages;  // the timed stages still to run
  double steps = 0, point_steps = 0;
  bool may_end_early = false;
  double frames = 0;  // per field
  int frame_width = 0, frame_height = 0;  // full size; the GIF's copy is smaller
  int fields = 0;
  double states = 0;  // VTK states
  double disk_bytes = 0, memory_bytes = 0;
  double point_steps_per_second = 0;  // calibrated now (calibrate)
  // Rows of series.csv: each measures every point (output/series.hpp).
  double rows = 0;
  double row_seconds = 0;  // all of them, with the run's threads
  int threads = 1;
  double wall_seconds = 0;
  // Where memory and disk are checked against what the machine has.
  double available_memory_bytes = 0;  // MemAvailable; 0 if unknown
  double free_disk_bytes = 0;         // on the output's file system; 0 if unknown
};

// What this machine takes, measured on a built-in 7,680-point soil block
// (figures vary from run to run; never assert them):
struct Calibration {
  // Point-steps per second of the GIMP step with the present OpenMP threads,
  // the block stepped for about 0.15 s of wall time.
  double point_steps_per_second = 0;
  // Seconds per point of a row of series.csv (sim::measure_motion and the
  // energy balance's two sums) on one thread: the block is one chunk of
  // sim/run/point_chunks.hpp, whose rows run on one thread.
  double row_seconds_per_point = 0;
};
// Measured once per thread count in a process (a sweep's members share it).
Calibration calibrate();

// The estimate for `sim` as it stands (fresh, or restored), whose frames are
// width x height pixels (0 x 0 when it paints none); `out` locates the disk
// it writes to ("" when unknown). Throws what sim.next_time_step() throws.
Estimate estimate_run(const sim::Simulation& sim, int width, int height,
                      const std::filesystem::path& out, int threads);

void print_estimate(std::ostream& o, const Estimate& e);

// The first limit the estimate passes, as an error message naming the file,
// the figure and the limit; "" if none.
std::string limit_passed(const Estimate& e, const std::string& file);

}  // namespace app
