// The capture pipeline for the synthetic-scene tests: the example camera (the built-in default of
// vem_synth), frames calibrated into the camera's polar map with the TRUE calibration, lights,
// clusters and angles.
#pragma once

#include <cstddef>

#include <glm/vec3.hpp>

#include "calib/core/camera_calibration.h"
#include "core/env_map.h"
#include "core/light.h"
#include "frames/raw_frame.h"
#include "synth/synthetic_camera.h"

namespace vem::testing {

inline constexpr int kPolarWidth = 1024;  // the camera's polar map: 1024 x 256, 0.35 deg a pixel
inline constexpr int kPolarHeight = 256;

// config/camera-example.toml, parsed from the text vem_synth embeds.
[[nodiscard]] const calib::CameraCalibration& exampleCamera();
// One SyntheticCamera of the example camera per test process (building one takes ~0.1 s).
[[nodiscard]] synth::SyntheticCamera& exampleSyntheticCamera();

// `frame` into the 1024 x 256 hemisphere map with `calibration` (remap + LUT at the frame's own
// exposure and gain).
[[nodiscard]] EnvMap calibratedMap(const calib::CameraCalibration& calibration,
                                   const vem::RawFrame& frame);

// N lights by the Havran sampler with the default pattern (hemisphere).
[[nodiscard]] LightSet hemisphereLights(const EnvMap& map, std::size_t count);
// The cluster (clusterLights, budget Q over the hemisphere) with the largest rgb luminance.
[[nodiscard]] Light strongestCluster(const LightSet& lights, int clusterBudget);

[[nodiscard]] double angleDeg(const glm::dvec3& a, const glm::dvec3& b);

}  // namespace vem::testing
