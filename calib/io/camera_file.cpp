// Reading (and saving) camera files: the fields of camera_file.h, each checked as it is read.
#include "calib/io/camera_file.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "calib/io/calibration_fields.h"
#include "calib/io/camera_file_fields.h"
#include "calib/io/file_access.h"
#include "util/toml_reader.h"

namespace vem::calib::io {
namespace {

using util::ArrayShape;
using util::shortestText;
using FieldReader = util::TomlReader;

std::array<double, 3> channelArray(const std::vector<double>& values) {
  std::array<double, 3> out{};
  for (std::size_t c = 0; c < values.size() && c < out.size(); ++c) out[c] = values[c];
  return out;
}

constexpr detail::FileHeader kCameraFileHeader{
    detail::kCameraFormatName, kCameraFileVersion, detail::kPlateCameraFormatName,
    " (a plate camera file, not a light-probe camera file)", " (not a vemcast camera file)"};

PhotometricQuality readPhotometricFit(FieldReader r) {
  r.onlyKeys(
      {"rms_residual", "max_residual", "max_check_error", "fit_patches", "check_patches", "date"});
  PhotometricQuality quality;
  quality.rmsResidualPercent = r.quantity("rms_residual", detail::kUnitPercent);
  quality.maxResidualPercent = r.quantity("max_residual", detail::kUnitPercent);
  quality.maxCheckErrorPercent = r.quantity("max_check_error", detail::kUnitPercent);
  for (const auto& [key, value] : {std::pair{"rms_residual", quality.rmsResidualPercent},
                                   std::pair{"max_residual", quality.maxResidualPercent},
                                   std::pair{"max_check_error", quality.maxCheckErrorPercent}})
    r.require(value >= 0.0, key,
              "expected a percentage of 0 or more, found " + shortestText(value));
  quality.fitPatches = int(r.integer("fit_patches", 0, 1'000'000));
  quality.checkPatches = int(r.integer("check_patches", 0, 1'000'000));
  quality.date = r.dateText("date");
  return quality;
}

void readLevels(FieldReader& r, PixelFormat format, PhotometricCalibration& photometric) {
  const double maxCode = format.maxCode();
  photometric.blackLevelCode = r.quantity("black_level", detail::kUnitCode);
  r.require(photometric.blackLevelCode >= 0.0, "black_level",
            "expected a code of 0 or more, found " + shortestText(photometric.blackLevelCode));
  photometric.saturationCode = r.quantity("saturation", detail::kUnitCode);
  r.require(photometric.saturationCode <= maxCode, "saturation",
            "expected at most " + shortestText(maxCode) + ", the largest " +
                pixelFormatName(format) + " code, found " +
                shortestText(photometric.saturationCode));
  r.require(photometric.saturationCode > photometric.blackLevelCode, "saturation",
            "expected a code above the black level " + shortestText(photometric.blackLevelCode) +
                ", found " + shortestText(photometric.saturationCode));
}

LogResponse readLogResponse(FieldReader& r, ArrayShape perChannel) {
  LogResponse response;
  response.aCode = channelArray(r.quantityArray("a", detail::kUnitCode, perChannel));
  const std::vector<double> b = r.quantityArray("b", detail::kUnitLogSlope, perChannel);
  for (const double slope : b)
    r.require(slope > 0.0, "b", "expected slopes above 0, found " + shortestText(slope));
  response.bCodePerLn = channelArray(b);
  return response;
}

LinearResponse readLinearResponse(FieldReader& r, ArrayShape perChannel) {
  const std::vector<double> gain = r.quantityArray("gain", detail::kUnitLinearGain, perChannel);
  for (const double g : gain)
    r.require(g > 0.0, "gain", "expected gains above 0, found " + shortestText(g));
  return LinearResponse{channelArray(gain)};
}

// The first code at which a tabulated curve goes wrong (negative, or lower than the code before).
std::optional<std::size_t> badTableCode(const std::vector<double>& curve) {
  for (std::size_t code = 0; code < curve.size(); ++code)
    if (curve[code] < 0.0 || (code > 0 && curve[code] < curve[code - 1])) return code;
  return std::nullopt;
}

TabulatedResponse readTableResponse(FieldReader& r, PixelFormat format, ArrayShape perChannel) {
  TabulatedResponse response;
  const std::string perCode = "one per code of " + pixelFormatName(format);
  const auto curves = r.quantityRows("exposure", detail::kUnitRelative, perChannel,
                                     ArrayShape{std::size_t(format.maxCode()) + 1, perCode});
  for (std::size_t c = 0; c < curves.size() && r.ok(); ++c) {
    if (const std::optional<std::size_t> code = badTableCode(curves[c]))
      r.fail("exposure", util::TomlProblem::BadValue,
             "channel " + std::to_string(c) + " is negative or decreases at code " +
                 std::to_string(*code) + " (expected a non-decreasing curve of values >= 0)");
    response.exposureByCode[c] = curves[c];
  }
  response.scaleCdM2 = r.quantity("scale", detail::kUnitTableScale);
  r.require(response.scaleCdM2 > 0.0, "scale",
            "expected a scale above 0, found " + shortestText(response.scaleCdM2));
  return response;
}

PhotometricCalibration readPhotometric(FieldReader r, PixelFormat format,
                                       PhotometricQuality& quality) {
  PhotometricCalibration photometric;
  const std::string model = r.string("model");
  const std::string reason = "one per channel of " + pixelFormatName(format);
  const ArrayShape perChannel{std::size_t(format.channels), reason};
  if (model == "log") {
    r.onlyKeys({"model", "black_level", "saturation", "a", "b", "fit"});
    photometric.response = readLogResponse(r, perChannel);
  } else if (model == "linear") {
    r.onlyKeys({"model", "black_level", "saturation", "gain", "fit"});
    photometric.response = readLinearResponse(r, perChannel);
  } else if (model == "table") {
    r.onlyKeys({"model", "black_level", "saturation", "exposure", "scale", "fit"});
    photometric.response = readTableResponse(r, format, perChannel);
  } else {
    r.fail("model", util::TomlProblem::BadValue,
           "expected \"log\", \"linear\" or \"table\", found \"" + model + "\"");
  }
  readLevels(r, format, photometric);
  quality = readPhotometricFit(r.section("fit"));
  return photometric;
}

KannalaBrandtLens readLens(FieldReader r, const CameraIdentity& camera, GeometricQuality& quality) {
  r.onlyKeys({"model", "k", "principal_point", "aspect", "max_theta", "fit"});
  const std::string model = r.string("model");
  r.require(model == detail::kLensModelName, "model",
            "expected \"kannala-brandt\", found \"" + model + "\"");
  KannalaBrandtLens lens;
  const std::vector<double> k = r.quantityArray("k", detail::kUnitPx, {5, "k1 to k5"});
  std::copy(k.begin(), k.end(), lens.kPx.begin());
  lens.principalPointPx = detail::readPrincipalPoint(r, camera);
  lens.aspect = r.number("aspect");
  r.require(lens.aspect > 0.0, "aspect",
            "expected a ratio above 0, found " + shortestText(lens.aspect));
  lens.maxThetaRad = r.angleRad("max_theta");
  r.require(lens.maxThetaRad > 0.0 && lens.maxThetaRad <= std::numbers::pi, "max_theta",
            "expected an angle above 0 and at most 180 deg, found " +
                shortestText(lens.maxThetaRad * 180.0 / std::numbers::pi) + " deg");
  if (const std::optional<const char*> defect = lensDefect(lens); defect && r.ok())
    r.fail("k", util::TomlProblem::BadValue, *defect);
  quality = detail::readGeometricQuality(r.section("fit"));
  return lens;
}

CameraOrientation readOrientation(FieldReader r) {
  r.onlyKeys({"image_rotation", "tilt", "tilt_azimuth"});
  CameraOrientation orientation;
  orientation.imageRotationDeg = r.angleDeg("image_rotation");
  orientation.tiltDeg = r.angleDeg("tilt");
  orientation.tiltAzimuthDeg = r.angleDeg("tilt_azimuth");
  return orientation;
}

CameraCalibration readCalibration(FieldReader& root) {
  CameraCalibration calibration;
  root.onlyKeys({"format", "version", "camera", "photometric", "geometric", "orientation"});
  calibration.camera = detail::readCameraIdentity(root.section("camera"));
  if (std::optional<FieldReader> photometric = root.optionalSection("photometric"))
    calibration.photometric = readPhotometric(*photometric, calibration.camera.pixelFormat,
                                              calibration.photometricQuality);
  if (std::optional<FieldReader> geometric = root.optionalSection("geometric"))
    calibration.lens = readLens(*geometric, calibration.camera, calibration.geometricQuality);
  calibration.orientation = readOrientation(root.section("orientation"));
  return calibration;
}

}  // namespace

std::expected<CameraCalibration, CalibFileFailure> parseCameraFile(const std::string& text,
                                                                   const std::string& sourceName) {
  return detail::parseTomlText(text, sourceName, [](FieldReader& root, util::TomlStatus&) {
    // The header first: a newer file is refused for its version, not for its new fields.
    detail::readFileHeader(root, kCameraFileHeader);
    return readCalibration(root);
  });
}

std::expected<CameraCalibration, CalibFileFailure> loadCameraFile(
    const std::filesystem::path& path) {
  return detail::loadTextFile(path, "camera file", parseCameraFile);
}

std::expected<void, CalibFileFailure> saveCameraFile(const CameraCalibration& calibration,
                                                     const std::filesystem::path& path) {
  return detail::saveCheckedTextFile(path, formatCameraFile(calibration), "camera file",
                                     parseCameraFile);
}

}  // namespace vem::calib::io
