// Against a real V4L2 capture device (label `hardware`, opt-in): the first capture node under
// /dev, or the one VEM_V4L2_DEVICE names. Skips when there is none, or v4l2-compliance is missing
// for the compliance check.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "cameras/v4l2/v4l2_device_list.h"
#include "cameras/v4l2/v4l2_source.h"

namespace vem::cameras {
namespace {

std::string captureDevice() {
  if (const char* named = std::getenv("VEM_V4L2_DEVICE")) return named;
  auto devices = listV4l2Devices();
  if (!devices) return "";
  for (const DeviceInfo& d : *devices) {
    if (!d.model.starts_with("(cannot open")) return d.spec.substr(5);
  }
  return "";
}

TEST(V4l2Hardware, TheCameraStreamsTenFramesWithIncreasingSeqAndMonotonicTimestamps) {
  const std::string path = captureDevice();
  if (path.empty()) GTEST_SKIP() << "no V4L2 capture device under /dev (set VEM_V4L2_DEVICE)";
  CameraSettings settings;
  settings.timeoutMs = 3000;
  auto source = V4l2Source::open(path, settings);
  ASSERT_TRUE(source) << source.error().message;
  const vem::SourceDescription d = (*source)->describe();
  std::printf("%s: %s (%s) %dx%d %s at %.2f Hz\n", d.spec.c_str(), d.cameraModel.c_str(),
              d.cameraSerial.c_str(), d.sensorWidthPx, d.sensorHeightPx,
              vem::pixelFormatName(d.pixelFormat).c_str(), d.nominalRateHz);
  std::uint64_t lastSeq = 0;
  std::int64_t lastTs = 0;
  int frames = 0;
  for (int attempt = 0; attempt < 40 && frames < 10; ++attempt) {
    auto frame = (*source)->next();
    if (!frame) {
      ASSERT_NE(frame.error().cause, vem::SourceErrorCause::NoDevice) << frame.error().message;
      continue;
    }
    if (frames > 0) {
      EXPECT_GT(frame->seq, lastSeq);
      EXPECT_GT(frame->captureTsNs, lastTs);
    }
    EXPECT_LE(frame->captureTsNs, frame->arrivalNs);
    EXPECT_EQ(frame->frame.width, d.sensorWidthPx);
    lastSeq = frame->seq;
    lastTs = frame->captureTsNs;
    ++frames;
    (*source)->recycle(std::move(*frame));
  }
  EXPECT_EQ(frames, 10);
}

TEST(V4l2Hardware, TheDriverPassesV4l2Compliance) {
  const std::string path = captureDevice();
  if (path.empty()) GTEST_SKIP() << "no V4L2 capture device under /dev";
  const std::string tool = VEM_V4L2_COMPLIANCE;
  if (tool.empty()) GTEST_SKIP() << "v4l2-compliance (v4l-utils) is not installed";
  const std::string command = tool + " -d " + path + " -s10 > /dev/null 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << "run `" << tool << " -d " << path << " -s10`";
}

}  // namespace
}  // namespace vem::cameras
