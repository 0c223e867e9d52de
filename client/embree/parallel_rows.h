// Rows of an image rendered on a few std::threads. Each row is computed by exactly one call of
// `renderRow`, which must write only that row's pixels; the rows are handed out from an atomic
// counter, so the result does not depend on the schedule (deterministic when renderRow is).
#pragma once

#include <functional>

namespace vem::embree {

// threadCount <= 0 means std::thread::hardware_concurrency(); never more threads than rows.
void forEachRow(int heightPx, int threadCount, const std::function<void(int row)>& renderRow);

}  // namespace vem::embree
