// The hardware state behind FakeV4l2Camera (the camera) and FakeV4l2Device (one open file of it):
// formats, controls, the buffer queue, the frame feed and the injected faults, under one mutex.
// Internal to the fake; tests use fake_v4l2_camera.h.
#pragma once

#include <linux/videodev2.h>

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "cameras/v4l2/v4l2_queries.h"
#include "cameras/v4l2/wake_event.h"

namespace vem::testing {

// One frame as the "sensor" delivers it into the next queued buffer.
struct FakeFrame {
  std::vector<std::uint8_t> bytes;         // the image as the driver writes it (bytesperline rows)
  std::optional<std::uint32_t> bytesUsed;  // default: bytes.size()
  bool errorFlag = false;                  // V4L2_BUF_FLAG_ERROR
  std::uint32_t sequenceSkip = 0;          // frames the "driver" lost just before this one
  std::optional<std::uint32_t> timestampClock;  // V4L2_BUF_FLAG_TIMESTAMP_*; default MONOTONIC
  std::optional<std::int64_t> timestampNs;      // default: when the buffer is filled
};

struct FakeFormat {
  std::uint32_t fourcc = 0;
  std::vector<cameras::V4l2FrameSize> sizes;  // discrete sizes; the first is the default
};

struct FakeControl {
  v4l2_queryctrl query{};
  int value = 0;
};

// Makes frame `index` for the format in force.
using FakeFrameGenerator = std::function<FakeFrame(std::uint64_t index, const v4l2_pix_format&)>;

struct FakeBuffer {
  enum class State { Dequeued, Queued, Done };
  std::vector<std::uint8_t> memory;
  State state = State::Dequeued;
  int mappings = 0;
  std::uint32_t bytesUsed = 0;
  std::uint32_t flags = 0;
  std::uint32_t sequence = 0;
  std::int64_t timestampNs = 0;
};

struct FakeV4l2State {
  mutable std::mutex mutex;
  // Identity and abilities.
  std::string card, busInfo, driver;
  std::uint32_t deviceCaps = 0;
  std::vector<FakeFormat> formats;
  std::vector<std::uint32_t> refusedFourccs;  // listed, but S_FMT falls back to formats[0]
  std::size_t rowAlignBytes = 1;
  std::vector<double> frameRatesHz;
  unsigned maxBuffers = 32;
  std::map<std::uint32_t, FakeControl> controlDefaults;

  // Settings in force (reset by replug).
  v4l2_pix_format format{};
  double frameRateHz = 0.0;
  std::map<std::uint32_t, FakeControl> controls;

  // Presence: files opened in an earlier generation are dead (ENODEV).
  bool plugged = true;
  std::uint64_t generation = 0;
  std::uint64_t nextFileId = 1;

  // The buffer queue, owned by the file that allocated it.
  std::uint64_t owner = 0;
  std::vector<FakeBuffer> buffers;
  std::vector<std::vector<FakeBuffer>> graveyard;  // buffers of an unplugged generation
  std::deque<std::uint32_t> queued, done;
  bool streaming = false;
  std::int64_t streamOnNs = 0;
  std::uint32_t sequence = 0;

  // Frame feed: pushed frames, or a generator every periodNs (0: whenever a buffer is free).
  FakeFrameGenerator generator;
  std::int64_t periodNs = 0;
  std::uint64_t generated = 0;
  std::int64_t nextDueNs = 0;
  cameras::WakeEvent ready;  // signalled when a buffer is done, on unplug, on pushed frames

  // Faults: the next `count` calls of a request fail with `error` (poll: request 0).
  struct Fault {
    unsigned long request;
    int error;
    int count;
  };
  std::vector<Fault> faults;

  // Observations for tests.
  std::vector<std::uint32_t> requestedBufferCounts;
  std::uint64_t dropped = 0;  // frames with no queued buffer to land in

  // Everything below expects `mutex` held.
  [[nodiscard]] std::optional<int> takeFault(unsigned long request);
  void resetSettings();
  void applyFormat(std::uint32_t fourcc, int widthPx, int heightPx);
  // Puts `frame` into the oldest queued buffer (true), or counts it dropped.
  bool deliver(const FakeFrame& frame, std::int64_t nowNs);
  // Produces the frames the generator owes by `nowNs`.
  void advance(std::int64_t nowNs);
  void releaseQueue();
};

}  // namespace vem::testing
