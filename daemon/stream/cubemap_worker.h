// CubemapWorker: builds the environment frames (cube maps) clients subscribed to on its own
// thread, so that nothing a client asks for runs on vemd's processing thread (issue 16: large cube
// maps asked for often had cut processing from 30 to 1-2 frames/s).
//
// - The processing thread offers the frame's polar map with the variants due in that frame
//   (StreamSink decides which, at each variant's rate). offer() copies the map into the worker's
//   one slot and returns: its cost is that copy, once per frame at most, whatever the number of
//   clients. A map still waiting in the slot is replaced by the newer one (counted as dropped):
//   the worker drops what it cannot keep up with, and the processing thread never waits for it.
// - The worker builds each face size once per frame with the most levels any due variant wants
//   (core/cube_map.h), encodes each (face size, levels) once (frame_encoding.h), draws the polar
//   preview once when a variant wants it, and hands each variant's message to the server, which
//   fans it out to every client subscribed to it.
// - The thread runs at nice 10 (setpriority), so when both cores are busy the capture and
//   processing threads come first.
// Thread-safe: offer() and the counters from any thread; the destructor stops and joins.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "core/env_map.h"
#include "stream/publisher.h"
#include "stream/subscription.h"

namespace vem::stream {

struct CubemapWorkerOptions {
  int zstdLevel = 3;
  int previewWidthPx = 256;
};

struct CubemapWorkerCounters {
  std::uint64_t framesOffered = 0;  // maps handed over by offer()
  std::uint64_t framesBuilt = 0;    // maps the worker turned into messages
  std::uint64_t framesDropped = 0;  // maps replaced in the slot before the worker took them
  std::uint64_t cubesBuilt = 0;     // cube maps built (one per face size per frame)
  std::uint64_t messagesPublished = 0;
};

class CubemapWorker {
 public:
  CubemapWorker(Publisher& server, CubemapWorkerOptions options);
  ~CubemapWorker();
  CubemapWorker(const CubemapWorker&) = delete;
  CubemapWorker& operator=(const CubemapWorker&) = delete;

  // Hands over `polar` (copied) and the variants due for the frame `seq`; never waits for a build.
  void offer(const EnvMap& polar, std::uint64_t seq, std::int64_t captureTsNs,
             std::vector<CubeVariant> due);

  [[nodiscard]] CubemapWorkerCounters counters() const;
  // Waits until the worker has nothing left to build (tests); false after `timeoutNs`.
  [[nodiscard]] bool waitIdle(std::int64_t timeoutNs) const;

 private:
  struct Job {
    EnvMap polar;
    std::uint64_t seq = 0;
    std::int64_t captureTsNs = 0;
    std::vector<CubeVariant> due;
  };

  void run();
  void build(const Job& job);

  Publisher& server_;
  CubemapWorkerOptions options_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  Job slot_;
  bool slotFull_ = false;
  bool building_ = false;
  bool stop_ = false;
  CubemapWorkerCounters counters_;
  std::thread thread_;  // last: starts after everything above exists
};

}  // namespace vem::stream
