// vemd's start-up (daemon/vemd/daemon_setup.h): a stop asked for while it builds stops it between
// steps or between the polar remap's rows, closing what it opened; the map size and the frames a
// queue may hold are bounded (docs/vemd.md, "Limits").
#include "vemd/daemon_setup.h"

#include <atomic>
#include <string>

#include <gtest/gtest.h>

#include "calib/core/polar_remap.h"
#include "recording/recording_reader.h"
#include "vemd/pipeline.h"
#include "vemd/pipeline_setup.h"
#include "vemd_fixtures.h"

namespace vem::testing {
namespace {

class Startup : public VemdFiles {
 protected:
  // A replay of a small recording into small maps, with a recording sink, no server.
  vemd::VemdConfig replayConfig() {
    const fs::path recording = dir_ / "sky.vem";
    writeSkyRecording(recording, 3, false);
    vemd::VemdConfig config;
    config.source.spec = "replay:" + recording.string();
    config.processing = smallProcessing();
    config.output.record = (dir_ / "out.vem").string();
    config.stream.enabled = false;
    return config;
  }
};

// Catches a start-up that ignores a stop: the check is asked before the long step and the build
// ends there, saying it stopped (not failed), with nothing built.
TEST_F(Startup, StopRequestedWhileOpeningTheSourceEndsStartUpAsStopped) {
  const vemd::VemdConfig config = replayConfig();
  int asked = 0;
  auto daemon = vemd::buildDaemon(config, {}, [&] {
    ++asked;
    return true;
  });
  ASSERT_FALSE(daemon);
  EXPECT_EQ(daemon.error().cause, vemd::StartupFailure::Cause::Stopped);
  EXPECT_EQ(daemon.error().message, "a stop was requested while opening the source");
  EXPECT_EQ(asked, 1);
  EXPECT_FALSE(fs::exists(dir_ / "out.vem"));
}

// Catches a remap build that runs to its end whatever happens (a 16384 x 16384 map went on for
// 55 s after SIGTERM): asked before every row, it stops at the first "true", and the pipeline is
// not made.
TEST_F(Startup, StopRequestedWhileBuildingTheRemapAbandonsItAtTheNextRow) {
  vem::ProcessingOptions options = smallProcessing();
  int asked = 0;
  auto pipeline = vemd::pipelineFromCameraFile(smallCameraToml(), "cam", options, [&] {
    ++asked;
    return asked == 10;
  });
  ASSERT_FALSE(pipeline);
  EXPECT_EQ(pipeline.error(), "cam: stopped while building the 256 x 64 polar remap");
  EXPECT_EQ(asked, 10);
}

// Catches a cancellable build that differs from the plain one (it must only add the questions).
TEST(PolarRemapBuild, AskingBetweenRowsGivesTheSameTableAsThePlainBuild) {
  const calib::CameraCalibration camera = smallCamera();
  const calib::PolarRemap plain = calib::buildPolarRemap(
      *camera.lens, camera.orientation, kSensorWidth, kSensorHeight, MapLayout::Hemisphere, 96, 24);
  int asked = 0;
  const auto asking = calib::buildPolarRemap(*camera.lens, camera.orientation, kSensorWidth,
                                             kSensorHeight, MapLayout::Hemisphere, 96, 24, [&] {
                                               ++asked;
                                               return false;
                                             });
  ASSERT_TRUE(asking);
  EXPECT_EQ(asked, 24);
  EXPECT_EQ(asking->topLeftTap, plain.topLeftTap);
  EXPECT_EQ(asking->fractionU, plain.fractionU);
  EXPECT_EQ(asking->fractionV, plain.fractionV);
}

// Catches a stop after the sinks opened that leaves them open: the recording vemd had created is
// closed with its index (a readable, empty recording), and start-up ends as stopped.
TEST_F(Startup, StopRequestedAfterTheSinksOpenedClosesTheRecordingWithItsIndex) {
  const vemd::VemdConfig config = replayConfig();
  std::atomic<bool> stop{false};
  auto daemon = vemd::buildDaemon(
      config,
      [&](const vem::SourceDescription&,
          std::vector<std::unique_ptr<vem::Sink>>&) -> std::expected<void, std::string> {
        stop = true;  // as a signal arriving while the stream server starts
        return {};
      },
      [&] { return stop.load(); });
  ASSERT_FALSE(daemon);
  EXPECT_EQ(daemon.error().cause, vemd::StartupFailure::Cause::Stopped);
  EXPECT_EQ(daemon.error().message, "a stop was requested while opening the sinks");
  auto reader = recording::RecordingReader::open(dir_ / "out.vem");
  ASSERT_TRUE(reader) << reader.error().message;
  EXPECT_TRUE(reader->hasIndex());
}

// Catches a queue whose frames could take more memory than vemd's budget: 4096 x 3072 RGB16
// frames are 72 MiB, so 8 queued (20 held) would be 1440 MiB; 5 (14 held, 1008 MiB) fit.
TEST(FrameMemory, QueueOfLargeFramesBeyondTheBudgetIsRefusedNamingTheDepthThatFits) {
  vem::SourceDescription source;
  source.spec = "v4l2:/dev/video0";
  source.sensorWidthPx = 4096;
  source.sensorHeightPx = 3072;
  source.pixelFormat = *vem::parsePixelFormat("RGB16");
  EXPECT_EQ(vemd::frameMemoryProblem(source, 8),
            "v4l2:/dev/video0: its 4096 x 3072 RGB16 frames take 72.0 MiB each, and with "
            "source.queue_depth = 8 vemd may hold 20 of them (1440 MiB), above its 1024 MiB "
            "budget for frames; set source.queue_depth to 5 or less");
  EXPECT_EQ(vemd::frameMemoryProblem(source, 5), std::nullopt);
  EXPECT_TRUE(vemd::frameMemoryProblem(source, 6).has_value());
}

// Catches a frame so large that not even a queue of one fits: the sentence asks for smaller
// frames instead of an impossible depth.
TEST(FrameMemory, FramesTooLargeForAnyQueueAskForASmallerFrameSize) {
  vem::SourceDescription source;
  source.spec = "replay:huge.vem";
  source.sensorWidthPx = 16384;
  source.sensorHeightPx = 16384;
  source.pixelFormat = *vem::parsePixelFormat("RGB16");
  const auto problem = vemd::frameMemoryProblem(source, 1);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("use a smaller frame size ([camera] width_px, height_px)"),
            std::string::npos)
      << *problem;
}

// Catches the pipeline accepting a map beyond the start-up limit when it is built in code (the
// stream's control path and tests build ProcessingOptions without the configuration file).
TEST(PipelineLimits, MapBeyondTheStartUpLimitIsRefusedByThePipelineToo) {
  vem::ProcessingOptions options = smallProcessing();
  options.mapWidth = 16384;
  options.mapHeight = 16384;
  auto pipeline = vemd::pipelineFromCameraFile(smallCameraToml(), "cam", options);
  ASSERT_FALSE(pipeline);
  EXPECT_EQ(pipeline.error(),
            "the polar map must be 4 to 4096 pixels wide and 4 to 2048 high (start-up time and "
            "memory grow with width x height), not 16384 x 16384");
}

}  // namespace
}  // namespace vem::testing
