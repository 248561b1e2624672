#pragma once
// Per-agent arrays of large swarms on huge pages. A step reaches into these arrays by agent
// id from pair lists; with 4 KiB pages, a million agents spread every array over thousands
// of pages and most such reads also miss the TLB. Blocks of at least kHugePageFrom bytes are
// therefore aligned to 2 MiB and advised as huge pages (madvise: a hint, which the kernel
// may ignore; the memory is the same either way). Smaller blocks come from operator new as
// usual, so small worlds pay nothing.
#include <cstddef>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace swarmagg {

template <typename T>
class HugePageAllocator {
 public:
  using value_type = T;
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;
  static constexpr std::size_t kHugePageFrom = std::size_t{1} << 20;

  HugePageAllocator() = default;
  template <typename U>
  HugePageAllocator(const HugePageAllocator<U>& /*other*/) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePageFrom) return std::allocator<T>().allocate(n);
    void* block = ::operator new (rounded(bytes), std::align_val_t{kHugePage});
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(block, rounded(bytes), MADV_HUGEPAGE);
#endif
    return static_cast<T*>(block);
  }

  void deallocate(T* block, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePageFrom) return std::allocator<T>().deallocate(block, n);
    ::operator delete (block, rounded(bytes), std::align_val_t{kHugePage});
  }

  friend bool operator==(const HugePageAllocator&, const HugePageAllocator&) {
    return true;
  }

 private:
  static std::size_t rounded(std::size_t bytes) {
    return (bytes + kHugePage - 1) / kHugePage * kHugePage;
  }
};

// A vector indexed by agent (or holding a few entries per agent), on huge pages when large.
template <typename T>
using AgentArray = std::vector<T, HugePageAllocator<T>>;

}  // namespace swarmagg
