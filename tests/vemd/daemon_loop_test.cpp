// The capture and processing threads: a stuck or slow sink makes counted drops and never holds
// up capture; failing sinks and sources; stop requests; frame limits. Built with TSan in CI.
#include "vemd/daemon_loop.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <optional>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "vemd/pipeline_setup.h"
#include "vemd/replay_source.h"
#include "vemd_fixtures.h"

namespace vem::testing {
namespace {

using namespace std::chrono_literals;
using vem::SourceError;
using vem::SourceErrorCause;

vemd::Pipeline smallPipeline() {
  auto pipeline = vemd::pipelineFromCameraFile(smallCameraToml(), "test camera", smallProcessing());
  EXPECT_TRUE(pipeline);
  return std::move(*pipeline);
}

vemd::LoopOptions quietLoop(std::size_t queueDepth = 4) {
  vemd::LoopOptions o;
  o.queueDepth = queueDepth;
  o.reportEveryS = 0.0;
  o.retryInitial = 1ms;
  o.retryMax = 4ms;
  return o;
}

struct SinkUnderTest {
  std::shared_ptr<TestSink::Log> log = std::make_shared<TestSink::Log>();
  TestSink* sink = nullptr;  // owned by the SinkSet
};

vemd::SinkSet sinksWith(SinkUnderTest& a, const std::string& name = "test") {
  std::vector<std::unique_ptr<vem::Sink>> sinks;
  auto sink = std::make_unique<TestSink>(name, a.log);
  a.sink = sink.get();
  sinks.push_back(std::move(sink));
  return vemd::SinkSet(std::move(sinks));
}

// The capture thread must not wait for processing: with the only sink stuck in its first frame,
// every later frame is still taken from the source; the queue keeps the newest `depth` and
// counts the rest as dropped. Exact counts, no timing.
TEST(DaemonLoop, CaptureKeepsTakingFramesWhileTheSinkIsStuck) {
  constexpr int kFrames = 40;
  constexpr std::size_t kDepth = 4;
  ScriptedSource source(ScriptedSource::frames(kFrames), true);
  source.gate();
  SinkUnderTest s;
  vemd::SinkSet sinks = sinksWith(s);
  Gate sinkGate;
  s.sink->gate = &sinkGate;
  vemd::Pipeline pipeline = smallPipeline();
  std::atomic<bool> stop{false};
  vemd::LoopResult result;
  std::thread loop(
      [&] { result = vemd::runDaemonLoop(source, pipeline, sinks, quietLoop(kDepth), stop); });
  source.release(1);
  bool ok = sinkGate.awaitArrivals(1);
  EXPECT_TRUE(ok) << "the first frame never reached the sink";
  // Frame 0 is in the stuck sink. Each further frame must be taken by the capture thread: it
  // comes back to next() for the (k + 1)-th time only after queueing the k-th frame.
  for (int k = 2; k <= kFrames && ok; ++k) {
    source.release(1);
    ok = source.awaitCalls(k + 1);
    EXPECT_TRUE(ok) << "capture stalled at frame " << k;
  }
  source.release(1);  // the end of the script
  if (!ok) stop = true;
  sinkGate.open();
  loop.join();
  ASSERT_TRUE(ok);
  EXPECT_EQ(result.reason, vemd::StopReason::EndOfStream);
  EXPECT_EQ(result.totals.framesIn, std::uint64_t(kFrames));
  EXPECT_EQ(result.totals.processed, 1 + kDepth);
  EXPECT_EQ(result.totals.dropped, kFrames - 1 - kDepth);
  // The newest frames were kept: the sink saw frame 0, then the last kDepth.
  std::vector<std::uint64_t> expected{0};
  for (std::size_t i = 0; i < kDepth; ++i) expected.push_back(kFrames - kDepth + i);
  EXPECT_EQ(s.log->seqs, expected);
  EXPECT_TRUE(s.log->closed);
}

// A sink that sleeps 20 ms per frame against a replay at 500 frames/s: the source still delivers
// every frame, the ones processing could not take are dropped and counted, none is lost silently.
TEST_F(VemdFiles, SlowSinkMakesCountedDropsAndTheSourceDeliversEveryFrame) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 60, false);
  auto source = vemd::ReplaySource::open(path, {{vemd::SourceRate::Mode::Fixed, 500.0}, false});
  ASSERT_TRUE(source);
  SinkUnderTest s;
  vemd::SinkSet sinks = sinksWith(s);
  s.sink->sleepPerFrame = 20ms;
  vemd::Pipeline pipeline = smallPipeline();
  std::atomic<bool> stop{false};
  const vemd::LoopResult result =
      vemd::runDaemonLoop(**source, pipeline, sinks, quietLoop(2), stop);
  EXPECT_EQ(result.reason, vemd::StopReason::EndOfStream);
  EXPECT_EQ(result.totals.framesIn, 60u);
  EXPECT_EQ(result.totals.processed + result.totals.dropped, 60u);
  EXPECT_GT(result.totals.dropped, 0u);
  EXPECT_EQ(s.log->seqs.size(), result.totals.processed);
  EXPECT_EQ(s.log->seqs.back(), 59u);  // the newest frame always gets through
}

