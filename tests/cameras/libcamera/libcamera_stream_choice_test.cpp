// Which stream vemd asks for (libcamera_stream_choice.h).
#include "cameras/libcamera/libcamera_stream_choice.h"

#include <gtest/gtest.h>

#include "cameras/libcamera/libcamera_pixel_layout.h"

namespace vem::cameras {
namespace {

const LibcameraPixelFormat kYuyv{drmFourcc('Y', 'U', 'Y', 'V'), 0};
const LibcameraPixelFormat kMjpeg{drmFourcc('M', 'J', 'P', 'G'), 0};

LibcameraCameraInfo mixedCamera() {
  return {"cam0",
          "mixed",
          {{LibcameraRole::VideoRecording, kLibcameraRGB888, {{640, 480}, {1920, 1080}}},
           {LibcameraRole::Raw, kLibcameraR8, {{1280, 1024}}},
           {LibcameraRole::Raw, kLibcameraR16, {{640, 512}, {1280, 1024}}},
           {LibcameraRole::VideoRecording, kLibcameraR16, {{1280, 1024}}}}};
}

TEST(LibcameraStreamChoice, DeepestFormatAtItsLargestSizeWhenNoneIsAsked) {
  const auto config = chooseLibcameraStream(mixedCamera(), {}, "libcamera:cam0");
  ASSERT_TRUE(config) << config.error();
  EXPECT_EQ(config->format, kLibcameraR16);
  EXPECT_EQ(config->role, LibcameraRole::Raw);  // mono: the sensor's own codes
  EXPECT_EQ(config->size, (LibcameraSize{1280, 1024}));
}

TEST(LibcameraStreamChoice, AskedFormatAndSizeAndBufferFloorAreKept) {
  CameraSettings s;
  s.pixelFormat = "RGB8";
  s.widthPx = 640;
  s.heightPx = 480;
  s.buffers = 1;
  const auto config = chooseLibcameraStream(mixedCamera(), s, "libcamera:cam0");
  ASSERT_TRUE(config) << config.error();
  EXPECT_EQ(config->format, kLibcameraRGB888);
  EXPECT_EQ(config->role, LibcameraRole::VideoRecording);
  EXPECT_EQ(config->size, (LibcameraSize{640, 480}));
  EXPECT_EQ(config->bufferCount, 2);
}

TEST(LibcameraStreamChoice, CameraOfferingNothingTakenIsRefusedNamingItsOffer) {
  const LibcameraCameraInfo camera{"usb",
                                   "webcam",
                                   {{LibcameraRole::VideoRecording, kYuyv, {{640, 480}}},
                                    {LibcameraRole::VideoRecording, kMjpeg, {{1920, 1080}}}}};
  const auto config = chooseLibcameraStream(camera, {}, "libcamera:usb");
  ASSERT_FALSE(config);
  EXPECT_NE(config.error().find("YUYV 640x480 (VideoRecording)"), std::string::npos)
      << config.error();
  EXPECT_NE(config.error().find("MJPEG 1920x1080"), std::string::npos) << config.error();
  EXPECT_NE(config.error().find("vemd takes R16"), std::string::npos) << config.error();
}

TEST(LibcameraStreamChoice, MisspelledPixelFormatIsRefusedNamingIt) {
  CameraSettings s;
  s.pixelFormat = "Mono14";
  const auto config = chooseLibcameraStream(mixedCamera(), s, "libcamera:cam0");
  ASSERT_FALSE(config);
  EXPECT_NE(config.error().find("\"Mono14\""), std::string::npos) << config.error();
}

TEST(LibcameraStreamChoice, ModesListOnlyWhatVemdTakesOnce) {
  const auto modes = libcameraModes(mixedCamera());
  EXPECT_EQ(std::count(modes.begin(), modes.end(), "Mono16 1280x1024 (R16, Raw)"), 1);
  EXPECT_EQ(std::count(modes.begin(), modes.end(), "RGB8 640x480 (RGB888, VideoRecording)"), 1);
  EXPECT_EQ(modes.size(), 6u);
}

}  // namespace
}  // namespace vem::cameras
