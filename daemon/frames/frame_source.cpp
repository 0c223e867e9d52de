#include "frames/frame_source.h"

#include <ctime>

namespace vem {

const char* sourceErrorName(SourceErrorCause cause) {
  switch (cause) {
    case SourceErrorCause::EndOfStream: return "end of stream";
    case SourceErrorCause::Timeout: return "timeout";
    case SourceErrorCause::NoDevice: return "no device";
    case SourceErrorCause::BadFrame: return "bad frame";
  }
  return "unknown";
}

std::expected<void, std::string> FrameSource::setExposure(double, double) {
  return std::unexpected(describe().spec + ": this source has no exposure control");
}

std::int64_t monotonicNowNs() {
  timespec ts{};
  ::clock_gettime(CLOCK_MONOTONIC, &ts);
  return std::int64_t(ts.tv_sec) * 1'000'000'000LL + std::int64_t(ts.tv_nsec);
}

}  // namespace vem
