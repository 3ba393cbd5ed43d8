#include "allocation_counter.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

// Relaxed is enough: the count is only read on the test's own thread, after a glFinish.
std::atomic<long> gLive{0};

void* countedAllocate(std::size_t bytes) {
  void* p = std::malloc(bytes == 0 ? 1 : bytes);
  if (p == nullptr) throw std::bad_alloc();
  gLive.fetch_add(1, std::memory_order_relaxed);
  return p;
}

void countedFree(void* p) noexcept {
  if (p == nullptr) return;
  gLive.fetch_sub(1, std::memory_order_relaxed);
  std::free(p);
}

}  // namespace

// The replaceable global forms; the nothrow forms of libstdc++ call these.
void* operator new(std::size_t bytes) {
  return countedAllocate(bytes);
}
void* operator new[](std::size_t bytes) {
  return countedAllocate(bytes);
}
void operator delete(void* p) noexcept {
  countedFree(p);
}
void operator delete[](void* p) noexcept {
  countedFree(p);
}
void operator delete(void* p, std::size_t) noexcept {
  countedFree(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  countedFree(p);
}

namespace reflect::testing {

long liveCppAllocations() {
  return gLive.load(std::memory_order_relaxed);
}

}  // namespace reflect::testing
