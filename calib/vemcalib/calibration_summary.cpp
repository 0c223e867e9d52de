#include "calibration_summary.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "calib/core/photometric_model.h"
#include "frame_arguments.h"

namespace vem::calibtool {
namespace {

constexpr const char* kIndent = "              ";  // under the section names

std::string channelName(PixelFormat format, int channel) {
  if (format.channels == 1) return "";
  return std::string(1, "RGB"[channel]) + ": ";
}

std::string responseLine(const calib::ResponseModel& response, double blackLevelCode,
                         std::size_t c) {
  if (const auto* log = std::get_if<calib::LogResponse>(&response))
    return fmt::format("code = {:.6g} + {:.6g} ln(L / 1 cd/m2)", log->aCode[c], log->bCodePerLn[c]);
  if (const auto* linear = std::get_if<calib::LinearResponse>(&response))
    return fmt::format("code = {:.6g} + {:.6g} L exposure_us gain", blackLevelCode,
                       linear->gainCodePerCdM2Us[c]);
  const auto& table = std::get<calib::TabulatedResponse>(response);
  return fmt::format("tabulated over {} codes, scale {:.6g} cd/m2*us",
                     table.exposureByCode[c].size(), table.scaleCdM2);
}

void printPhotometric(std::ostream& out, const calib::CameraCalibration& calibration) {
  if (!calibration.photometric) {
    fmt::print(out, "photometric:  none (run vemcalib photometric or vemcalib response)\n");
    return;
  }
  const calib::PhotometricCalibration& p = *calibration.photometric;
  const PixelFormat format = calibration.camera.pixelFormat;
  fmt::print(out, "photometric:  {} response, black level {:g}, saturation {:g} (codes)\n",
             calib::responseModelName(p.response), p.blackLevelCode, p.saturationCode);
  for (const std::string& line : responseLines(p, format)) fmt::print(out, "{}{}\n", kIndent, line);
  const bool log = std::holds_alternative<calib::LogResponse>(p.response);
  fmt::print(out, "{}{}{}\n", kIndent, readableRange(p, format, kDefaultExposureUs, 1.0),
             log ? "" : " at 1000 us and gain 1");
  const calib::PhotometricQuality& q = calibration.photometricQuality;
  fmt::print(out,
             "  fit:        {}: {} patches, rms residual {:.3g} %, largest {:.3g} %; {} check "
             "patches, largest error {:.3g} %\n",
             q.date, q.fitPatches, q.rmsResidualPercent, q.maxResidualPercent, q.checkPatches,
             q.maxCheckErrorPercent);
}

void printGeometric(std::ostream& out, const calib::CameraCalibration& calibration) {
  if (!calibration.lens) {
    fmt::print(out, "geometric:    none (run vemcalib fisheye)\n");
    return;
  }
  const calib::KannalaBrandtLens& lens = *calibration.lens;
  const double fovDeg = 2.0 * lens.maxThetaRad * 180.0 / std::numbers::pi;
  fmt::print(out,
             "geometric:    Kannala-Brandt lens, field of view {:.4g} deg, image circle radius "
             "{:.1f} px\n",
             fovDeg, lens.radiusPx(lens.maxThetaRad));
  fmt::print(out, "{}k = {:.6g} px; principal point ({:.6g}, {:.6g}) px; aspect {:.6g}\n", kIndent,
             fmt::join(lens.kPx, ", "), lens.principalPointPx.x, lens.principalPointPx.y,
             lens.aspect);
  const calib::GeometricQuality& q = calibration.geometricQuality;
  fmt::print(out, "  fit:        {}: rms reprojection {:.3g} px over {} views ({} corners)\n",
             q.date, q.rmsReprojectionPx, q.views, q.corners);
}

}  // namespace

std::vector<std::string> responseLines(const calib::PhotometricCalibration& photometric,
                                       PixelFormat format) {
  std::vector<std::string> lines;
  for (int c = 0; c < format.channels; ++c)
    lines.push_back(channelName(format, c) +
                    responseLine(photometric.response, photometric.blackLevelCode, std::size_t(c)));
  return lines;
}

std::string readableRange(const calib::PhotometricCalibration& photometric, PixelFormat format,
                          double exposureUs, double gain) {
  double lowest = 0.0, highest = INFINITY;  // what every channel reads
  for (int c = 0; c < format.channels; ++c) {
    lowest =
        std::max(lowest, calib::luminanceFromCode(photometric, c, photometric.blackLevelCode + 1.0,
                                                  exposureUs, gain));
    highest = std::min(highest, calib::luminanceFromCode(photometric, c, photometric.saturationCode,
                                                         exposureUs, gain));
  }
  return fmt::format("reads {:.3g} to {:.3g} cd/m2 ({:.2g} decades)", lowest, highest,
                     std::log10(highest / lowest));
}

void printCalibration(std::ostream& out, const calib::CameraCalibration& calibration,
                      const std::string& path) {
  const calib::CameraIdentity& camera = calibration.camera;
  fmt::print(out, "{}: vemcast camera file\n", path);
  fmt::print(out, "camera:       {}, serial {}, {} x {} px, {}\n", camera.model, camera.serial,
             camera.sensorWidthPx, camera.sensorHeightPx, pixelFormatName(camera.pixelFormat));
  printPhotometric(out, calibration);
  printGeometric(out, calibration);
  const calib::CameraOrientation& o = calibration.orientation;
  fmt::print(out, "orientation:  image rotation {:g} deg, tilt {:g} deg toward phi = {:g} deg\n",
             o.imageRotationDeg, o.tiltDeg, o.tiltAzimuthDeg);
}

}  // namespace vem::calibtool
