#include "stream/cubemap_worker.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <utility>

#include "core/cube_map.h"
#include "stream/frame_encoding.h"
#include "stream/thread_niceness.h"

namespace vem::stream {

namespace {

SharedBytes shared(ServerMessage message) {
  return std::make_shared<const std::string>(serialize(std::move(message)));
}

}  // namespace

CubemapWorker::CubemapWorker(Publisher& server, CubemapWorkerOptions options)
    : server_(server), options_(options), thread_([this] { run(); }) {}

CubemapWorker::~CubemapWorker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void CubemapWorker::offer(const EnvMap& polar, std::uint64_t seq, std::int64_t captureTsNs,
                          std::vector<CubeVariant> due) {
  if (due.empty()) return;
  {
    std::lock_guard lock(mutex_);
    if (slotFull_) ++counters_.framesDropped;
    // Copy into the slot's own storage: after the first frame this allocates nothing.
    slot_.polar.layout = polar.layout;
    slot_.polar.width = polar.width;
    slot_.polar.height = polar.height;
    slot_.polar.rgb.assign(polar.rgb.begin(), polar.rgb.end());
    slot_.seq = seq;
    slot_.captureTsNs = captureTsNs;
    slot_.due = std::move(due);
    slotFull_ = true;
    ++counters_.framesOffered;
  }
  changed_.notify_all();
}

CubemapWorkerCounters CubemapWorker::counters() const {
  std::lock_guard lock(mutex_);
  return counters_;
}

bool CubemapWorker::waitIdle(std::int64_t timeoutNs) const {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, std::chrono::nanoseconds(timeoutNs),
                           [&] { return !slotFull_ && !building_; });
}

void CubemapWorker::run() {
  // If the system refuses, the worker still only ever takes the newest map.
  (void)setThisThreadNice(kCubemapWorkerNice);
  Job job;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      building_ = false;
      changed_.notify_all();
      changed_.wait(lock, [&] { return stop_ || slotFull_; });
      if (stop_) return;
      std::swap(job, slot_);  // the slot keeps the old storage for the next offer
      slotFull_ = false;
      building_ = true;
    }
    build(job);
  }
}

void CubemapWorker::build(const Job& job) {
  // Face size -> the level counts wanted at that size, each with the variants that want it.
  std::map<int, std::map<int, std::vector<CubeVariant>, std::greater<>>> wanted;
  for (const CubeVariant& variant : job.due)
    wanted[variant.facePx][variant.levels].push_back(variant);

  std::optional<PolarPreview> preview;  // drawn once per frame, when some variant wants it
  std::uint64_t cubes = 0;
  std::uint64_t messages = 0;
  for (auto& [facePx, byLevels] : wanted) {
    CubeMap cube = cubeMapFromEnvMap(job.polar, facePx, byLevels.begin()->first);
    ++cubes;
    // Most levels first; then drop levels from the end for the variants that want fewer.
    for (auto& [levels, variants] : byLevels) {
      cube.levels.resize(std::min<std::size_t>(cube.levels.size(), std::size_t(levels)));
      const ServerMessage encoded =
          environmentFrameMessage(cube, job.seq, job.captureTsNs, unixNowNs(), options_.zstdLevel);
      for (const CubeVariant& variant : variants) {
        ServerMessage message = encoded;
        if (variant.preview) {
          if (!preview) {
            attachPolarPreview(message, job.polar, options_.previewWidthPx);
            preview = message.environment().preview();
          } else {
            *message.mutable_environment()->mutable_preview() = *preview;
          }
        }
        server_.publishEnvironment(variant, shared(std::move(message)));
        ++messages;
      }
    }
  }
  std::lock_guard lock(mutex_);
  ++counters_.framesBuilt;
  counters_.cubesBuilt += cubes;
  counters_.messagesPublished += messages;
}

}  // namespace vem::stream
