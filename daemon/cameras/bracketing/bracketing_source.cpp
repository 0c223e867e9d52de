#include "cameras/bracketing/bracketing_source.h"

#include <numeric>
#include <utility>
#include <variant>

#include <fmt/format.h>

#include "calib/io/camera_file.h"
#include "util/contract.h"

namespace vem::cameras {
namespace {

SourceError noDevice(std::string message) {
  return SourceError{SourceErrorCause::NoDevice, std::move(message)};
}

std::string bracketSpec(const BracketSettings& settings, const std::string& innerSpec) {
  return fmt::format("bracket:{}@{}+{}", settings.count, settings.stopsApart, innerSpec);
}

// The inner camera's calibration, or why it cannot be bracketed.
std::expected<calib::CameraCalibration, std::string> ldrCalibration(
    const SourceDescription& inner) {
  if (inner.calibrationToml.empty()) {
    return std::unexpected(fmt::format(
        "{}: the camera has no camera file: bracketing needs its response (vemcalib response)",
        inner.spec));
  }
  auto camera = calib::io::parseCameraFile(inner.calibrationToml, inner.spec);
  if (!camera) return std::unexpected(camera.error().message);
  if (!camera->photometric) {
    return std::unexpected(fmt::format(
        "{}: the camera file has no photometric section: bracketing needs the camera's response "
        "(vemcalib response)",
        inner.spec));
  }
  if (std::holds_alternative<calib::LogResponse>(camera->photometric->response)) {
    return std::unexpected(fmt::format(
        "{}: the camera file has a log response, which exposure does not change: expected a "
        "\"table\" or \"linear\" response of a camera without an HDR sensor",
        inner.spec));
  }
  if (camera->camera.pixelFormat != inner.pixelFormat) {
    return std::unexpected(fmt::format("{}: the camera delivers {} but its camera file is for {}",
                                       inner.spec, pixelFormatName(inner.pixelFormat),
                                       pixelFormatName(camera->camera.pixelFormat)));
  }
  return std::move(*camera);
}

std::size_t maxFramesWithoutGroup(std::size_t count) { return 4 * count + 8; }

}  // namespace

std::expected<std::unique_ptr<BracketingSource>, SourceError> BracketingSource::create(
    std::unique_ptr<FrameSource> inner, BracketSettings settings) {
  VEM_EXPECTS(inner);
  const SourceDescription description = inner->describe();
  if (auto problem = bracketSettingsProblem(settings)) {
    return std::unexpected(noDevice(fmt::format("{}: {}", description.spec, *problem)));
  }
  auto camera = ldrCalibration(description);
  if (!camera) return std::unexpected(noDevice(camera.error()));
  std::vector<double> effective = bracketExposuresUs(settings);
  for (double& exposureUs : effective) exposureUs *= settings.gain;
  const calib::BracketWeighting weighting = bracketWeightingFor(camera->camera.pixelFormat);
  auto sensor =
      makeVirtualHdrSensor(*camera->photometric, camera->camera.pixelFormat, effective, weighting);
  if (!sensor) {
    return std::unexpected(noDevice(fmt::format("{}: {}", description.spec, sensor.error())));
  }
  std::string toml = calib::io::formatCameraFile(virtualCameraCalibration(*camera, *sensor));
  if (auto requested = inner->setExposure(settings.baseExposureUs, settings.gain); !requested) {
    return std::unexpected(noDevice(
        fmt::format("{}: the camera takes no exposure requests, which bracketing needs: {}",
                    description.spec, requested.error())));
  }
  return std::unique_ptr<BracketingSource>(new BracketingSource(
      std::move(inner), settings, std::move(*camera), std::move(*sensor), std::move(toml)));
}

BracketingSource::BracketingSource(std::unique_ptr<FrameSource> inner, BracketSettings settings,
                                   calib::CameraCalibration ldrCamera, VirtualHdrSensor sensor,
                                   std::string virtualToml)
    : inner_(std::move(inner)),
      innerDescription_(inner_->describe()),
      settings_(settings),
      exposuresUs_(bracketExposuresUs(settings)),
      ldrCamera_(std::move(ldrCamera)),
      weighting_(bracketWeightingFor(ldrCamera_.camera.pixelFormat)),
      sensor_(sensor),
      virtualToml_(std::move(virtualToml)),
      grouper_(
          [&] {
            std::vector<double> effective = exposuresUs_;
            for (double& e : effective) e *= settings.gain;
            return effective;
          }(),
          settings.matchTolerance) {}

SourceDescription BracketingSource::describe() const {
  SourceDescription d = innerDescription_;
  d.spec = bracketSpec(settings_, innerDescription_.spec);
  d.pixelFormat = sensor_.format;
  d.calibrationToml = virtualToml_;
  d.nominalRateHz = innerDescription_.nominalRateHz / double(settings_.count);
  return d;
}

void BracketingSource::requestExposure() {
  auto requested = inner_->setExposure(exposuresUs_[requestIndex_], settings_.gain);
  if (!requested) {
    ++counters_.exposureRequestsRefused;
    lastRefusal_ = std::move(requested.error());
  }
}

std::expected<CapturedFrame, SourceError> BracketingSource::next() {
  const calib::CameraIdentity& camera = ldrCamera_.camera;
  for (std::size_t pulled = 0;; ++pulled) {
    requestExposure();
    auto got = inner_->next();
    if (!got) {
      dropPending(grouper_.reset(), BracketDropReason::Error);
      return std::unexpected(std::move(got.error()));
    }
    requestIndex_ = (requestIndex_ + 1) % exposuresUs_.size();
    ++counters_.framesIn;
    const RawFrame& frame = got->frame;
    if (frame.width != camera.sensorWidthPx || frame.height != camera.sensorHeightPx ||
        frame.format != camera.pixelFormat) {
      auto error = SourceError{
          SourceErrorCause::BadFrame,
          fmt::format("{}: frame {} is {} x {} {}, but the camera file is for {} x {} {}",
                      describe().spec, got->seq, frame.width, frame.height,
                      pixelFormatName(frame.format), camera.sensorWidthPx, camera.sensorHeightPx,
                      pixelFormatName(camera.pixelFormat))};
      dropPending(grouper_.reset(), BracketDropReason::Error);
      dropFrame(std::move(*got), BracketDropReason::Error);
      return std::unexpected(std::move(error));
    }
    const GroupStep step = grouper_.offer(got->seq, frame.exposureUs * frame.gain);
    dropPending(step.dropPending, step.pendingReason);
    if (!step.keepFrame) {
      if (pulled + 1 >= maxFramesWithoutGroup(exposuresUs_.size())) {
        auto error = noGroupError(got->frame);
        dropFrame(std::move(*got), BracketDropReason::OutOfCycle);
        return std::unexpected(std::move(error));
      }
      dropFrame(std::move(*got), BracketDropReason::OutOfCycle);
      continue;
    }
    pendingFrames_.push_back(std::move(got->frame));
    got->frame = RawFrame{};
    pendingIds_.push_back(std::move(*got));
    if (step.complete) return mergeGroup();
    if (pulled + 1 >= maxFramesWithoutGroup(exposuresUs_.size())) {
      return std::unexpected(noGroupError(pendingFrames_.back()));
    }
  }
}

SourceError BracketingSource::noGroupError(const RawFrame& last) const {
  std::string expected;
  for (const double e : exposuresUs_) {
    expected += fmt::format("{}{:.6g}", expected.empty() ? "" : ", ", e * settings_.gain);
  }
  return SourceError{
      SourceErrorCause::BadFrame,
      fmt::format(
          "{}: no complete bracket in the last {} frames: the last frame reports exposure "
          "{:.6g} us x gain {:.6g}, expected exposure x gain {} us in turn{}",
          describe().spec, maxFramesWithoutGroup(exposuresUs_.size()), last.exposureUs, last.gain,
          expected,
          lastRefusal_.empty() ? "" : " (the camera refused a request: " + lastRefusal_ + ")")};
}

CapturedFrame BracketingSource::mergeGroup() {
  CapturedFrame out;
  if (!spareCodes_.empty()) {
    out.frame.codes = std::move(spareCodes_.back());
    spareCodes_.pop_back();
  }
  lastStats_ = mergeToVirtualHdr(pendingFrames_, *ldrCamera_.photometric, weighting_, sensor_,
                                 scratch_, out.frame);
  out.frame.exposureUs = std::accumulate(exposuresUs_.begin(), exposuresUs_.end(), 0.0);
  out.frame.gain = 1.0;
  const std::size_t k = pendingIds_.size();
  const std::int64_t early = pendingIds_[(k - 1) / 2].captureTsNs;
  const std::int64_t late = pendingIds_[k / 2].captureTsNs;
  out.captureTsNs = early + (late - early) / 2;
  out.arrivalNs = pendingIds_.back().arrivalNs;
  out.seq = counters_.groups++;
  counters_.saturatedSamples += lastStats_.saturatedSamples;
  counters_.darkSamples += lastStats_.darkSamples;
  for (std::size_t i = 0; i < k; ++i) {
    pendingIds_[i].frame = std::move(pendingFrames_[i]);
    inner_->recycle(std::move(pendingIds_[i]));
  }
  pendingFrames_.clear();
  pendingIds_.clear();
  return out;
}

void BracketingSource::count(std::size_t frames, BracketDropReason reason) {
  counters_.framesDropped += frames;
  switch (reason) {
    case BracketDropReason::OutOfCycle: counters_.droppedOutOfCycle += frames; break;
    case BracketDropReason::Gap: counters_.droppedForGap += frames; break;
    case BracketDropReason::Error: counters_.droppedForError += frames; break;
  }
}

void BracketingSource::dropPending(std::size_t frames, BracketDropReason reason) {
  VEM_EXPECTS(frames == 0 || frames == pendingFrames_.size());
  if (frames == 0) return;
  count(frames, reason);
  for (std::size_t i = 0; i < pendingFrames_.size(); ++i) {
    pendingIds_[i].frame = std::move(pendingFrames_[i]);
    inner_->recycle(std::move(pendingIds_[i]));
  }
  pendingFrames_.clear();
  pendingIds_.clear();
}

void BracketingSource::dropFrame(CapturedFrame&& frame, BracketDropReason reason) {
  count(1, reason);
  inner_->recycle(std::move(frame));
}

void BracketingSource::recycle(CapturedFrame&& spent) {
  constexpr std::size_t kMaxSpareBuffers = 8;
  if (spareCodes_.size() < kMaxSpareBuffers && spent.frame.codes.capacity() > 0) {
    spareCodes_.push_back(std::move(spent.frame.codes));
  }
}

void BracketingSource::interrupt() { inner_->interrupt(); }

std::expected<void, std::string> BracketingSource::setExposure(double, double) {
  return std::unexpected(describe().spec +
                         ": a bracketing source sets its camera's exposure itself");
}

}  // namespace vem::cameras
