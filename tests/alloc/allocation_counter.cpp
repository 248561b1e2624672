#include "alloc/allocation_counter.hpp"

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <new>

namespace swarmagg::testing {
namespace {

// Constant-initialised, so they count from before any static constructor runs.
constinit std::atomic<std::uint64_t> news{0};
constinit std::atomic<std::uint64_t> deletes{0};
constinit std::atomic<std::uint64_t> mallocs{0};

void* counted_new(std::size_t size) {
  news.fetch_add(1, std::memory_order_relaxed);
  // malloc(0) may return null; operator new must return a unique pointer.
  return std::malloc(size == 0 ? 1 : size);
}

void* counted_aligned_new(std::size_t size, std::align_val_t alignment) {
  news.fetch_add(1, std::memory_order_relaxed);
  const auto align = static_cast<std::size_t>(alignment);
  // aligned_alloc wants a size that is a multiple of the alignment.
  const std::size_t rounded = (size + align - 1) / align * align;
  return std::aligned_alloc(align, rounded == 0 ? align : rounded);
}

void* throwing(void* p) {
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

void counted_delete(void* p) {
  if (p == nullptr) return;
  deletes.fetch_add(1, std::memory_order_relaxed);
  std::free(p);
}

}  // namespace

AllocationCounts allocation_counts() {
  return {news.load(std::memory_order_relaxed), deletes.load(std::memory_order_relaxed),
          mallocs.load(std::memory_order_relaxed)};
}

#ifdef SWARMAGG_COUNT_MALLOC
bool counts_mallocs() {
  return true;
}
#else
bool counts_mallocs() {
  return false;
}
#endif

}  // namespace swarmagg::testing

namespace counter = swarmagg::testing;

void* operator new(std::size_t size) {
  return counter::throwing(counter::counted_new(size));
}
void* operator new[](std::size_t size) {
  return counter::throwing(counter::counted_new(size));
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  return counter::counted_new(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  return counter::counted_new(size);
}
void* operator new(std::size_t size, std::align_val_t alignment) {
  return counter::throwing(counter::counted_aligned_new(size, alignment));
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
  return counter::throwing(counter::counted_aligned_new(size, alignment));
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  return counter::counted_aligned_new(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  return counter::counted_aligned_new(size, alignment);
}

void operator delete(void* p) noexcept {
  counter::counted_delete(p);
}
void operator delete[](void* p) noexcept {
  counter::counted_delete(p);
}
void operator delete(void* p, std::size_t) noexcept {
  counter::counted_delete(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  counter::counted_delete(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  counter::counted_delete(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  counter::counted_delete(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
  counter::counted_delete(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  counter::counted_delete(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  counter::counted_delete(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  counter::counted_delete(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  counter::counted_delete(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  counter::counted_delete(p);
}

#ifdef SWARMAGG_COUNT_MALLOC
// glibc's own entry points: the definitions below interpose malloc and friends for the whole
// process (shared libraries included) and forward to these. Memory from either side may be
// freed by the other, as both are glibc's allocator.
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);

void* malloc(std::size_t size) noexcept {
  counter::mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  counter::mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) noexcept {
  counter::mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, size);
}
void* memalign(std::size_t alignment, std::size_t size) noexcept {
  counter::mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  counter::mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  counter::mallocs.fetch_add(1, std::memory_order_relaxed);
  void* p = __libc_memalign(alignment, size);
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}
void free(void* p) noexcept {
  __libc_free(p);
}
}
#endif
