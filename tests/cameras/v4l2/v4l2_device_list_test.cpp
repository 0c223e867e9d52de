// Listing V4L2 cameras and finding one by card name, over fake nodes.
#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>

#include "cameras/v4l2/v4l2_device_list.h"
#include "cameras/v4l2/v4l2_source_fixtures.h"

namespace vem::testing {
namespace {

// /dev/video0: a capture camera; /dev/video1: its metadata node; /dev/video2: no permission.
struct FakeNodes {
  FakeV4l2Camera camera{[] {
    FakeV4l2Config c;
    c.card = "Ricoh Theta V";
    c.busInfo = "usb-0000:00:14.0-3";
    c.formats = {{V4L2_PIX_FMT_YUYV, {{1920, 960}, {3840, 1920}}},
                 {V4L2_PIX_FMT_MJPEG, {{3840, 1920}}}};
    return c;
  }()};
  FakeV4l2Camera metadata{[] {
    FakeV4l2Config c;
    c.card = "Ricoh Theta V";
    c.deviceCaps = V4L2_CAP_META_CAPTURE | V4L2_CAP_STREAMING;
    c.formats = {{V4L2_PIX_FMT_GREY, {{1, 1}}}};
    return c;
  }()};

  cameras::V4l2Opener opener() {
    return
        [this](
            const std::string& path) -> std::expected<std::unique_ptr<cameras::V4l2Device>, int> {
          if (path == "/dev/video0") return camera.open();
          if (path == "/dev/video1") return metadata.open();
          if (path == "/dev/video2") return std::unexpected(EACCES);
          return std::unexpected(ENOENT);
        };
  }
};

TEST(V4l2DeviceList, CaptureNodesAreListedWithTheirModesAndUnopenableOnesWithTheReason) {
  FakeNodes nodes;
  const auto devices =
      cameras::listV4l2Devices({"/dev/video0", "/dev/video1", "/dev/video2"}, nodes.opener());
  ASSERT_EQ(devices.size(), 2u);
  EXPECT_EQ(devices[0].spec, "v4l2:/dev/video0");
  EXPECT_EQ(devices[0].model, "Ricoh Theta V");
  EXPECT_EQ(devices[0].serial, "usb-0000:00:14.0-3");
  EXPECT_EQ(devices[0].modes,
            (std::vector<std::string>{"YUYV 1920x960 (as RGB8)", "YUYV 3840x1920 (as RGB8)",
                                      "MJPG 3840x1920 (not readable)"}));
  EXPECT_EQ(devices[1].spec, "v4l2:/dev/video2");
  EXPECT_EQ(devices[1].model, "(cannot open /dev/video2: Permission denied)");
}

TEST(V4l2DeviceList, ACameraIsFoundByItsCardNameSkippingItsMetadataNode) {
  FakeNodes nodes;
  auto opener = nodes.opener();
  const std::vector<std::string> paths = {"/dev/video1", "/dev/video2", "/dev/video0"};
  auto found = cameras::openV4l2ByCardName("Ricoh Theta V", paths, opener);
  ASSERT_TRUE(found);
  auto missing = cameras::openV4l2ByCardName("Other", paths, opener);
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error(), ENOENT);
  // Through the source, by name, as `--source v4l2:NAME` does.
  auto source = cameras::V4l2Source::open(
      "Ricoh Theta V",
      [&](const std::string& name) { return cameras::openV4l2ByCardName(name, paths, opener); },
      settingsFor("RGB8", 1920, 960));
  ASSERT_TRUE(source) << source.error().message;
  EXPECT_EQ((*source)->describe().spec, "v4l2:Ricoh Theta V");
}

TEST(V4l2DeviceList, VideoNodesAreSortedByNumberNotByName) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("vem_v4l2_nodes_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const char* name : {"video10", "video2", "video0", "vbi0", "video1x"}) {
    std::ofstream(dir / name) << "";
  }
  const auto paths = cameras::videoNodePaths(dir.string());
  std::filesystem::remove_all(dir);
  ASSERT_EQ(paths.size(), 3u);
  EXPECT_EQ(paths[0], (dir / "video0").string());
  EXPECT_EQ(paths[1], (dir / "video2").string());
  EXPECT_EQ(paths[2], (dir / "video10").string());
}

}  // namespace
}  // namespace vem::testing
