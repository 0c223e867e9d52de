#include "client/embree/parallel_rows.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace vem::embree {

void forEachRow(int heightPx, int threadCount, const std::function<void(int row)>& renderRow) {
  if (heightPx <= 0) return;
  const auto rows = [&] {
    // One row per task: rows differ a lot in cost (sky against geometry), so TBB's work stealing
    // balances them.
    tbb::parallel_for(tbb::blocked_range<int>(0, heightPx, 1),
                      [&](const tbb::blocked_range<int>& range) {
                        for (int row = range.begin(); row < range.end(); ++row) renderRow(row);
                      });
  };
  if (threadCount <= 0) {
    rows();
    return;
  }
  tbb::task_arena arena(threadCount);
  arena.execute(rows);
}

}  // namespace vem::embree
