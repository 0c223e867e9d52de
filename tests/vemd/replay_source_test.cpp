// ReplaySource: frames as recorded, laps that keep seq and time increasing, buffer reuse,
// interrupts, and the end of a recording.
#include "vemd/replay_source.h"

#include <chrono>
#include <condition_variable>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>

#include "recording/recording_reader.h"

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
  const vem::SourceDescription d = source->describe();
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
  EXPECT_EQ(end.error().cause, vem::SourceErrorCause::EndOfStream);
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
  EXPECT_EQ(interrupted.error().cause, vem::SourceErrorCause::Timeout);
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
  EXPECT_EQ(frame.error().cause, vem::SourceErrorCause::Timeout);
}

// Every frame record of `path` damaged (one byte flipped inside each); the index stays intact.
void damageEveryFrame(const fs::path& path) {
  std::vector<std::uint64_t> offsets;
  {
    auto reader = recording::RecordingReader::open(path);
    ASSERT_TRUE(reader && reader->hasIndex());
    for (const recording::IndexEntry& entry : reader->index()) offsets.push_back(entry.offset);
  }
  std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
  for (const std::uint64_t offset : offsets) {
    file.seekg(std::streamoff(offset + 100));
    char byte = 0;
    file.read(&byte, 1);
    byte = char(byte ^ 0x40);
    file.seekp(std::streamoff(offset + 100));
    file.write(&byte, 1);
  }
  ASSERT_TRUE(file.good());
}

// A recording with a valid header but no intact frame opened and then ended at once, so vemd
// "replayed" it and exited 0. It is refused when it is opened, in one sentence naming the file.
TEST_F(ReplaySourceFiles, RecordingWithNoIntactFrameIsRefusedAtOpen) {
  const fs::path empty = dir_ / "empty.vem";
  writeSkyRecording(empty, 0, false);
  const fs::path damaged = dir_ / "damaged.vem";
  writeSkyRecording(damaged, 3, false);
  damageEveryFrame(damaged);
  const std::vector<std::pair<fs::path, std::string>> cases{{empty, "damaged records: 0"},
                                                            {damaged, "damaged records: 1"}};
  for (const auto& [path, damage] : cases) {
    for (const bool loop : {false, true}) {
      auto source = vemd::ReplaySource::open(path, {kMax, loop});
      ASSERT_FALSE(source) << path << (loop ? " looping" : "");
      EXPECT_EQ(source.error().cause, vem::SourceErrorCause::NoDevice);
      EXPECT_EQ(source.error().message, path.string() + ": the recording holds no intact frame (" +
                                            damage +
                                            ", truncated tail: 0 bytes), so there is nothing "
                                            "to replay");
    }
  }
}

// Log lines of the default logger while it lives, as "level|message".
class CapturedLog {
 public:
  CapturedLog()
      : ring_(std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(64)),
        previous_(spdlog::default_logger()) {
    auto logger = std::make_shared<spdlog::logger>("test", ring_);
    logger->set_pattern("%l|%v");
    spdlog::set_default_logger(logger);
  }
  ~CapturedLog() { spdlog::set_default_logger(previous_); }
  CapturedLog(const CapturedLog&) = delete;
  CapturedLog& operator=(const CapturedLog&) = delete;

  [[nodiscard]] std::vector<std::string> lines() const {
    std::vector<std::string> lines = ring_->last_formatted();
    for (std::string& line : lines) {
      if (line.ends_with('\n')) line.pop_back();
    }
    return lines;
  }

 private:
  std::shared_ptr<spdlog::sinks::ringbuffer_sink_mt> ring_;
  std::shared_ptr<spdlog::logger> previous_;
};

// Capture times 0, 1e18, 2e18, 3e18 ns made `--rate recorded` wait about 31 years per frame,
// silently. Each jump now takes one nominal period (1 ms at this header's 1000 Hz); the first of
// the run is a warning, the end of the run says how many there were, nothing is logged per frame.
TEST_F(ReplaySourceFiles, AbsurdCaptureTimesAreNotWaitedOutAndWarnedOncePerRun) {
  recording::RecordingHeader header = smallRecordingHeader();
  header.nominalRateHz = 1000.0;
  const fs::path path = dir_ / "jumps.vem";
  const std::vector<std::int64_t> stamps{0,
                                         1'000'000'000'000'000'000,
                                         2'000'000'000'000'000'000,
                                         3'000'000'000'000'000'000,
                                         3'000'000'000'001'000'000,
                                         3'000'000'000'002'000'000};
  {
    auto writer = recording::RecordingWriter::create(path, header);
    ASSERT_TRUE(writer) << writer.error().message;
    for (std::size_t i = 0; i < stamps.size(); ++i) {
      ASSERT_TRUE(writer->append(i, stamps[i], cachedSkyFrame(int(i))));
    }
    ASSERT_TRUE(writer->close());
  }
  const CapturedLog log;
  auto source = openReplay(path, {SourceRate::Mode::Recorded, 0.0}, false);
  ASSERT_TRUE(source);

  // A wait that is not skipped is cut short after a generous bound, so the test fails instead of
  // hanging for years.
  std::mutex mutex;
  std::condition_variable done;
  bool finished = false;
  std::thread watchdog([&] {
    std::unique_lock lock(mutex);
    if (!done.wait_for(lock, std::chrono::seconds(30), [&] { return finished; })) {
      source->interrupt();
    }
  });
  std::vector<std::int64_t> delivered;
  for (std::size_t i = 0; i < stamps.size(); ++i) {
    auto frame = source->next();
    if (!frame) {
      ADD_FAILURE() << "frame " << i << ": " << frame.error().message;
      break;
    }
    delivered.push_back(frame->captureTsNs);
  }
  {
    std::lock_guard lock(mutex);
    finished = true;
  }
  done.notify_all();
  watchdog.join();
  EXPECT_EQ(delivered, stamps) << "the frames keep their recorded capture times";

  std::vector<std::string> warnings, infos;
  for (const std::string& line : log.lines()) {
    if (line.starts_with("warning|")) warnings.push_back(line);
    if (line.starts_with("info|")) infos.push_back(line);
  }
  ASSERT_EQ(warnings.size(), 1U) << ::testing::PrintToString(log.lines());
  EXPECT_EQ(warnings[0],
            "warning|" + path.string() +
                ": the capture time jumps from 0 ns to 1000000000000000000 ns before frame 1 "
                "(expected a step of 0 to 10 s); replaying that step as one frame period (1.000 "
                "ms) instead of waiting it out (further jumps are counted, not logged, until the "
                "capture times are regular again)");
  ASSERT_EQ(infos.size(), 1U) << ::testing::PrintToString(log.lines());
  EXPECT_EQ(infos[0], "info|" + path.string() +
                          ": capture times regular again after 3 jump(s) replayed as one frame "
                          "period each");
}

}  // namespace
}  // namespace vem::testing
