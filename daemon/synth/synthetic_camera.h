// SyntheticCamera: turns a scene's state (synthetic_scene.h) into the raw frame a calibrated camera
// would deliver, like calib::simulateFrame (calib/core/camera_simulator.h) but fast enough for
// recordings and a live synthetic source.
//
// What is precomputed once per camera: the world direction of every sample of every sensor pixel
// (the lens through the orientation, as simulateFrame does), kept only for pixels the lens circle
// reaches; and the response as a SensorCodeTable per exposure and gain (sensor_code_table.h). A
// frame then costs one radiance lookup per sample and one table read per channel. On the example
// camera (1280 x 1024 RGB12, 757k pixels in the circle) with 1 sample per pixel, a `sky` frame
// takes about 35 ms on one core (docs/synthetic-scenes.md has the measurements).
//
// Semantics match simulateFrame: samplesPerAxis^2 samples on a regular grid inside each pixel,
// those outside the lens circle contributing 0 (a pixel wholly outside reads the black level); a
// mono sensor sees the Rec. 709 luminance; the response at the state's exposure and gain; Gaussian
// read noise of readNoiseCode codes plus, for linear and tabulated responses, shot noise of
// variance shotNoiseGain x (code - black); a pixel at or above saturation reads the saturation code
// exactly; codes rounded and clipped to the format. Differences: the response is tabulated (within
// 0.01 codes), and the noise comes from a table of 65536 Gaussian draws picked by a hash of
// (seed, frame index, pixel), so a frame is reproducible from its index alone.
//
// Not thread-safe (it caches the response table): one camera per thread.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "calib/core/camera_calibration.h"
#include "calib/core/camera_simulator.h"
#include "frames/raw_frame.h"
#include "synth/sensor_code_table.h"
#include "synth/synthetic_scene.h"

namespace vem::synth {

struct SyntheticCameraOptions {
  int samplesPerAxis = 1;    // samples per pixel and axis: 1 = the pixel's centre (fastest)
  calib::SensorNoise noise;  // default: no noise, the codes are the truth's
};

// Why `calibration` cannot drive a SyntheticCamera, as a sentence fragment ("the camera has no
// photometric section"), or nullopt when it can.
[[nodiscard]] std::optional<std::string> syntheticCameraProblem(
    const calib::CameraCalibration& calibration);

class SyntheticCamera {
 public:
  // `calibration` must pass syntheticCameraProblem(). Costs about 0.1 s for 1.3 Mpx.
  explicit SyntheticCamera(calib::CameraCalibration calibration,
                           SyntheticCameraOptions options = {});

  // The frame for `state`, taken with its exposure and gain; frameIndex picks the noise draw.
  [[nodiscard]] RawFrame render(const SceneState& state, std::uint64_t frameIndex = 0);
  // The same into `frame`, reusing its storage.
  void render(const SceneState& state, std::uint64_t frameIndex, RawFrame& frame);

  [[nodiscard]] const calib::CameraCalibration& calibration() const { return calibration_; }
  // Pixels with at least one sample inside the lens circle.
  [[nodiscard]] std::size_t litPixelCount() const { return litPixels_.size(); }

 private:
  void traceSensor();
  [[nodiscard]] const SensorCodeTable& codeTable(double exposureUs, double gain);
  template <bool kNoisy, int kChannels>
  void renderCodes(const SceneState& state, const SensorCodeTable& table, std::uint64_t frameIndex,
                   RawFrame& frame) const;

  calib::CameraCalibration calibration_;
  SyntheticCameraOptions options_;
  std::uint16_t topCode_ = 0;
  bool shotNoise_ = false;
  std::vector<std::uint32_t> litPixels_;   // sensor pixel index v * width + u
  std::vector<std::uint32_t> sampleEnd_;   // litPixels_[k]'s samples end at sampleEnd_[k]
  std::vector<glm::vec3> sampleDirs_;      // world directions, unit
  std::vector<std::uint32_t> darkPixels_;  // pixels wholly outside the circle
  std::vector<float> normals_;             // standard Gaussian draws
  std::optional<SensorCodeTable> table_;
};

}  // namespace vem::synth
