// Small cameras, frames, recordings, sources and sinks for vemd's tests: a 320 x 256 Mono12 log
// camera (tests/support/test_cameras.h), frames of a procedural sky turning a little every frame,
// 256 x 64 maps, and in-process sources and sinks whose behaviour the tests script.
#pragma once

#include <unistd.h>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "calib/core/camera_simulator.h"
#include "calib/io/camera_file.h"
#include "frames/frame_source.h"
#include "frames/sink.h"
#include "recording/recording_writer.h"
#include "support/test_cameras.h"
#include "support/test_maps.h"
#include "vemd/pipeline.h"
#include "vemd/pipeline_setup.h"

namespace vem::testing {

namespace fs = std::filesystem;

inline constexpr int kSensorWidth = 320;
inline constexpr int kSensorHeight = 256;
inline constexpr std::int64_t kFramePeriodNs = 33'333'333;

inline calib::CameraCalibration smallCamera() {
  return cameraTruth(kSensorWidth, kSensorHeight, 1);
}
inline std::string smallCameraToml() { return calib::io::formatCameraFile(smallCamera()); }

inline vem::ProcessingOptions smallProcessing() {
  vem::ProcessingOptions o;
  o.mapWidth = 256;
  o.mapHeight = 64;
  o.lightCount = 64;
  o.clusterBudget = 16;
  return o;
}

// Frame i: the procedural sky turned by i columns, read noise seeded by i, exposure changing
// every 4 frames (the log sensor ignores it, the code table is rebuilt anyway).
inline vem::RawFrame skyFrame(int index) {
  static const EnvMap sky = proceduralSky(MapLayout::Sphere, 128, 64);
  calib::SimulationOptions options;
  options.supersamples = 1;
  options.exposureUs = 1000.0 + 250.0 * (index / 4);
  options.noise = {2.0, 0.0, std::uint64_t(index) + 1};
  return calib::simulateFrame(calib::radianceFromMap(rotatedColumns(sky, index)), smallCamera(),
                              options);
}

inline constexpr int kCachedFrames = 16;

// skyFrame(index % kCachedFrames), made once per process (thread-safe).
inline const vem::RawFrame& cachedSkyFrame(int index) {
  static const std::vector<vem::RawFrame> frames = [] {
    std::vector<vem::RawFrame> made;
    for (int i = 0; i < kCachedFrames; ++i) made.push_back(skyFrame(i));
    return made;
  }();
  return frames[std::size_t(index % kCachedFrames)];
}

inline recording::RecordingHeader smallRecordingHeader() {
  const calib::CameraCalibration camera = smallCamera();
  recording::RecordingHeader h;
  h.cameraModel = camera.camera.model;
  h.cameraSerial = camera.camera.serial;
  h.sensorWidthPx = kSensorWidth;
  h.sensorHeightPx = kSensorHeight;
  h.pixelFormat = camera.camera.pixelFormat;
  h.nominalRateHz = 30.0;
  h.calibrationToml = smallCameraToml();
  h.writerName = "vemd_tests";
  return h;
}

inline vem::CapturedFrame captured(const vem::RawFrame& frame, std::uint64_t seq) {
  return {frame, seq, std::int64_t(seq) * kFramePeriodNs, vem::monotonicNowNs()};
}

// A recording of `count` sky frames (seq i, ts i x 33.3 ms), each with the lights a fresh
// pipeline computed from it when `withLights`.
inline void writeSkyRecording(const fs::path& path, int count, bool withLights) {
  auto writer = recording::RecordingWriter::create(path, smallRecordingHeader());
  ASSERT_TRUE(writer) << writer.error().message;
  auto pipeline = vemd::pipelineFromCameraFile(smallCameraToml(), "test camera", smallProcessing());
  ASSERT_TRUE(pipeline) << pipeline.error();
  for (int i = 0; i < count; ++i) {
    const vem::CapturedFrame frame = captured(cachedSkyFrame(i), std::uint64_t(i));
    const LightSet* lights = withLights ? &pipeline->process(frame).lights : nullptr;
    auto appended = writer->append(frame.seq, frame.captureTsNs, frame.frame, lights);
    ASSERT_TRUE(appended) << appended.error().message;
  }
  auto closed = writer->close();
  ASSERT_TRUE(closed) << closed.error().message;
}

// A fresh folder per test, removed afterwards.
class VemdFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("vemd_") + info->test_suite_name() + "_" +
                                        info->name() + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// A gate a test opens or closes and other threads wait at; counts who arrived.
class Gate {
 public:
  void open() {
    {
      std::lock_guard lock(mutex_);
      open_ = true;
    }
    changed_.notify_all();
  }
  // Counts the arrival, then waits until the gate is open.
  void pass() {
    std::unique_lock lock(mutex_);
    ++arrivals_;
    changed_.notify_all();
    changed_.wait(lock, [&] { return open_; });
  }
  // Waits until `count` arrivals happened; false after `timeout` (a test failure, not a timing).
  bool awaitArrivals(int count, std::chrono::seconds timeout = std::chrono::seconds(30)) {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, timeout, [&] { return arrivals_ >= count; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  bool open_ = false;
  int arrivals_ = 0;
};

// A source that delivers sky frames (or scripted errors), each only when the test releases it:
// release(n) lets n more frames out. Every next() beyond the script is EndOfStream.
class ScriptedSource final : public vem::FrameSource {
 public:
  struct Step {
    std::optional<vem::SourceError> error;  // else a frame
  };
  ScriptedSource(std::vector<Step> script, bool paced)
      : script_(std::move(script)), paced_(paced) {}

  static std::vector<Step> frames(int count) { return std::vector<Step>(std::size_t(count)); }

  [[nodiscard]] vem::SourceDescription describe() const override {
    const calib::CameraCalibration camera = smallCamera();
    vem::SourceDescription d;
    d.spec = "scripted";
    d.sensorWidthPx = kSensorWidth;
    d.sensorHeightPx = kSensorHeight;
    d.pixelFormat = camera.camera.pixelFormat;
    d.calibrationToml = smallCameraToml();
    d.nominalRateHz = 30.0;
    d.liveClock = true;
    d.paced = paced_;
    return d;
  }

  [[nodiscard]] std::expected<vem::CapturedFrame, vem::SourceError> next() override {
    {
      std::unique_lock lock(mutex_);
      ++calls_;
      changed_.notify_all();
      changed_.wait(lock, [&] { return interrupted_ || released_ > 0 || !gated_; });
      if (interrupted_) {
        interrupted_ = false;
        return std::unexpected(vem::SourceError{vem::SourceErrorCause::Timeout, "interrupted"});
      }
      if (gated_) --released_;
    }
    if (position_ >= script_.size()) {
      return std::unexpected(vem::SourceError{vem::SourceErrorCause::EndOfStream, "the end"});
    }
    const Step step = script_[position_++];
    if (step.error) return std::unexpected(*step.error);
    const std::uint64_t seq = delivered_++;
    vem::CapturedFrame frame = captured(cachedSkyFrame(int(seq)), seq);
    frame.captureTsNs = vem::monotonicNowNs();
    return frame;
  }
  void recycle(vem::CapturedFrame&&) override { recycled_.fetch_add(1); }
  void interrupt() override {
    {
      std::lock_guard lock(mutex_);
      interrupted_ = true;
    }
    changed_.notify_all();
  }

  // Frames only come out as the test releases them.
  void gate() {
    std::lock_guard lock(mutex_);
    gated_ = true;
  }
  void release(int frames) {
    {
      std::lock_guard lock(mutex_);
      released_ += frames;
    }
    changed_.notify_all();
  }
  // Waits until next() was entered `count` times in all; false after a generous timeout.
  bool awaitCalls(int count) {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, std::chrono::seconds(30), [&] { return calls_ >= count; });
  }
  [[nodiscard]] int recycled() const { return recycled_.load(); }

 private:
  std::vector<Step> script_;
  bool paced_;
  std::size_t position_ = 0;
  std::uint64_t delivered_ = 0;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool gated_ = false;
  bool interrupted_ = false;
  int released_ = 0;
  int calls_ = 0;
  std::atomic<int> recycled_{0};
};

// Records what it was given; optionally sleeps per frame, fails at frame k, or waits at a gate.
class TestSink final : public vem::Sink {
 public:
  struct Log {
    std::mutex mutex;
    std::vector<std::uint64_t> seqs;
    std::vector<LightSet> lights;
    bool closed = false;
  };
  explicit TestSink(std::string name, std::shared_ptr<Log> log)
      : name_(std::move(name)), log_(std::move(log)) {}

  std::chrono::milliseconds sleepPerFrame{0};
  std::optional<std::size_t> failAtFrame;
  Gate* gate = nullptr;

  [[nodiscard]] std::string name() const override { return name_; }
  [[nodiscard]] std::expected<void, vem::SinkFailure> consume(
      const vem::ProcessedFrame& frame) override {
    if (gate != nullptr) gate->pass();
    if (sleepPerFrame.count() > 0) std::this_thread::sleep_for(sleepPerFrame);
    std::lock_guard lock(log_->mutex);
    if (failAtFrame && log_->seqs.size() == *failAtFrame) {
      return std::unexpected(vem::SinkFailure{name_ + ": the disk is full"});
    }
    log_->seqs.push_back(frame.captured->seq);
    log_->lights.push_back(frame.lights);
    return {};
  }
  [[nodiscard]] std::expected<void, vem::SinkFailure> close() override {
    std::lock_guard lock(log_->mutex);
    log_->closed = true;
    return {};
  }

 private:
  std::string name_;
  std::shared_ptr<Log> log_;
};

}  // namespace vem::testing
