// Test support for bracketing: a simulated LDR camera (calib's 8-bit camera response,
// bracket_simulation.h, behind the tests' 190-degree lens) and a FrameSource around it that follows
// a real camera's semantics for exposure: a request made with setExposure() before frame n is
// applied from frame n + latency on, every frame reports the exposure and gain it was really taken
// with. Scripted faults: frames lost before delivery (seq gaps), frames taken at another exposure,
// errors returned instead of a frame, requests refused.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "calib/core/camera_calibration.h"
#include "frames/frame_source.h"
#include "synth/synthetic_camera.h"
#include "synth/synthetic_scene.h"

namespace vem::testing {

// An 8-bit LDR camera: ldrCameraPhotometric(scaleCdM2), black 0, saturation 255, wideLensTruth.
[[nodiscard]] calib::CameraCalibration ldrCamera(int width, int height, int channels,
                                                 double scaleCdM2);

struct LdrFakeOptions {
  int latencyFrames = 2;             // a request applies this many frames after it was made
  double initialExposureUs = 10000;  // before any request applies
  double initialGain = 1.0;
  double rateHz = 30.0;      // frame n shows the scene at n / rateHz seconds
  calib::SensorNoise noise;  // none by default
  int samplesPerAxis = 1;
  std::string spec = "fake-ldr:cam0";
};

class LdrFakeCamera final : public vem::FrameSource {
 public:
  LdrFakeCamera(calib::CameraCalibration camera, std::shared_ptr<const synth::SyntheticScene> scene,
                LdrFakeOptions options);

  [[nodiscard]] vem::SourceDescription describe() const override;
  [[nodiscard]] std::expected<vem::CapturedFrame, vem::SourceError> next() override;
  void recycle(vem::CapturedFrame&& spent) override;
  void interrupt() override { ++interrupts; }
  [[nodiscard]] std::expected<void, std::string> setExposure(double exposureUs,
                                                             double gain) override;

  // Script (by the camera's frame number = seq).
  std::set<std::uint64_t> lostFrames;                  // captured, never delivered
  std::map<std::uint64_t, double> exposureOverrideUs;  // taken (and reported) at this exposure
  std::map<int, vem::SourceError> errorsAtCall;        // next() call number (0-based) fails so
  bool refuseRequests = false;

  // What happened.
  int interrupts = 0;
  int recycled = 0;
  int calls = 0;
  std::vector<std::pair<double, double>> requests;  // every setExposure() call
  std::uint64_t nextSeq() const { return seq_; }

  // The scene time of frame `seq`.
  [[nodiscard]] double timeS(std::uint64_t seq) const { return double(seq) / options_.rateHz; }
  [[nodiscard]] std::int64_t captureTsNs(std::uint64_t seq) const;

 private:
  // The exposure frame `seq` is taken with: the last request applied by then.
  std::pair<double, double> exposureAt(std::uint64_t seq);

  std::shared_ptr<const synth::SyntheticScene> scene_;
  synth::SyntheticCamera camera_;
  std::string toml_;
  LdrFakeOptions options_;
  std::deque<std::pair<std::uint64_t, std::pair<double, double>>> pending_;  // applies at, value
  std::pair<double, double> current_;
  std::uint64_t seq_ = 0;
};

}  // namespace vem::testing
