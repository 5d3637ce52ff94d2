// The grid's per-node arrays, whose memory follows the material rather than
// the domain.
//
// A grid covers the whole domain, but a step writes only the window of
// nodes its points touch (grid.hpp). The arrays are therefore taken from
// the kernel as zero pages and never written at construction: a page of
// nodes becomes resident when a step first writes into it, so a column that
// fills a fifth of its box holds about a quarter of the grid's pages, not
// all of them (bench/throughput --sizes, issue 17). Reading an untouched
// page reads zeros, which is what the grid held before.
#pragma once

#include <sys/mman.h>

#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace sim {

template <class T>
struct ZeroPages {
  static_assert(std::is_trivial_v<T>, "zero pages hold numbers and flags, whose zero is all bits 0");
  using value_type = T;
  // Blocks of this size and more are mapped pages of their own; smaller
  // ones come zeroed from calloc.
  static constexpr std::size_t kMapped = 256 * 1024;

  ZeroPages() = default;
  template <class U>
  ZeroPages(const ZeroPages<U>&) {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    void* p = bytes >= kMapped
                  ? mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0)
                  : std::calloc(n, sizeof(T));
    if (p == MAP_FAILED || p == nullptr) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) {
    if (n * sizeof(T) >= kMapped)
      munmap(p, n * sizeof(T));
    else
      std::free(p);
  }
  // Value-initialising a trivial element writes the zero it already holds:
  // skipped, so that resize() touches no page.
  template <class U>
  void construct(U*) noexcept {}
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const ZeroPages<U>&) const { return true; }
  template <class U>
  bool operator!=(const ZeroPages<U>&) const { return false; }
};

template <class T>
using NodeArray = std::vector<T, ZeroPages<T>>;

}  // namespace sim
