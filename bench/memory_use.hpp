// What the solver's state takes: the bytes its vectors hold, and the
// process's peak resident set.
#pragma once

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "sim/physics/world.hpp"

namespace bench {

template <typename T, typename A>
double bytes(const std::vector<T, A>& v) {
  return static_cast<double>(v.capacity() * sizeof(T));
}

// Bytes the solver's state takes: every std::vector in the world (the
// points' through sim::for_each_point_array; keep the rest in step with
// sim/physics/world.hpp and grid.hpp), the grid's
// arrays counted over the window of nodes the last step touched, as only
// the pages a step writes take memory (sim/physics/node_array.hpp). The
// grid's share goes to `grid`.
inline double vector_bytes(const sim::World& w, double* grid) {
  double points = 0;
  sim::for_each_point_array(w, [&](const auto& v) { points += bytes(v); });
  const sim::Grid& g = w.grid;
  double per_node = 2 * sizeof(std::uint8_t);  // fix_x, fix_y
  for (const auto* v : {&g.mass, &g.px, &g.py, &g.vx, &g.vy, &g.fx, &g.fy, &g.ax, &g.ay,
                        &g.held_ax, &g.held_ay, &g.wall_gap_x, &g.wall_gap_y, &g.wall_impulse_x,
                        &g.wall_impulse_y})
    if (!v->empty()) per_node += sizeof(double);
  const double window = double(g.i_end - g.i_begin) * double(g.j_end - g.j_begin);
  const double nodes = per_node * window + bytes(g.row_sums);
  const double scratch = bytes(w.weights) + bytes(w.bin_key) + bytes(w.order) +
                         bytes(w.band_start) + bytes(w.thread_counts) + bytes(w.thread_window) +
                         bytes(w.thread_totals) + bytes(w.thread_bands) + bytes(w.band_sums) +
                         bytes(w.material_specs) + bytes(w.materials) + bytes(w.scene_index) +
                         bytes(w.sort_scratch) + bytes(w.sort_scratch_bytes) +
                         bytes(w.sort_scratch_ints);
  if (grid) *grid = nodes;
  return points + nodes + scratch;
}

// Peak resident set of this process, bytes: VmHWM of /proc/self/status. It
// belongs to the process's own memory map, so a child does not inherit its
// parent's peak through the spawn (wait4's ru_maxrss does: a vfork-style
// spawn runs on the parent's map until exec, and exec keeps that map's peak).
inline double own_peak_rss() {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return NAN;
  char line[256];
  double kib = NAN;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, "VmHWM: %lf kB", &kib) == 1) break;
  std::fclose(f);
  return kib * 1024.0;
}

// Peak resident set, in bytes, of a child process: this program run with
// `arguments`, which prints its own_peak_rss() and nothing else.
inline double child_peak_rss(const std::string& arguments) {
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return NAN;
  self[n] = 0;
  const std::string command = "'" + std::string(self) + "' " + arguments;
  std::FILE* child = popen(command.c_str(), "r");
  if (!child) return NAN;
  double bytes = NAN;
  if (std::fscanf(child, "%lf", &bytes) != 1) bytes = NAN;
  return pclose(child) == 0 ? bytes : NAN;
}

}  // namespace bench
