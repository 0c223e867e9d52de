#include "client/embree/parallel_rows.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace vem::embree {

void forEachRow(int heightPx, int threadCount, const std::function<void(int row)>& renderRow) {
  const int wanted = threadCount > 0 ? threadCount : int(std::thread::hardware_concurrency());
  const int count = std::clamp(wanted, 1, std::max(heightPx, 1));
  std::atomic<int> next{0};
  const auto work = [&] {
    for (int row = next.fetch_add(1); row < heightPx; row = next.fetch_add(1)) {
      renderRow(row);
    }
  };
  std::vector<std::jthread> helpers;
  helpers.reserve(std::size_t(count - 1));
  for (int i = 1; i < count; ++i) {
    helpers.emplace_back(work);
  }
  work();
}

}  // namespace vem::embree
