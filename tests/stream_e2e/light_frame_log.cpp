#include "stream_e2e/light_frame_log.h"

#include <algorithm>
#include <bit>
#include <iterator>

namespace vem::e2e {

namespace {

constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ULL;
constexpr std::uint64_t kFnvPrime = 0x100000001b3ULL;

void mix(std::uint64_t& hash, std::uint32_t word) {
  for (int byte = 0; byte < 4; ++byte) {
    hash ^= (word >> (8 * byte)) & 0xFFU;
    hash *= kFnvPrime;
  }
}

double elapsedS(const std::vector<LoggedFrame>& frames) {
  return std::chrono::duration<double>(frames.back().receivedAt - frames.front().receivedAt)
      .count();
}

}  // namespace

std::uint64_t lightsDigest(const LightSet& lights) {
  std::uint64_t hash = kFnvOffset;
  for (const Light& light : lights.lights) {
    mix(hash, light.id);
    for (int axis = 0; axis < 3; ++axis) {
      mix(hash, std::bit_cast<std::uint32_t>(light.dir[axis]));
      mix(hash, std::bit_cast<std::uint32_t>(light.rgb[axis]));
    }
  }
  return hash;
}

void LightFrameLog::record(const client::Received<client::LightFrame>& received) {
  LoggedFrame logged{received.frame.seq, received.frame.lights.lights.size(),
                     lightsDigest(received.frame.lights), received.receivedAt};
  std::lock_guard lock(mutex_);
  frames_.push_back(logged);
}

std::vector<LoggedFrame> LightFrameLog::frames() const {
  std::lock_guard lock(mutex_);
  return frames_;
}

std::vector<LoggedFrame> LightFrameLog::framesBetween(std::uint64_t firstSeq,
                                                      std::uint64_t lastSeq) const {
  std::vector<LoggedFrame> out;
  std::lock_guard lock(mutex_);
  std::ranges::copy_if(frames_, std::back_inserter(out), [&](const LoggedFrame& frame) {
    return frame.seq >= firstSeq && frame.seq <= lastSeq;
  });
  return out;
}

std::size_t LightFrameLog::size() const {
  std::lock_guard lock(mutex_);
  return frames_.size();
}

std::uint64_t missingSeqs(const std::vector<LoggedFrame>& frames) {
  std::uint64_t missing = 0;
  for (std::size_t i = 1; i < frames.size(); ++i) {
    const std::uint64_t previous = frames[i - 1].seq, seq = frames[i].seq;
    missing += seq > previous ? seq - previous - 1 : 1;
  }
  return missing;
}

double receivedRateHz(const std::vector<LoggedFrame>& frames) {
  if (frames.size() < 2 || elapsedS(frames) <= 0.0) return 0.0;
  return double(frames.size() - 1) / elapsedS(frames);
}

double seqRateHz(const std::vector<LoggedFrame>& frames) {
  if (frames.size() < 2 || elapsedS(frames) <= 0.0) return 0.0;
  return double(frames.back().seq - frames.front().seq) / elapsedS(frames);
}

}  // namespace vem::e2e
