// The largest single allocation through the global operator new between start and stop (this test
// binary replaces operator new): shows that a decoder does not allocate what hostile input
// declares. Not thread-aware: tracks every thread's allocations.
#pragma once

#include <cstddef>

namespace vem::testing {

void startTrackingAllocations();
// The largest allocation, in bytes, since startTrackingAllocations.
[[nodiscard]] std::size_t stopTrackingAllocations();

}  // namespace vem::testing
