// Small fake cameras and frames for V4l2Source's tests: a FakeV4l2Camera with one or two formats,
// settings that ask for them, and frames of known codes pushed through it.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "cameras/v4l2/fake_v4l2_camera.h"
#include "cameras/v4l2/fake_v4l2_frames.h"
#include "cameras/v4l2/v4l2_source.h"

namespace vem::testing {

inline constexpr const char* kFakePath = "/dev/video0";

inline FakeV4l2Config fakeConfig(std::uint32_t fourcc, int widthPx, int heightPx,
                                 std::size_t rowAlignBytes = 1) {
  FakeV4l2Config c;
  c.formats = {{fourcc, {{widthPx, heightPx}}}};
  c.rowAlignBytes = rowAlignBytes;
  return c;
}

inline cameras::CameraSettings settingsFor(const std::string& pixelFormat, int widthPx,
                                           int heightPx) {
  cameras::CameraSettings s;
  s.pixelFormat = pixelFormat;
  s.widthPx = widthPx;
  s.heightPx = heightPx;
  s.timeoutMs = 2000;
  return s;
}

inline std::unique_ptr<cameras::V4l2Source> openSource(FakeV4l2Camera& camera,
                                                       const cameras::CameraSettings& settings) {
  auto source = cameras::V4l2Source::open(kFakePath, camera.opener(kFakePath), settings);
  EXPECT_TRUE(source) << (source ? "" : source.error().message);
  return source ? std::move(*source) : nullptr;
}

// width x height x values-per-pixel random codes below 2^bits.
inline std::vector<std::uint16_t> randomCodes(std::size_t count, int bits, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::vector<std::uint16_t> codes(count);
  for (auto& c : codes) c = std::uint16_t(random() & ((1u << bits) - 1u));
  return codes;
}

inline FakeFrame fakeFrame(const FakeV4l2Camera& camera, const std::vector<std::uint16_t>& codes) {
  FakeFrame f;
  f.bytes = encodeFakeFrame(codes, camera.format());
  return f;
}

}  // namespace vem::testing
