// From the sensor to the environment map: a table, built once per calibration, that gives for each
// map pixel the sensor position its direction projects to (kannala_brandt.h through
// camera_orientation.h), and its application to every frame: bilinear interpolation of the
// luminance of the four nearest sensor pixels (codes through the photometric table first, so
// radiance, not codes, is interpolated).
//
// Conventions: the map's layout and pixel directions are daemon/core/env_map.h's (the camera's
// polar map is MapLayout::Hemisphere, e.g. 1024 x 256); radiance in cd/m^2 per channel; a mono
// sensor fills R = G = B. Map pixels whose direction falls outside the lens circle (beyond
// maxThetaRad) or whose four taps are not all on the sensor are invalid: they read 0 and their
// mask entry is 0.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "calib/core/camera_orientation.h"
#include "calib/core/kannala_brandt.h"
#include "calib/core/photometric_model.h"
#include "core/env_map.h"
#include "frames/raw_frame.h"

namespace vem::calib {

struct PolarRemap {
  static constexpr std::uint32_t kInvalid = 0xffffffffu;

  MapLayout layout = MapLayout::Hemisphere;
  int mapWidth = 0;
  int mapHeight = 0;
  int sensorWidth = 0;
  int sensorHeight = 0;
  // Per map pixel (row-major): the sensor pixel index v0 * sensorWidth + u0 of the top-left tap,
  // or kInvalid; and the bilinear fractions (u - u0, v - v0).
  std::vector<std::uint32_t> topLeftTap;
  std::vector<float> fractionU;
  std::vector<float> fractionV;

  [[nodiscard]] std::vector<std::uint8_t> validMask() const;  // 1 valid, 0 invalid
  [[nodiscard]] double validFraction() const;
};

[[nodiscard]] PolarRemap buildPolarRemap(const KannalaBrandtLens& lens,
                                         const CameraOrientation& orientation, int sensorWidth,
                                         int sensorHeight, MapLayout layout, int mapWidth,
                                         int mapHeight);

// The same, asking `stopRequested` before each map row (the build costs about 0.2 us per map pixel
// and 12 bytes of table each, so a large map takes seconds): when it answers true the build is
// abandoned and nullopt returned. The caller decides what a stop means (a signal, a deadline) and
// may use the calls to report progress; the table is otherwise the plain build's, bit for bit.
[[nodiscard]] std::optional<PolarRemap> buildPolarRemap(const KannalaBrandtLens& lens,
                                                        const CameraOrientation& orientation,
                                                        int sensorWidth, int sensorHeight,
                                                        MapLayout layout, int mapWidth,
                                                        int mapHeight,
                                                        const std::function<bool()>& stopRequested);

// Writes the map of `frame` into `map` (resized to the remap's size and layout as needed, so a
// caller reusing one EnvMap allocates once). `lut` must match the frame's format.
void applyPolarRemap(const PolarRemap& remap, const RawFrame& frame, const CodeToLuminanceLut& lut,
                     EnvMap& map);

// The same from an image already in luminance (e.g. merged brackets): `luminanceCdM2` holds
// sensorWidth * sensorHeight * channels floats.
void applyPolarRemap(const PolarRemap& remap, std::span<const float> luminanceCdM2, int channels,
                     EnvMap& map);

}  // namespace vem::calib
