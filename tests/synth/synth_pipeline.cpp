#include "synth/synth_pipeline.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "calib/core/polar_remap.h"
#include "calib/io/camera_file.h"
#include "core/color.h"
#include "core/default_pattern.h"
#include "core/light_clustering.h"
#include "core/light_generator.h"
#include "core/sampling_tables.h"
#include "synth/default_camera.h"

namespace vem::testing {

const calib::CameraCalibration& exampleCamera() {
  static const calib::CameraCalibration camera = [] {
    auto parsed = calib::io::parseCameraFile(std::string(synth::exampleCameraToml()),
                                             std::string(synth::kExampleCameraSource));
    if (!parsed) throw std::runtime_error(parsed.error().message);
    return *parsed;
  }();
  return camera;
}

synth::SyntheticCamera& exampleSyntheticCamera() {
  static synth::SyntheticCamera camera(exampleCamera());
  return camera;
}

EnvMap calibratedMap(const calib::CameraCalibration& calibration, const vem::RawFrame& frame) {
  const calib::PolarRemap remap =
      calib::buildPolarRemap(*calibration.lens, calibration.orientation, frame.width, frame.height,
                             MapLayout::Hemisphere, kPolarWidth, kPolarHeight);
  const calib::CodeToLuminanceLut lut = calib::buildCodeToLuminanceLut(
      *calibration.photometric, frame.format, frame.exposureUs, frame.gain);
  EnvMap map;
  calib::applyPolarRemap(remap, frame, lut, map);
  return map;
}

LightSet hemisphereLights(const EnvMap& map, std::size_t count) {
  const SamplingTables tables = buildSamplingTables(map);
  return generateLights(tables, defaultSamplingPattern(map.layout).first(count),
                        SamplerKind::Havran);
}

Light strongestCluster(const LightSet& lights, int clusterBudget) {
  ClusteringParams params;
  params.clusterBudget = clusterBudget;
  params.layout = MapLayout::Hemisphere;
  const Clustering clustering = clusterLights(lights, params);
  return *std::ranges::max_element(clustering.clusters.lights, {},
                                   [](const Light& light) { return luminance(light.rgb); });
}

double angleDeg(const glm::dvec3& a, const glm::dvec3& b) {
  const double c = glm::dot(glm::normalize(a), glm::normalize(b));
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

}  // namespace vem::testing
