// ReplaySource: frames as recorded, laps that keep seq and time increasing, buffer reuse,
// interrupts, and the end of a recording.
#include "vemd/replay_source.h"

#include <gtest/gtest.h>

#include "vemd_fixtures.h"

namespace vem::testing {
namespace {

using ReplaySourceFiles = VemdFiles;
using vemd::SourceRate;

std::unique_ptr<vemd::ReplaySource> openReplay(const fs::path& path, SourceRate rate, bool loop) {
  auto source = vemd::ReplaySource::open(path, {rate, loop});
  EXPECT_TRUE(source) << (source ? "" : source.error().message);
  return source ? std::move(*source) : nullptr;
}

const SourceRate kMax{SourceRate::Mode::Max, 0.0};

TEST_F(ReplaySourceFiles, FramesComeBackAsRecordedWithTheHeadersDescription) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 3, false);
  auto source = openReplay(path, kMax, false);
  ASSERT_TRUE(source);
  const vemd::SourceDescription d = source->describe();
  EXPECT_EQ(d.spec, "replay:" + path.string());
  EXPECT_EQ(d.sensorWidthPx, kSensorWidth);
  EXPECT_EQ(d.calibrationToml, smallCameraToml());
  EXPECT_EQ(d.nominalRateHz, 30.0);
  EXPECT_FALSE(d.paced);
  EXPECT_FALSE(d.liveClock);
  for (int i = 0; i < 3; ++i) {
    auto frame = source->next();
    ASSERT_TRUE(frame) << frame.error().message;
    EXPECT_EQ(frame->seq, std::uint64_t(i));
    EXPECT_EQ(frame->captureTsNs, i * kFramePeriodNs);
    EXPECT_EQ(frame->frame.codes, cachedSkyFrame(i).codes);
    EXPECT_EQ(frame->frame.exposureUs, cachedSkyFrame(i).exposureUs);
    EXPECT_GT(frame->arrivalNs, 0);
  }
  auto end = source->next();
  ASSERT_FALSE(end);
  EXPECT_EQ(end.error().cause, vemd::SourceErrorCause::EndOfStream);
  EXPECT_EQ(end.error().message, path.string() + ": end of the recording (3 frames)");
}

// Each lap follows the last: seq by one, time by one period, so the temporal filter sees one
// stream (a restart at seq 0 would be rejected as stale, a jump would reset it).
TEST_F(ReplaySourceFiles, LoopKeepsSeqAndTimestampsIncreasingAcrossLaps) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 4, false);
  auto source = openReplay(path, kMax, true);
  ASSERT_TRUE(source);
  for (int i = 0; i < 11; ++i) {
    auto frame = source->next();
    ASSERT_TRUE(frame) << frame.error().message;
    EXPECT_EQ(frame->seq, std::uint64_t(i));
    EXPECT_EQ(frame->captureTsNs, i * kFramePeriodNs) << i;
    EXPECT_EQ(frame->frame.codes, cachedSkyFrame(i % 4).codes);
  }
  EXPECT_EQ(source->laps(), 2u);
}

TEST_F(ReplaySourceFiles, RecycledBuffersAreReusedForLaterFrames) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 4, false);
  auto source = openReplay(path, kMax, false);
  ASSERT_TRUE(source);
  auto first = source->next();
  ASSERT_TRUE(first);
  const std::uint16_t* buffer = first->frame.codes.data();
  source->recycle(std::move(*first));
  auto second = source->next();  // decoded into the recycled buffer
  ASSERT_TRUE(second);
  EXPECT_EQ(second->frame.codes.data(), buffer);
  EXPECT_EQ(second->frame.codes, cachedSkyFrame(1).codes);
}

TEST_F(ReplaySourceFiles, InterruptEndsAWaitWithTimeoutAndLosesNoFrame) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 3, false);
  auto source = openReplay(path, {SourceRate::Mode::Fixed, 0.01}, false);  // 100 s per frame
  ASSERT_TRUE(source);
  auto first = source->next();  // the first frame is due at once
  ASSERT_TRUE(first);
  std::thread interrupter([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    source->interrupt();
  });
  auto interrupted = source->next();  // waits 100 s unless interrupted
  interrupter.join();
  ASSERT_FALSE(interrupted);
  EXPECT_EQ(interrupted.error().cause, vemd::SourceErrorCause::Timeout);
}

// An interrupt that arrives while nobody waits is kept for the next wait: a stop requested just
// before the capture thread calls next() is not lost.
TEST_F(ReplaySourceFiles, InterruptBeforeTheWaitIsNotLost) {
  const fs::path path = dir_ / "sky.vem";
  writeSkyRecording(path, 3, false);
  auto source = openReplay(path, {SourceRate::Mode::Fixed, 0.01}, false);
  ASSERT_TRUE(source);
  ASSERT_TRUE(source->next());
  source->interrupt();
  auto frame = source->next();
  ASSERT_FALSE(frame);
  EXPECT_EQ(frame.error().cause, vemd::SourceErrorCause::Timeout);
}

TEST_F(ReplaySourceFiles, RecordingWithoutFramesEndsAtOnceEvenWhenLooping) {
  const fs::path path = dir_ / "empty.vem";
  writeSkyRecording(path, 0, false);
  auto source = openReplay(path, kMax, true);
  ASSERT_TRUE(source);
  auto frame = source->next();
  ASSERT_FALSE(frame);
  EXPECT_EQ(frame.error().cause, vemd::SourceErrorCause::EndOfStream);
  EXPECT_EQ(frame.error().message, path.string() + ": the recording holds no intact frame");
}

}  // namespace
}  // namespace vem::testing