// "As fast as possible" has no pace to protect: the replay waits for the pipeline and every
// frame is processed, in order.
TEST_F(VemdFiles, ReplayAtMaxRateProcessesEveryFrameInOrder) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 20, false);
  auto source = vemd::ReplaySource::open(path, {{vemd::SourceRate::Mode::Max, 0.0}, false});
  ASSERT_TRUE(source);
  SinkUnderTest s;
  vemd::SinkSet sinks = sinksWith(s);
  s.sink->sleepPerFrame = 2ms;
  vemd::Pipeline pipeline = smallPipeline();
  std::atomic<bool> stop{false};
  const vemd::LoopResult result =
      vemd::runDaemonLoop(**source, pipeline, sinks, quietLoop(1), stop);
  EXPECT_EQ(result.totals.processed, 20u);
  EXPECT_EQ(result.totals.dropped, 0u);
  ASSERT_EQ(s.log->seqs.size(), 20u);
  for (std::uint64_t i = 0; i < 20; ++i) EXPECT_EQ(s.log->seqs[i], i);
}

TEST_F(VemdFiles, FrameLimitStopsAfterExactlyNFramesOfALoopingReplay) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 5, false);
  auto source = vemd::ReplaySource::open(path, {{vemd::SourceRate::Mode::Max, 0.0}, true});
  ASSERT_TRUE(source);
  SinkUnderTest s;
  vemd::SinkSet sinks = sinksWith(s);
  vemd::Pipeline pipeline = smallPipeline();
  vemd::LoopOptions options = quietLoop();
  options.maxFrames = 13;
  std::atomic<bool> stop{false};
  const vemd::LoopResult result = vemd::runDaemonLoop(**source, pipeline, sinks, options, stop);
  EXPECT_EQ(result.reason, vemd::StopReason::FrameLimit);
  EXPECT_EQ(result.totals.framesIn, 13u);
  EXPECT_EQ(result.totals.processed, 13u);
  ASSERT_EQ(s.log->seqs.size(), 13u);
  for (std::uint64_t i = 0; i < 13; ++i) EXPECT_EQ(s.log->seqs[i], i);  // seq goes on across laps
}

