#include "cameras/v4l2/fake_v4l2_state.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "cameras/v4l2/v4l2_formats.h"

namespace vem::testing {

std::optional<int> FakeV4l2State::takeFault(unsigned long request) {
  for (auto it = faults.begin(); it != faults.end(); ++it) {
    if (it->request != request) continue;
    const int error = it->error;
    if (--it->count <= 0) faults.erase(it);
    return error;
  }
  return std::nullopt;
}

void FakeV4l2State::resetSettings() {
  controls = controlDefaults;
  frameRateHz = frameRatesHz.empty() ? 0.0 : frameRatesHz.front();
  const FakeFormat& first = formats.front();
  applyFormat(first.fourcc, first.sizes.front().widthPx, first.sizes.front().heightPx);
}

// As a driver does: an unknown or refused format falls back to the first, a size to the nearest
// listed one; bytesperline is the packed row rounded up to rowAlignBytes.
void FakeV4l2State::applyFormat(std::uint32_t fourcc, int widthPx, int heightPx) {
  auto offered = std::ranges::find(formats, fourcc, &FakeFormat::fourcc);
  if (offered == formats.end() ||
      std::ranges::find(refusedFourccs, fourcc) != refusedFourccs.end()) {
    offered = formats.begin();
  }
  const auto& sizes = offered->sizes;
  const auto nearest = std::ranges::min_element(sizes, {}, [&](const cameras::V4l2FrameSize& s) {
    return std::abs(s.widthPx - widthPx) + std::abs(s.heightPx - heightPx);
  });
  format = v4l2_pix_format{};
  format.pixelformat = offered->fourcc;
  format.width = std::uint32_t(nearest->widthPx);
  format.height = std::uint32_t(nearest->heightPx);
  format.field = V4L2_FIELD_NONE;
  const std::size_t row = cameras::packedRowBytes(offered->fourcc, nearest->widthPx);
  const std::size_t aligned = (row + rowAlignBytes - 1) / rowAlignBytes * rowAlignBytes;
  format.bytesperline = std::uint32_t(aligned);
  format.sizeimage = row == 0 ? std::uint32_t(nearest->widthPx * nearest->heightPx * 2)
                              : std::uint32_t(aligned * std::size_t(nearest->heightPx));
  format.colorspace = V4L2_COLORSPACE_SRGB;
}

bool FakeV4l2State::deliver(const FakeFrame& frame, std::int64_t nowNs) {
  sequence += frame.sequenceSkip;
  if (!streaming || queued.empty()) {
    ++dropped;
    ++sequence;
    return false;
  }
  const std::uint32_t index = queued.front();
  queued.pop_front();
  FakeBuffer& buffer = buffers[index];
  const std::size_t n = std::min(frame.bytes.size(), buffer.memory.size());
  std::memcpy(buffer.memory.data(), frame.bytes.data(), n);
  buffer.bytesUsed = std::min<std::uint32_t>(frame.bytesUsed.value_or(std::uint32_t(n)),
                                             std::uint32_t(buffer.memory.size()));
  buffer.flags = frame.timestampClock.value_or(V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC) |
                 V4L2_BUF_FLAG_TSTAMP_SRC_EOF | (frame.errorFlag ? V4L2_BUF_FLAG_ERROR : 0u);
  buffer.sequence = sequence++;
  buffer.timestampNs = frame.timestampNs.value_or(nowNs);
  buffer.state = FakeBuffer::State::Done;
  done.push_back(index);
  ready.signal();
  return true;
}

void FakeV4l2State::advance(std::int64_t nowNs) {
  if (!generator || !streaming) return;
  if (periodNs <= 0) {
    // As fast as consumed: one frame whenever none is waiting.
    if (done.empty() && !queued.empty()) deliver(generator(generated++, format), nowNs);
    return;
  }
  while (nextDueNs <= nowNs) {
    if (queued.empty()) {
      ++dropped;  // no buffer: the frame is lost, as a driver loses it
      ++sequence;
      ++generated;
    } else {
      deliver(generator(generated++, format), nextDueNs);
    }
    nextDueNs += periodNs;
  }
}

void FakeV4l2State::releaseQueue() {
  streaming = false;
  queued.clear();
  done.clear();
  for (FakeBuffer& b : buffers) b.state = FakeBuffer::State::Dequeued;
}

}  // namespace vem::testing
