// A replacement of the global operator new that records the largest allocation while tracking is
// on (allocation_tracker.h). Its own file, so the compiler never sees it beside a delete.
#include "stream_wire/allocation_tracker.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<bool> gTracking{false};
std::atomic<std::size_t> gLargest{0};
}  // namespace

void* operator new(std::size_t bytes) {
  if (gTracking.load(std::memory_order_relaxed)) {
    std::size_t seen = gLargest.load(std::memory_order_relaxed);
    while (bytes > seen && !gLargest.compare_exchange_weak(seen, bytes)) {
    }
  }
  if (void* p = std::malloc(bytes == 0 ? 1 : bytes)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t /*bytes*/) noexcept { std::free(p); }

namespace vem::testing {

void startTrackingAllocations() {
  gLargest = 0;
  gTracking = true;
}

std::size_t stopTrackingAllocations() {
  gTracking = false;
  return gLargest;
}

}  // namespace vem::testing
