#include "vemd/replay_source.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "util/printable.h"

namespace vem::vemd {

namespace {
constexpr std::int64_t kFallbackPeriodNs = 33'333'333;  // 30 frames/s when nothing says better
constexpr std::size_t kMaxSpareBuffers = 8;

// a + b and a - b modulo 2^64: hostile capture times (near the ends of int64) shift without
// undefined behaviour; the schedule then sees an absurd step and does not wait for it.
std::int64_t wrappingAdd(std::int64_t a, std::int64_t b) {
  return std::int64_t(std::uint64_t(a) + std::uint64_t(b));
}
std::int64_t wrappingSub(std::int64_t a, std::int64_t b) {
  return std::int64_t(std::uint64_t(a) - std::uint64_t(b));
}

// The header's frame period (at least 1 ns, at most the longest step a schedule follows), else
// 30 frames/s.
std::int64_t nominalPeriodNs(const recording::RecordingHeader& header) {
  const double rateHz = header.nominalRateHz;
  if (!(rateHz > 0.0) || !std::isfinite(rateHz)) return kFallbackPeriodNs;
  return std::clamp<std::int64_t>(std::llround(std::min(1e9 / rateHz, 1e18)), 1,
                                  FrameSchedule::kMaxRecordedIntervalNs);
}

}  // namespace

std::expected<std::unique_ptr<ReplaySource>, SourceError> ReplaySource::open(
    const std::filesystem::path& path, const ReplayOptions& options) {
  auto reader = recording::RecordingReader::open(path);
  if (!reader)
    return std::unexpected(SourceError{SourceErrorCause::NoDevice, reader.error().message});
  std::unique_ptr<ReplaySource> source(new ReplaySource(std::move(*reader), options));
  // The first frame is read now: a recording without an intact frame fails the start-up with one
  // sentence instead of ending the run at once as if it had been replayed.
  if (auto first = source->readNext(); !first) {
    return std::unexpected(SourceError{SourceErrorCause::NoDevice, first.error().message});
  }
  source->frameRead_ = true;
  return source;
}

ReplaySource::ReplaySource(recording::RecordingReader reader, const ReplayOptions& options)
    : reader_(std::move(reader)),
      options_(options),
      name_(util::printable(reader_.path().string())),
      schedule_(schedulePeriodNs(options.rate), nominalPeriodNs(reader_.header())) {}

SourceDescription ReplaySource::describe() const {
  const recording::RecordingHeader& h = reader_.header();
  SourceDescription d;
  d.spec = "replay:" + reader_.path().string();
  d.cameraModel = h.cameraModel;
  d.cameraSerial = h.cameraSerial;
  d.sensorWidthPx = h.sensorWidthPx;
  d.sensorHeightPx = h.sensorHeightPx;
  d.pixelFormat = h.pixelFormat;
  d.calibrationToml = h.calibrationToml;
  d.nominalRateHz =
      options_.rate.mode == SourceRate::Mode::Fixed ? options_.rate.hz : h.nominalRateHz;
  d.liveClock = false;
  d.paced = options_.rate.mode != SourceRate::Mode::Max;
  return d;
}

std::expected<CapturedFrame, SourceError> ReplaySource::next() {
  if (!frameWaiting_) {
    if (frameRead_) {
      frameRead_ = false;  // the first frame, read by open()
    } else if (auto read = readNext(); !read) {
      return std::unexpected(read.error());
    }
    frameWaiting_ = true;
    const FrameDue due =
        schedule_.next(wrappingAdd(recorded_.captureTsNs, tsShiftNs_), monotonicNowNs());
    reportJump(due.jump);
    waitingDueNs_ = due.dueNs;
  }
  if (!pacer_.sleepUntil(waitingDueNs_)) {
    return std::unexpected(
        SourceError{SourceErrorCause::Timeout,
                    fmt::format("{}: interrupted while waiting for the next frame", name_)});
  }
  frameWaiting_ = false;
  CapturedFrame out;
  out.frame = std::move(recorded_.frame);
  out.seq = recorded_.seq + seqShift_;
  out.captureTsNs = wrappingAdd(recorded_.captureTsNs, tsShiftNs_);
  out.arrivalNs = monotonicNowNs();
  return out;
}

void ReplaySource::reportJump(const std::optional<TimestampJump>& jump) {
  if (jump) {
    if (jumpsInARow_++ == 0) {
      spdlog::warn(
          "{}: the capture time jumps from {} ns to {} ns before frame {} (expected a step of 0 to "
          "{} s); replaying that step as one frame period ({:.3f} ms) instead of waiting it out "
          "(further jumps are counted, not logged, until the capture times are regular again)",
          name_, jump->fromTsNs, jump->toTsNs, recorded_.seq + seqShift_,
          FrameSchedule::kMaxRecordedIntervalNs / 1'000'000'000,
          double(nominalPeriodNs(reader_.header())) * 1e-6);
    }
    return;
  }
  if (jumpsInARow_ == 0) return;
  spdlog::info("{}: capture times regular again after {} jump(s) replayed as one frame period each",
               name_, jumpsInARow_);
  jumpsInARow_ = 0;
}

void ReplaySource::recycle(CapturedFrame&& spent) {
  if (spareCodes_.size() < kMaxSpareBuffers && spent.frame.codes.capacity() > 0) {
    spareCodes_.push_back(std::move(spent.frame.codes));
  }
}

void ReplaySource::interrupt() { pacer_.interrupt(); }

std::uint64_t ReplaySource::damagedRecords() const {
  return damagedBeforeLap_ + reader_.damage().damagedRecords;
}

std::expected<bool, SourceError> ReplaySource::readNext() {
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (recorded_.frame.codes.capacity() == 0 && !spareCodes_.empty()) {
      recorded_.frame.codes = std::move(spareCodes_.back());
      spareCodes_.pop_back();
    }
    auto got = reader_.next(recorded_);
    if (!got) return std::unexpected(SourceError{SourceErrorCause::NoDevice, got.error().message});
    if (*got) {
      if (framesThisLap_ == 0) {
        firstSeq_ = recorded_.seq;
        firstTsNs_ = recorded_.captureTsNs;
      }
      lastSeq_ = recorded_.seq;
      lastTsNs_ = recorded_.captureTsNs;
      ++framesThisLap_;
      return true;
    }
    if (framesThisLap_ == 0) {
      const recording::DamageStats& damage = reader_.damage();
      return std::unexpected(SourceError{
          SourceErrorCause::EndOfStream,
          fmt::format("{}: the recording holds no intact frame (damaged records: {}, truncated "
                      "tail: {} bytes), so there is nothing to replay",
                      name_, damage.damagedRecords, damage.truncatedTailBytes)});
    }
    if (!options_.loop) {
      return std::unexpected(
          SourceError{SourceErrorCause::EndOfStream,
                      fmt::format("{}: end of the recording ({} frames)", name_, framesThisLap_)});
    }
    startNextLap();
  }
  return std::unexpected(SourceError{SourceErrorCause::EndOfStream, "unreachable"});
}

void ReplaySource::startNextLap() {
  seqShift_ += lastSeq_ - firstSeq_ + 1;
  tsShiftNs_ =
      wrappingAdd(tsShiftNs_, wrappingAdd(wrappingSub(lastTsNs_, firstTsNs_), lapPeriodNs()));
  damagedBeforeLap_ += reader_.damage().damagedRecords;
  reader_.rewind();
  framesThisLap_ = 0;
  ++laps_;
}

std::int64_t ReplaySource::lapPeriodNs() const {
  if (reader_.header().nominalRateHz > 0.0) return nominalPeriodNs(reader_.header());
  std::int64_t spanNs = 0;
  if (framesThisLap_ > 1 && !__builtin_sub_overflow(lastTsNs_, firstTsNs_, &spanNs) && spanNs > 0) {
    return spanNs / std::int64_t(framesThisLap_ - 1);
  }
  return kFallbackPeriodNs;
}

}  // namespace vem::vemd
