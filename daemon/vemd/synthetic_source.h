// SyntheticSource: a synthetic scene (daemon/synth, docs/synthetic-scenes.md) seen through a
// simulated calibrated camera (synth::SyntheticCamera), as a live-like frame source: frame k shows
// the scene at time k / rateHz seconds and is delivered at its due time on CLOCK_MONOTONIC.
//
// - Pace (SourceRate): "recorded" is the nominal kNominalRateHz, a number of Hz that rate, "max"
//   no waiting (scene time still advances by 1 / kNominalRateHz per frame).
// - Timestamps: captureTsNs is CLOCK_MONOTONIC at the frame's due time (the moment it "exposes"),
//   so the daemon measures the latency from capture; the frame is rendered before it is due.
//   seq counts from 0. Endless: next() never returns EndOfStream.
// - The camera: a camera file (or the built-in example camera, config/camera-example.toml); its
//   text is the calibration the source describes, so the pipeline calibrates with the truth.
// - Buffers: recycled frames' codes are rendered into again.
#pragma once

#include <cstdint>
#include <expected>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frames/frame_source.h"
#include "synth/synthetic_camera.h"
#include "synth/synthetic_scene.h"
#include "vemd/pacer.h"
#include "vemd/source_rate.h"

namespace vem::vemd {

struct SyntheticOptions {
  static constexpr double kNominalRateHz = 30.0;
  SourceRate rate;
  std::string cameraFile;  // "": the built-in example camera
  double readNoiseCode = 0.0;
  std::uint64_t seed = 1;  // the noise, and the clouds scene's field
};

class SyntheticSource final : public FrameSource {
 public:
  // Makes the scene `scene` names (loading hdri:FILE's map) and the camera. NoDevice with one
  // sentence when the scene, the camera file or its calibration is unusable.
  [[nodiscard]] static std::expected<std::unique_ptr<SyntheticSource>, SourceError> create(
      const std::string& scene, const SyntheticOptions& options);

  [[nodiscard]] SourceDescription describe() const override;
  [[nodiscard]] std::expected<CapturedFrame, SourceError> next() override;
  void recycle(CapturedFrame&& spent) override;
  void interrupt() override;

 private:
  SyntheticSource(std::string spec, std::unique_ptr<synth::SyntheticScene> scene,
                  calib::CameraCalibration camera, std::string cameraToml,
                  const SyntheticOptions& options);
  [[nodiscard]] double rateHz() const;

  std::string spec_;
  std::unique_ptr<synth::SyntheticScene> scene_;
  std::string cameraToml_;
  SyntheticOptions options_;
  synth::SyntheticCamera camera_;
  Pacer pacer_;
  FrameSchedule schedule_;
  std::vector<std::vector<std::uint16_t>> spareCodes_;
  std::optional<RawFrame> rendered_;  // the next frame, rendered before it is due
  std::int64_t dueNs_ = 0;
  std::uint64_t seq_ = 0;
};

}  // namespace vem::vemd
