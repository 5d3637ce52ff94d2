#include "sim/physics/point_order.hpp"

#include <omp.h>

#include <algorithm>
#include <type_traits>

namespace sim {

namespace {

// v[s] := v[from[s]] for every slot s, through `scratch`, which takes v's old memory.
template <class T>
void gather(std::vector<T>& v, const std::vector<int>& from, std::vector<T>& scratch, int threads) {
  const long n = static_cast<long>(v.size());
  scratch.resize(v.size());
#pragma omp parallel for num_threads(threads) schedule(static)
  for (long s = 0; s < n; ++s) scratch[s] = v[from[s]];
  v.swap(scratch);
}

// Every per-point array by `from`, each through the world's scratch array
// of its kind, so that a sort allocates nothing once the first two have
// sized them. Sorts of 6.5 M points on 2 threads took 6.0 to 16.4 ns per
// point while each allocated the bytes' scratch and a new scene index
// (faulted in and zeroed page by page) and filled the index on one thread;
// 4.6 to 12.1 without (`bench/phases 16 10 --threads 2 --sorts 10`, issue 17,
// twentieth pass, bench/README.md). A random field's surfaces are arrays of
// doubles too (point_strength.hpp), moved through the same scratch.
void gather_all(World& w, const std::vector<int>& from, int threads) {
  for_each_point_array(w, [&](auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    if constexpr (std::is_same_v<T, double>) {
      gather(v, from, w.sort_scratch, threads);
    } else {
      static_assert(std::is_same_v<T, std::uint8_t>, "a per-point array of a new kind: give it a scratch");
      gather(v, from, w.sort_scratch_bytes, threads);
    }
  });
}

}  // namespace

void sort_points_by_cell(World& w) {
  const long n = static_cast<long>(w.points.size());
  if (static_cast<long>(w.order.size()) != n) return;  // no step yet
  const int threads = team_size(w.team);
  gather_all(w, w.order, threads);
  std::vector<int>& scene = w.sort_scratch_ints;
  scene.resize(n);
  const bool in_scene_order = w.scene_index.empty();
#pragma omp parallel for num_threads(threads) schedule(static)
  for (long s = 0; s < n; ++s) {
    scene[s] = in_scene_order ? w.order[s] : w.scene_index[w.order[s]];
    w.order[s] = static_cast<int>(s);
  }
  w.scene_index.swap(scene);
}

std::vector<int> slots_in_scene_order(const World& w) {
  std::vector<int> slots(w.scene_index.size());
  for (std::size_t s = 0; s < slots.size(); ++s) slots[w.scene_index[s]] = static_cast<int>(s);
  return slots;
}

void restore_scene_order(World& w) {
  if (w.scene_index.empty()) return;
  gather_all(w, slots_in_scene_order(w), team_size(w.team));
  if (w.order.size() == w.points.size())
    for (int& s : w.order) s = w.scene_index[s];
  w.scene_index.clear();
}

bool sort_due(const World& w, long steps) {
  const std::size_t n = w.order.size();
  if (steps % kStepsPerSort != 0 || n != w.points.size() || n < 2) return false;
  std::size_t apart = 0;
  for (std::size_t s = 1; s < n; ++s) apart += w.order[s] != w.order[s - 1] + 1;
  return static_cast<double>(apart) > kSortAtDisorder * static_cast<double>(n);
}

int scene_index_of(const World& w, int slot) {
  return w.scene_index.empty() ? slot : w.scene_index[slot];
}

int slot_of_scene_index(const World& w, int scene) {
  if (w.scene_index.empty()) return scene;
  return static_cast<int>(std::find(w.scene_index.begin(), w.scene_index.end(), scene) -
                          w.scene_index.begin());
}

}  // namespace sim
