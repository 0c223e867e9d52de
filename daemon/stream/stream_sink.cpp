#include "stream/stream_sink.h"

#include <algorithm>
#include <memory>
#include <utility>

#include "frames/frame_source.h"
#include "frames/published_lights.h"
#include "stream/frame_encoding.h"
#include "util/contract.h"

namespace vem::stream {

namespace {

constexpr std::size_t kMaxWindowSamples = 4096;

SharedBytes shared(ServerMessage message) {
  return std::make_shared<const std::string>(serialize(std::move(message)));
}

}  // namespace

StreamSink::StreamSink(Publisher& server, StreamSinkOptions options)
    : server_(server),
      options_(options),
      windowStartNs_(monotonicNowNs()),
      worker_(server, CubemapWorkerOptions{options.zstdLevel, options.previewWidthPx}) {}

std::expected<void, SinkFailure> StreamSink::consume(const ProcessedFrame& frame) {
  VEM_EXPECTS(frame.captured != nullptr);
  const std::int64_t nowNs = monotonicNowNs();
  const std::int64_t nowUnixNs = unixNowNs();
  LightFrameStamp stamp;
  stamp.captureUnixNs = nowUnixNs - (nowNs - frame.captured->arrivalNs);
  stamp.publishUnixNs = nowUnixNs;
  stamp.status = SOURCE_STATE_OK;
  stamp.filterDelayFrames = stamp_.filterDelayFrames;
  server_.publishLights(shared(lightFrameMessage(frame, stamp)));
  ++framesPublished_;
  ++windowFrames_;
  lightsInLastFrame_ = std::uint32_t(publishedLights(frame).lights->lights.size());
  if (windowLatenciesMs_.size() < kMaxWindowSamples) {
    windowLatenciesMs_.push_back(double(monotonicNowNs() - frame.captured->arrivalNs) * 1e-6);
  }
  publishCubemaps(frame, nowNs);
  return {};
}

void StreamSink::publishCubemaps(const ProcessedFrame& frame, std::int64_t nowNs) {
  const CubemapDemand demand = server_.cubemapDemand();
  std::erase_if(nextCubemapDueNs_, [&](const auto& entry) {
    return std::ranges::find(demand.variants, entry.first, &VariantDemand::variant) ==
           demand.variants.end();
  });
  if (frame.polar == nullptr) return;
  std::vector<CubeVariant> due;
  for (const VariantDemand& wanted : demand.variants) {
    auto [next, fresh] = nextCubemapDueNs_.try_emplace(wanted.variant, nowNs);
    if (nowNs < next->second) continue;
    next->second = std::max(next->second + std::int64_t(1e9 / wanted.rateHz), nowNs);
    due.push_back(wanted.variant);
  }
  worker_.offer(*frame.polar, frame.captured->seq, frame.captured->captureTsNs, std::move(due));
}

SinkWindow StreamSink::takeWindow(std::int64_t nowMonotonicNs) {
  SinkWindow window;
  window.frames = std::exchange(windowFrames_, 0);
  window.elapsedS = double(nowMonotonicNs - windowStartNs_) * 1e-9;
  if (!windowLatenciesMs_.empty()) {
    auto middle = windowLatenciesMs_.begin() + std::ptrdiff_t(windowLatenciesMs_.size() / 2);
    std::nth_element(windowLatenciesMs_.begin(), middle, windowLatenciesMs_.end());
    window.latencyMedianMs = *middle;
  }
  windowLatenciesMs_.clear();
  windowStartNs_ = nowMonotonicNs;
  return window;
}

}  // namespace vem::stream
