#include "vemd/capture_thread.h"

#include <algorithm>
#include <utility>

#include <spdlog/spdlog.h>

#include "util/printable.h"

namespace vem::vemd {

namespace {
// A source's message may quote what a camera reported (its name, a driver's text): escaped.
constexpr std::size_t kLoggedMessageBytes = 1024;
}  // namespace

CaptureThread::CaptureThread(FrameSource& source, util::DropOldestQueue<CapturedFrame>& frames,
                             util::DropOldestQueue<CapturedFrame>& spares, const CaptureOptions& options)
    : source_(source),
      frames_(frames),
      spares_(spares),
      options_(options),
      backoff_(options.retryInitial, options.retryMax),
      thread_([this] { run(); }) {}

CaptureThread::~CaptureThread() {
  stop();
  join();
}

void CaptureThread::stop() {
  stop_.store(true);
  source_.interrupt();
  backoffWait_.interrupt();
  frames_.close();
}

std::optional<SourceErrorCause> CaptureThread::failure() const {
  const int cause = failure_.load();
  if (cause == kNoFailure) return std::nullopt;
  return SourceErrorCause(cause);
}

void CaptureThread::join() {
  if (thread_.joinable()) thread_.join();
}

void CaptureThread::run() {
  while (!stop_.load()) {
    recycleSpares();
    auto frame = source_.next();
    if (stop_.load()) break;
    if (!frame) {
      if (frame.error().cause == SourceErrorCause::EndOfStream) {
        spdlog::info("source: {}", util::printable(frame.error().message, kLoggedMessageBytes));
        endOfStream_.store(true);
        failure_.store(int(SourceErrorCause::EndOfStream));
        break;
      }
      if (!backOff(frame.error())) break;
      continue;
    }
    if (failing_) {
      spdlog::info("source: frames again after {} failed attempt(s)", failedAttempts_);
      failing_ = false;
      failure_.store(kNoFailure);
      failedAttempts_ = 0;
      backoff_.reset();
    }
    deliver(std::move(*frame));
    if (options_.maxFrames > 0 && delivered_.load() >= options_.maxFrames) {
      limitReached_.store(true);
      break;
    }
  }
  frames_.close();
}

bool CaptureThread::backOff(const SourceError& error) {
  sourceErrors_.fetch_add(1);
  ++failedAttempts_;
  if (!failing_ || failingCause_ != error.cause) {
    spdlog::warn("source: {} ({}); retrying every {} to {} ms",
                 util::printable(error.message, kLoggedMessageBytes), sourceErrorName(error.cause),
                 options_.retryInitial.count(), options_.retryMax.count());
    failing_ = true;
    failingCause_ = error.cause;
    failure_.store(int(error.cause));
  }
  const auto wait = backoff_.next();
  const std::int64_t deadline =
      monotonicNowNs() + std::chrono::duration_cast<std::chrono::nanoseconds>(wait).count();
  return backoffWait_.sleepUntil(deadline) && !stop_.load();
}

void CaptureThread::deliver(CapturedFrame frame) {
  std::optional<CapturedFrame> back =
      options_.lossless ? frames_.pushOrWait(std::move(frame)) : frames_.push(std::move(frame));
  delivered_.fetch_add(1);
  if (back) source_.recycle(std::move(*back));
}

void CaptureThread::recycleSpares() {
  while (auto spare = spares_.popFor(std::chrono::nanoseconds(0))) {
    source_.recycle(std::move(*spare));
  }
}

}  // namespace vem::vemd
