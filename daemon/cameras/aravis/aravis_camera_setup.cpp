#include "cameras/aravis/aravis_camera_setup.h"

#include <cmath>
#include <cstring>
#include <vector>

#include <fmt/format.h>

#include "cameras/aravis/glib_object.h"

namespace vem::cameras {

namespace {

enum class GainUnit { Decibel, Linear, None };

GainUnit gainUnit(ArvCamera* camera) {
  ArvGcNode* node = arv_device_get_feature(arv_camera_get_device(camera), "Gain");
  if (node == nullptr || !ARV_IS_GC_FLOAT(node)) return GainUnit::None;
  const char* unit = arv_gc_float_get_unit(ARV_GC_FLOAT(node));
  if (unit == nullptr || *unit == '\0' || std::strcmp(unit, "dB") == 0) return GainUnit::Decibel;
  if (std::strcmp(unit, "x") == 0 || std::strcmp(unit, "times") == 0) return GainUnit::Linear;
  return GainUnit::None;
}

std::vector<std::string> offeredPixelFormats(ArvCamera* camera) {
  GErrorSlot error;
  guint count = 0;
  const char** names =
      arv_camera_dup_available_pixel_formats_as_strings(camera, &count, error.out());
  std::vector<std::string> out;
  for (guint i = 0; names != nullptr && i < count; ++i) out.emplace_back(names[i]);
  g_free(static_cast<void*>(names));
  return out;
}

std::expected<int, std::string> checkedSize(const char* what, int wanted, int minimum, int maximum,
                                            int increment) {
  if (wanted == 0) return maximum;
  const int step = std::max(1, increment);
  if (wanted < minimum || wanted > maximum || (wanted - minimum) % step != 0) {
    return std::unexpected(
        fmt::format("the camera offers {}s {} to {} px in steps of {}, not {} px", what, minimum,
                    maximum, step, wanted));
  }
  return wanted;
}

std::expected<void, std::string> applySize(ArvCamera* camera, const CameraSettings& settings,
                                           CameraGeometry& geometry) {
  GErrorSlot error;
  if (arv_camera_is_region_offset_available(camera, nullptr)) {
    arv_camera_set_integer(camera, "OffsetX", 0, error.out());
    arv_camera_set_integer(camera, "OffsetY", 0, error.out());
  }
  int minW = 0, maxW = 0, minH = 0, maxH = 0;
  arv_camera_get_width_bounds(camera, &minW, &maxW, error.out());
  if (error) return std::unexpected("cannot read the camera's width bounds: " + error.message());
  arv_camera_get_height_bounds(camera, &minH, &maxH, error.out());
  if (error) return std::unexpected("cannot read the camera's height bounds: " + error.message());
  auto width = checkedSize("width", settings.widthPx, minW, maxW,
                           arv_camera_get_width_increment(camera, nullptr));
  if (!width) return std::unexpected(width.error());
  auto height = checkedSize("height", settings.heightPx, minH, maxH,
                            arv_camera_get_height_increment(camera, nullptr));
  if (!height) return std::unexpected(height.error());
  arv_camera_set_integer(camera, "Width", *width, error.out());
  if (!error) arv_camera_set_integer(camera, "Height", *height, error.out());
  if (error)
    return std::unexpected(
        fmt::format("cannot set the size {}x{}: {}", *width, *height, error.message()));
  geometry.widthPx = int(arv_camera_get_integer(camera, "Width", nullptr));
  geometry.heightPx = int(arv_camera_get_integer(camera, "Height", nullptr));
  return {};
}

std::expected<void, std::string> applyFrameRate(ArvCamera* camera, double rateHz) {
  if (!arv_camera_is_frame_rate_available(camera, nullptr)) {
    return std::unexpected(
        fmt::format("the camera has no AcquisitionFrameRate to set {} Hz", rateHz));
  }
  GErrorSlot error;
  double minimum = 0.0, maximum = 0.0;
  arv_camera_get_frame_rate_bounds(camera, &minimum, &maximum, error.out());
  if (!error && (rateHz < minimum || rateHz > maximum)) {
    return std::unexpected(fmt::format("the camera's frame rate goes from {} to {} Hz, not {} Hz",
                                       minimum, maximum, rateHz));
  }
  arv_camera_set_frame_rate(camera, rateHz, error.out());
  if (error)
    return std::unexpected(
        fmt::format("cannot set the frame rate {} Hz: {}", rateHz, error.message()));
  return {};
}

std::expected<void, std::string> applyExposure(ArvCamera* camera, double exposureUs) {
  if (!arv_camera_is_exposure_time_available(camera, nullptr)) {
    return std::unexpected("the camera has no ExposureTime to set");
  }
  GErrorSlot error;
  if (arv_camera_is_exposure_auto_available(camera, nullptr)) {
    arv_camera_set_exposure_time_auto(camera, ARV_AUTO_OFF, error.out());
  }
  double minimum = 0.0, maximum = 0.0;
  arv_camera_get_exposure_time_bounds(camera, &minimum, &maximum, error.out());
  if (!error && (exposureUs < minimum || exposureUs > maximum)) {
    return std::unexpected(fmt::format("the camera's exposure goes from {} to {} us, not {} us",
                                       minimum, maximum, exposureUs));
  }
  arv_camera_set_exposure_time(camera, exposureUs, error.out());
  if (error)
    return std::unexpected(
        fmt::format("cannot set the exposure {} us: {}", exposureUs, error.message()));
  return {};
}

std::expected<void, std::string> applyGain(ArvCamera* camera, double gain) {
  const GainUnit unit = gainUnit(camera);
  if (unit == GainUnit::None) {
    if (gain == 1.0) return {};
    return std::unexpected(fmt::format(
        "the camera has no Gain feature in dB or as a factor, so gain {} cannot be set", gain));
  }
  if (!(gain > 0.0)) return std::unexpected(fmt::format("gain {} is not a positive factor", gain));
  const double value = unit == GainUnit::Decibel ? 20.0 * std::log10(gain) : gain;
  const char* unitName = unit == GainUnit::Decibel ? "dB" : "x";
  GErrorSlot error;
  if (arv_camera_is_gain_auto_available(camera, nullptr)) {
    arv_camera_set_gain_auto(camera, ARV_AUTO_OFF, error.out());
  }
  double minimum = 0.0, maximum = 0.0;
  arv_camera_get_float_bounds(camera, "Gain", &minimum, &maximum, error.out());
  if (!error && (value < minimum - 1e-9 || value > maximum + 1e-9)) {
    return std::unexpected(fmt::format("gain {} ({:.3f} {}) is outside the camera's {} to {} {}",
                                       gain, value, unitName, minimum, maximum, unitName));
  }
  arv_camera_set_float(camera, "Gain", value, error.out());
  if (error) return std::unexpected(fmt::format("cannot set gain {}: {}", gain, error.message()));
  return {};
}

bool isAutomatic(ArvCamera* camera, bool available, ArvAuto (*get)(ArvCamera*, GError**)) {
  if (!available) return false;
  GErrorSlot error;
  const ArvAuto mode = get(camera, error.out());
  return !error && mode != ARV_AUTO_OFF;
}

}  // namespace

std::expected<CameraGeometry, std::string> applyGeometry(ArvCamera* camera,
                                                         const CameraSettings& settings) {
  CameraGeometry geometry;
  auto chosen = chooseNativeFormat(settings.pixelFormat, offeredPixelFormats(camera));
  if (!chosen) return std::unexpected(chosen.error());
  geometry.native = *chosen;
  GErrorSlot error;
  const std::string name(geometry.native->genicamName);
  arv_camera_set_pixel_format_from_string(camera, name.c_str(), error.out());
  if (error)
    return std::unexpected(fmt::format("cannot set pixel format {}: {}", name, error.message()));
  if (auto sized = applySize(camera, settings, geometry); !sized)
    return std::unexpected(sized.error());
  if (settings.frameRateHz) {
    if (auto rate = applyFrameRate(camera, *settings.frameRateHz); !rate) {
      return std::unexpected(rate.error());
    }
  }
  return geometry;
}

std::expected<void, std::string> applyExposureGain(ArvCamera* camera,
                                                   std::optional<double> exposureUs,
                                                   std::optional<double> gain) {
  if (exposureUs) {
    if (auto applied = applyExposure(camera, *exposureUs); !applied) return applied;
  }
  if (gain) return applyGain(camera, *gain);
  return {};
}

ExposureReadback readExposureGain(ArvCamera* camera) {
  ExposureReadback out;
  GErrorSlot error;
  if (arv_camera_is_exposure_time_available(camera, nullptr)) {
    const double us = arv_camera_get_exposure_time(camera, error.out());
    if (!error) out.exposureUs = us;
  }
  const GainUnit unit = gainUnit(camera);
  if (unit != GainUnit::None) {
    const double value = arv_camera_get_float(camera, "Gain", error.out());
    if (!error) out.gain = unit == GainUnit::Decibel ? std::pow(10.0, value / 20.0) : value;
  }
  out.automatic = isAutomatic(camera, arv_camera_is_exposure_auto_available(camera, nullptr),
                              arv_camera_get_exposure_time_auto) ||
                  isAutomatic(camera, arv_camera_is_gain_auto_available(camera, nullptr),
                              arv_camera_get_gain_auto);
  return out;
}

double readFrameRateHz(ArvCamera* camera) {
  if (!arv_camera_is_frame_rate_available(camera, nullptr)) return 0.0;
  GErrorSlot error;
  const double rate = arv_camera_get_frame_rate(camera, error.out());
  return error ? 0.0 : rate;
}

}  // namespace vem::cameras
