#pragma once
// Counts every heap allocation the process makes, on any thread: operator new in all its
// forms (allocation_counter.cpp replaces them) and, where the build allows interposing
// malloc (not under sanitizers, whose runtimes own malloc), the C allocation functions too,
// which is how libraries such as Box2D allocate. Take a snapshot before and after the code
// under test and subtract.
#include <cstdint>

namespace swarmagg::testing {

struct AllocationCounts {
  std::uint64_t news = 0;     // operator new / new[], every overload
  std::uint64_t deletes = 0;  // operator delete / delete[] of a non-null pointer
  std::uint64_t mallocs = 0;  // malloc, calloc, realloc, aligned forms (news included)

  friend AllocationCounts operator-(const AllocationCounts& a, const AllocationCounts& b) {
    return {a.news - b.news, a.deletes - b.deletes, a.mallocs - b.mallocs};
  }
  friend AllocationCounts operator+(const AllocationCounts& a, const AllocationCounts& b) {
    return {a.news + b.news, a.deletes + b.deletes, a.mallocs + b.mallocs};
  }
};

AllocationCounts allocation_counts();
// False when malloc could not be interposed in this build: `mallocs` then stays 0.
bool counts_mallocs();

}  // namespace swarmagg::testing