TEST(DaemonLoop, FailingSinkIsDroppedOnceAndTheOthersKeepGoing) {
  ScriptedSource source(ScriptedSource::frames(10), false);
  SinkUnderTest failing, healthy;
  std::vector<std::unique_ptr<vem::Sink>> list;
  auto bad = std::make_unique<TestSink>("bad", failing.log);
  bad->failAtFrame = 3;
  list.push_back(std::move(bad));
  list.push_back(std::make_unique<TestSink>("good", healthy.log));
  vemd::SinkSet sinks(std::move(list));
  vemd::Pipeline pipeline = smallPipeline();
  std::atomic<bool> stop{false};
  const vemd::LoopResult result = vemd::runDaemonLoop(source, pipeline, sinks, quietLoop(), stop);
  EXPECT_EQ(result.totals.processed, 10u);
  EXPECT_EQ(result.sinkFailures, 1u);
  EXPECT_EQ(failing.log->seqs.size(), 3u);
  EXPECT_TRUE(failing.log->closed);  // closed when dropped: a recorder still writes its index
  EXPECT_EQ(healthy.log->seqs.size(), 10u);
  EXPECT_TRUE(healthy.log->closed);
  EXPECT_EQ(sinks.size(), 0u);
}

// A camera that is gone for a while: each failed attempt is counted and retried, and frames flow
// again afterwards; EndOfStream alone ends the run.
TEST(DaemonLoop, SourceErrorsAreRetriedAndCountedUntilFramesFlowAgain) {
  std::vector<ScriptedSource::Step> script = ScriptedSource::frames(3);
  for (int i = 0; i < 4; ++i) {
    script.push_back({SourceError{SourceErrorCause::NoDevice, "camera gone"}});
  }
  script.push_back({SourceError{SourceErrorCause::Timeout, "no frame in 1 s"}});
  for (int i = 0; i < 3; ++i) script.push_back({});
  ScriptedSource source(script, false);
  SinkUnderTest s;
  vemd::SinkSet sinks = sinksWith(s);
  vemd::Pipeline pipeline = smallPipeline();
  std::atomic<bool> stop{false};
  const vemd::LoopResult result = vemd::runDaemonLoop(source, pipeline, sinks, quietLoop(8), stop);
  EXPECT_EQ(result.reason, vemd::StopReason::EndOfStream);
  EXPECT_EQ(result.totals.sourceErrors, 5u);
  EXPECT_EQ(result.totals.processed, 6u);
}

// The loop tells its control why no frames come (the stream's Status): a lost camera shows as
// NoDevice while the capture thread retries, and the failure clears once frames flow again.
TEST(DaemonLoop, ControlSeesTheCameraGoneWhileRetryingAndBackWhenFramesFlow) {
  class StateLog final : public vem::LoopControl {
   public:
    void betweenFrames(vem::PipelineControl&, const vem::LoopCounters& counters) override {
      if (seen.empty() || seen.back() != counters.sourceFailure) seen.push_back(counters.sourceFailure);
    }
    std::vector<std::optional<SourceErrorCause>> seen;
  };
  std::vector<ScriptedSource::Step> script = ScriptedSource::frames(2);
  for (int i = 0; i < 100; ++i) {  // 100 attempts at the 4 ms backoff: several polls of the loop
    script.push_back({SourceError{SourceErrorCause::NoDevice, "camera gone"}});
  }
  for (int i = 0; i < 30; ++i) script.push_back({});
  ScriptedSource source(script, false);
  SinkUnderTest s;
  vemd::SinkSet sinks = sinksWith(s);
  vemd::Pipeline pipeline = smallPipeline();
  std::atomic<bool> stop{false};
  StateLog control;
  const vemd::LoopResult result =
      vemd::runDaemonLoop(source, pipeline, sinks, quietLoop(8), stop, nullptr, &control);
  EXPECT_EQ(result.totals.sourceErrors, 100u);
  const auto noDevice = std::find(control.seen.begin(), control.seen.end(),
                                  std::optional<SourceErrorCause>(SourceErrorCause::NoDevice));
  ASSERT_NE(noDevice, control.seen.end()) << "the control never saw the camera gone";
  EXPECT_NE(std::find(noDevice, control.seen.end(), std::nullopt), control.seen.end())
      << "the failure did not clear when frames flowed again";
}

