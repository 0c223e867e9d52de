// Rows of an image rendered in parallel on TBB's worker threads (tbb::parallel_for), which live as
// long as the process instead of being started for every frame. Each row is computed by exactly
// one call of `renderRow`, which must write only that row's pixels, so the result does not depend
// on the schedule (deterministic when renderRow is).
#pragma once

#include <functional>

namespace vem::embree {

// At most `threadCount` threads work on the rows (the caller's included); <= 0: as many as TBB
// has (one per hardware thread).
void forEachRow(int heightPx, int threadCount, const std::function<void(int row)>& renderRow);

}  // namespace vem::embree
