// Writing camera files: formatCameraFile (camera_file.h), field by field in the documented order,
// each with a short note for the reader of the file.
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "calib/io/camera_file.h"
#include "calib/io/calibration_fields.h"
#include "calib/io/camera_file_fields.h"
#include "calib/io/toml_writer.h"

namespace vem::calib::io {
namespace {

using detail::TomlWriter;

std::span<const double> channels(const std::array<double, 3>& values, PixelFormat format) {
  return std::span<const double>(values).first(std::size_t(format.channels));
}

std::string channelNote(PixelFormat format, std::string_view what) {
  return std::string(format.channels == 3 ? "R, G, B: " : "") + std::string(what);
}

void writeResponse(TomlWriter& w, const ResponseModel& response, PixelFormat format) {
  if (const auto* log = std::get_if<LogResponse>(&response)) {
    w.quantity("a", channels(log->aCode, format), detail::kUnitCode,
               channelNote(format, "code at L = 1 cd/m2"));
    w.quantity("b", channels(log->bCodePerLn, format), detail::kUnitLogSlope,
               channelNote(format, "codes per ln unit of luminance"));
  } else if (const auto* linear = std::get_if<LinearResponse>(&response)) {
    w.quantity("gain", channels(linear->gainCodePerCdM2Us, format), detail::kUnitLinearGain,
               channelNote(format, "code = black + gain L exposure gain"));
  } else if (const auto* table = std::get_if<TabulatedResponse>(&response)) {
    std::vector<std::span<const double>> rows;
    for (int c = 0; c < format.channels; ++c)
      rows.emplace_back(table->exposureByCode[std::size_t(c)]);
    w.quantityRows("exposure", rows, detail::kUnitRelative,
                   "per channel, the relative exposure of each code (index = code)");
    w.quantity("scale", table->scaleCdM2, detail::kUnitTableScale,
               "L = exposure[code] scale / (exposure_us gain)");
  }
}

void writePhotometric(TomlWriter& w, const PhotometricCalibration& photometric,
                      const PhotometricQuality& quality, PixelFormat format) {
  const std::string model = responseModelName(photometric.response);
  w.table("photometric");
  w.string("model", model,
           model == "log"      ? "code = a + b ln(L / 1 cd/m2)"
           : model == "linear" ? "code = black + gain L exposure_us gain"
                               : "tabulated, code to relative exposure");
  w.quantity("black_level", photometric.blackLevelCode, detail::kUnitCode,
             "codes at or below read as 0 cd/m2");
  w.quantity("saturation", photometric.saturationCode, detail::kUnitCode,
             "codes at or above are clipped");
  writeResponse(w, photometric.response, format);
  w.table("photometric.fit");
  w.quantity("rms_residual", quality.rmsResidualPercent, detail::kUnitPercent,
             "over the fit patches");
  w.quantity("max_residual", quality.maxResidualPercent, detail::kUnitPercent);
  w.quantity("max_check_error", quality.maxCheckErrorPercent, detail::kUnitPercent,
             "over the check patches, left out of the fit");
  w.integer("fit_patches", quality.fitPatches);
  w.integer("check_patches", quality.checkPatches);
  w.string("date", quality.date, "UTC");
}

void writeLens(TomlWriter& w, const KannalaBrandtLens& lens, const GeometricQuality& quality) {
  w.table("geometric");
  w.string("model", detail::kLensModelName, "r(theta) = k1 theta + k2 theta^3 + ... + k5 theta^9");
  w.quantity("k", lens.kPx, detail::kUnitPx, "k1 .. k5, theta in radians");
  const std::array<double, 2> centre{lens.principalPointPx.x, lens.principalPointPx.y};
  w.quantity("principal_point", centre, detail::kUnitPx, "x (column), y (row)");
  w.number("aspect", lens.aspect, "row scale / column scale");
  detail::writeAngle(w, "max_theta", lens.maxThetaRad, "half the field of view");
  detail::writeGeometricQuality(w, "geometric.fit", quality);
}

void writeOrientation(TomlWriter& w, const CameraOrientation& orientation) {
  w.table("orientation");
  w.quantity("image_rotation", orientation.imageRotationDeg, detail::kUnitDeg,
             "phi = 0 lies this far counter-clockwise from +u");
  w.quantity("tilt", orientation.tiltDeg, detail::kUnitDeg, "optical axis from the zenith");
  w.quantity("tilt_azimuth", orientation.tiltAzimuthDeg, detail::kUnitDeg, "toward this phi");
}

}  // namespace

std::string formatCameraFile(const CameraCalibration& calibration) {
  TomlWriter w;
  w.comment("vemcast camera calibration, written by vemcalib (docs/calibration.md).");
  w.comment("Every quantity is { value = ..., unit = \"...\" }; L is luminance in cd/m2.");
  w.string("format", detail::kCameraFormatName);
  w.integer("version", kCameraFileVersion);
  detail::writeCameraIdentity(w, calibration.camera);
  if (calibration.photometric)
    writePhotometric(w, *calibration.photometric, calibration.photometricQuality,
                     calibration.camera.pixelFormat);
  if (calibration.lens) writeLens(w, *calibration.lens, calibration.geometricQuality);
  writeOrientation(w, calibration.orientation);
  return w.text();
}

}  // namespace vem::calib::io
