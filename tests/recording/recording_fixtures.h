// Small recordings for the recording tests: a calibrated camera's header, deterministic frames
// with sensor-like content, light sets holding awkward floats, and file helpers.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "calib/io/camera_file.h"
#include "recording/frame_codec.h"
#include "recording/recording_header.h"
#include "recording/recording_reader.h"
#include "recording/recording_writer.h"
#include "support/test_cameras.h"

namespace vem::testing {

namespace fs = std::filesystem;

inline constexpr int kSmallWidth = 64;
inline constexpr int kSmallHeight = 48;
inline constexpr double kSmallRateHz = 30.0;
inline constexpr std::int64_t kPeriodNs = 33'333'333;

inline recording::RecordingHeader smallHeader(int channels = 1, int bits = 12) {
  calib::CameraCalibration camera = cameraTruth(kSmallWidth, kSmallHeight, channels);
  camera.camera.pixelFormat = {channels, bits};
  recording::RecordingHeader h;
  h.cameraModel = camera.camera.model;
  h.cameraSerial = camera.camera.serial;
  h.sensorWidthPx = kSmallWidth;
  h.sensorHeightPx = kSmallHeight;
  h.pixelFormat = camera.camera.pixelFormat;
  h.nominalRateHz = kSmallRateHz;
  h.calibrationToml = calib::io::formatCameraFile(camera);
  h.createdUnixNs = 1'760'000'000'000'000'000;
  h.writerName = "vem_recording_tests";
  h.writerVersion = "0.1.0";
  return h;
}

// A smooth gradient with a bright blob that moves with `index`, plus pseudo-random noise: codes
// in [0, maxCode], different in every frame.
inline vem::RawFrame smallFrame(const recording::RecordingHeader& h, int index) {
  vem::RawFrame f = vem::RawFrame::blank(h.sensorWidthPx, h.sensorHeightPx, h.pixelFormat);
  f.exposureUs = 1000.0 + 0.1 * index;
  f.gain = 1.0 + 1.0 / 3.0 * index;  // not a short decimal: tests the bits
  std::uint32_t state = 2463534242u + std::uint32_t(index) * 7919u;
  const double maxCode = double(h.pixelFormat.maxCode());
  for (int v = 0; v < f.height; ++v) {
    for (int u = 0; u < f.width; ++u) {
      for (int c = 0; c < h.pixelFormat.channels; ++c) {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        const double du = u - (10.0 + index), dv = v - 20.0;
        const double level = 0.2 + 0.3 * v / f.height + 0.5 * std::exp(-(du * du + dv * dv) / 40.0);
        const double noisy = level * maxCode + double(state % 16) - 8.0;
        f.codes[f.index(u, v, c)] = std::uint16_t(std::clamp(noisy, 0.0, maxCode));
      }
    }
  }
  return f;
}

// Lights whose floats round-trip only if every bit is kept: -0, a denormal, NaN, infinity.
inline LightSet awkwardLights(int index) {
  LightSet set;
  set.luminanceSr = 12.345678901234567 + index;
  set.black = index % 2 == 1;
  for (std::uint32_t i = 0; i < 4; ++i) {
    Light l;
    l.id = i * 7 + std::uint32_t(index);
    l.dir = glm::vec3(0.6F, 0.8F * float(i), -0.0F);
    l.rgb = glm::vec3(
        std::numeric_limits<float>::denorm_min(), 1.0F / 3.0F + float(index),
        i == 3 ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity());
    set.lights.push_back(l);
  }
  return set;
}

inline bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
inline bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline bool sameLights(const LightSet& a, const LightSet& b) {
  if (a.lights.size() != b.lights.size() || !sameBits(a.luminanceSr, b.luminanceSr) ||
      a.black != b.black) {
    return false;
  }
  for (std::size_t i = 0; i < a.lights.size(); ++i) {
    if (a.lights[i].id != b.lights[i].id) return false;
    for (int k = 0; k < 3; ++k) {
      if (!sameBits(a.lights[i].dir[k], b.lights[i].dir[k]) ||
          !sameBits(a.lights[i].rgb[k], b.lights[i].rgb[k])) {
        return false;
      }
    }
  }
  return true;
}

inline std::vector<char> readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void writeBytes(const fs::path& path, const char* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(data, std::streamsize(size));
}

// Seq i * step (from 0), ts i * period, lights on even frames.
inline void writeSmallRecording(const fs::path& path, int frames,
                                const recording::RecordingHeader& header = smallHeader(),
                                bool close = true) {
  auto writer = recording::RecordingWriter::create(path, header);
  ASSERT_TRUE(writer) << writer.error().message;
  for (int i = 0; i < frames; ++i) {
    const LightSet lights = awkwardLights(i);
    auto done = writer->append(std::uint64_t(i), i * kPeriodNs, smallFrame(header, i),
                               i % 2 == 0 ? &lights : nullptr);
    ASSERT_TRUE(done) << done.error().message;
  }
  if (close) {
    auto closed = writer->close();
    ASSERT_TRUE(closed) << closed.error().message;
  }
}

// A recording written by hand, record by record, with whatever sequence numbers and capture
// times it is given, none checked (the writer refuses a seq that does not increase; other
// writers, or damage, may not). No index or footer: the file ends after the last frame, as a
// crash leaves it. Frame i is smallFrame(header, i).
struct HandFrame {
  std::uint64_t seq = 0;
  std::int64_t captureTsNs = 0;
};

inline void writeRecordingByHand(const fs::path& path, const std::vector<HandFrame>& frames,
                                 const recording::RecordingHeader& header = smallHeader()) {
  std::vector<std::byte> bytes = recording::encodeHeaderRecord(header);
  recording::FrameCodec codec;
  std::vector<std::byte> record;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    codec.encodeRecord(frames[i].seq, frames[i].captureTsNs, smallFrame(header, int(i)), nullptr,
                       record);
    bytes.insert(bytes.end(), record.begin(), record.end());
  }
  writeBytes(path, reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

// Every intact frame of the file, in order, and the reader's damage counts.
struct ReadBack {
  std::vector<recording::RecordedFrame> frames;
  recording::DamageStats damage;
};

inline ReadBack readAll(recording::RecordingReader& reader) {
  ReadBack back;
  for (;;) {
    auto frame = reader.next();
    if (!frame) {
      ADD_FAILURE() << frame.error().message;
      break;
    }
    if (!*frame) break;
    back.frames.push_back(std::move(**frame));
  }
  back.damage = reader.damage();
  return back;
}

// A fresh folder per test, removed afterwards.
class RecordingFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           (std::string("vem_recording_") + info->name() + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

}  // namespace vem::testing
