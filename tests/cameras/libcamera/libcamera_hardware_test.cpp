// Real cameras through libcamera (label `hardware`): lists what libcamera sees, and when it sees a
// camera vemd can take, captures a few frames from it. Skips when libcamera lists no camera.
#include <algorithm>
#include <cstdio>

#include <gtest/gtest.h>

#include "cameras/libcamera/libcamera_devices.h"
#include "cameras/libcamera/libcamera_source.h"

namespace vem::cameras {
namespace {

TEST(LibcameraHardware, ListsCamerasAndCapturesFromTheFirstItTakes) {
  auto devices = listLibcameraDevices();
  ASSERT_TRUE(devices) << devices.error();
  if (devices->empty()) GTEST_SKIP() << "libcamera lists no camera";
  for (const DeviceInfo& d : *devices) {
    std::printf("%s (%s): %zu modes\n", d.spec.c_str(), d.model.c_str(), d.modes.size());
  }
  const auto usable = std::find_if(devices->begin(), devices->end(),
                                   [](const DeviceInfo& d) { return !d.modes.empty(); });
  if (usable == devices->end()) GTEST_SKIP() << "no camera offers a format vemd takes";
  CameraSettings settings;
  settings.timeoutMs = 3000;
  auto source =
      LibcameraSource::open(usable->spec.substr(std::string("libcamera:").size()), settings);
  ASSERT_TRUE(source) << source.error().message;
  std::uint64_t lastSeq = 0;
  int frames = 0;
  for (int k = 0; k < 20 && frames < 5; ++k) {
    auto frame = (*source)->next();
    if (!frame) continue;
    if (frames > 0) {
      EXPECT_GT(frame->seq, lastSeq);
    }
    EXPECT_LE(frame->captureTsNs, frame->arrivalNs);
    lastSeq = frame->seq;
    ++frames;
    (*source)->recycle(std::move(*frame));
  }
  EXPECT_EQ(frames, 5);
}

}  // namespace
}  // namespace vem::cameras