// A stop request ends a source that never ends: the loop wakes the capture thread out of next(),
// closes the sinks and reports.
TEST(DaemonLoop, StopRequestEndsAnEndlessSourceAndClosesTheSinks) {
  ScriptedSource source(ScriptedSource::frames(1000), true);
  source.gate();
  SinkUnderTest s;
  vemd::SinkSet sinks = sinksWith(s);
  vemd::Pipeline pipeline = smallPipeline();
  std::atomic<bool> stop{false};
  vemd::LoopResult result;
  std::thread loop(
      [&] { result = vemd::runDaemonLoop(source, pipeline, sinks, quietLoop(), stop); });
  source.release(3);
  ASSERT_TRUE(source.awaitCalls(4));  // three frames out, the capture thread waits for a fourth
  stop = true;
  loop.join();
  EXPECT_EQ(result.reason, vemd::StopReason::StopRequested);
  EXPECT_EQ(result.totals.framesIn, 3u);
  EXPECT_TRUE(s.log->closed);
}

TEST(DaemonLoop, FramesThePipelineCannotTakeAreCountedAsBadAndSkipped) {
  class WrongSizeSource final : public vem::FrameSource {
   public:
    vem::SourceDescription describe() const override {
      vem::SourceDescription d;
      d.paced = false;
      return d;
    }
    std::expected<vem::CapturedFrame, SourceError> next() override {
      if (n_ == 6) return std::unexpected(SourceError{SourceErrorCause::EndOfStream, "end"});
      const bool bad = n_ % 2 == 1;
      vem::CapturedFrame f =
          captured(bad ? vem::RawFrame::blank(8, 8, {1, 12}) : cachedSkyFrame(int(n_)), n_);
      ++n_;
      return f;
    }
    void recycle(vem::CapturedFrame&&) override {}
    void interrupt() override {}

   private:
    std::uint64_t n_ = 0;
  } source;
  SinkUnderTest s;
  vemd::SinkSet sinks = sinksWith(s);
  vemd::Pipeline pipeline = smallPipeline();
  std::atomic<bool> stop{false};
  const vemd::LoopResult result = vemd::runDaemonLoop(source, pipeline, sinks, quietLoop(), stop);
  EXPECT_EQ(result.totals.processed, 3u);
  EXPECT_EQ(result.totals.badFrames, 3u);
  EXPECT_EQ(s.log->seqs, (std::vector<std::uint64_t>{0, 2, 4}));
}

TEST(DaemonLoop, ProcessedFramesGoBackToTheSourceForReuse) {
  ScriptedSource source(ScriptedSource::frames(12), false);
  SinkUnderTest s;
  vemd::SinkSet sinks = sinksWith(s);
  vemd::Pipeline pipeline = smallPipeline();
  std::atomic<bool> stop{false};
  (void)vemd::runDaemonLoop(source, pipeline, sinks, quietLoop(), stop);
  EXPECT_GT(source.recycled(), 0);
}

TEST(DaemonLoop, ObserverHearsFirstFrameOnceAndAliveWhileRunning) {
  struct Counting final : vemd::LoopObserver {
    int firstFrames = 0, alives = 0, stops = 0;
    void firstFrameProcessed() override { ++firstFrames; }
    void alive() override { ++alives; }
    void stopping() override { ++stops; }
  } observer;
  ScriptedSource source(ScriptedSource::frames(5), false);
  vemd::SinkSet sinks;
  vemd::Pipeline pipeline = smallPipeline();
  std::atomic<bool> stop{false};
  (void)vemd::runDaemonLoop(source, pipeline, sinks, quietLoop(), stop, &observer);
  EXPECT_EQ(observer.firstFrames, 1);
  EXPECT_GE(observer.alives, 5);
  EXPECT_EQ(observer.stops, 1);
}

}  // namespace
}  // namespace vem::testing
