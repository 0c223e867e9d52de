// Processed frames for the sink tests: a small camera frame (the recording tests' fixtures), a
// small polar map, lights with floats whose decimal forms are long, and a fresh folder per test.
#pragma once

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/env_map.h"
#include "core/light.h"
#include "frames/processed_frame.h"
#include "recording/recording_fixtures.h"
#include "vemd/sinks/recording_context.h"

namespace vem::testing {

namespace fs = std::filesystem;

// A sequence number and timestamp beyond 2^53: a detour through double would change them.
inline constexpr std::uint64_t kFirstSeq = (std::uint64_t(1) << 60) + 1;
inline constexpr std::int64_t kFirstTsNs = 1'760'000'000'123'456'789;

inline glm::vec3 unitDirection(double thetaRad, double phiRad) {
  return glm::vec3(directionFromAngles(thetaRad, phiRad));
}

// `count` lights whose floats are not short decimals (1/3, 1e-30, 3e38, ...), all different.
inline LightSet oddLights(int index, int count = 5) {
  LightSet set;
  set.luminanceSr = 7.0 / 3.0 + index;
  for (int i = 0; i < count; ++i) {
    Light light;
    light.id = std::uint32_t(3 * i + index);
    light.dir = unitDirection(0.1 + 0.27 * i, 0.3 + 1.1 * i + 0.01 * index);
    light.rgb = glm::vec3(1.0F / 3.0F + float(i), 1e-30F * float(i + 1), 3.0e38F / float(i + 1));
    set.lights.push_back(light);
  }
  return set;
}

inline vemd::RecordingContext smallContext() {
  const recording::RecordingHeader h = smallHeader();
  vemd::RecordingContext context;
  context.cameraModel = h.cameraModel;
  context.cameraSerial = h.cameraSerial;
  context.pixelFormat = h.pixelFormat;
  context.widthPx = h.sensorWidthPx;
  context.heightPx = h.sensorHeightPx;
  context.nominalRateHz = h.nominalRateHz;
  context.calibrationToml = h.calibrationToml;
  return context;
}

// One processed frame with what it borrows: the captured frame and the polar map.
struct TestFrame {
  explicit TestFrame(int index) {
    captured.frame = smallFrame(smallHeader(), index);
    captured.seq = kFirstSeq + std::uint64_t(index);
    captured.captureTsNs = kFirstTsNs + index * kPeriodNs;
    polar = EnvMap::filled(MapLayout::Hemisphere, 36, 9, glm::vec3(0.5F));
    processed.captured = &captured;
    processed.polar = &polar;
    processed.lights = oddLights(index);
  }
  TestFrame(const TestFrame&) = delete;
  TestFrame& operator=(const TestFrame&) = delete;

  vem::CapturedFrame captured;
  EnvMap polar;
  vem::ProcessedFrame processed;
};

inline std::vector<std::string> readLines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A fresh folder per test, removed afterwards.
class SinkFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("vem_sinks_") + info->test_suite_name() + "_" +
                                        info->name() + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

}  // namespace vem::testing
