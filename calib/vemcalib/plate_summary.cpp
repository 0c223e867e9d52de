#include "plate_summary.h"

#include <cmath>
#include <numbers>
#include <span>

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "plate_output.h"

namespace vem::calibtool {
namespace {

constexpr const char* kIndent = "              ";

std::span<const double> usedDistortion(const calib::PlateIntrinsics& in) {
  return std::span<const double>(in.distortion)
      .first(std::size_t(calib::distortionCount(in.model)));
}

void printIntrinsics(std::ostream& out, const calib::PlateCamera& plate) {
  const calib::PlateIntrinsics& in = plate.intrinsics;
  fmt::print(out,
             "intrinsics:   {} lens, fx {:.6g} px, fy {:.6g} px, principal point ({:.6g}, "
             "{:.6g}) px\n",
             calib::plateLensModelName(in.model), in.fxPx, in.fyPx, in.cxPx, in.cyPx);
  fmt::print(out, "{}distortion {:.6g}\n", kIndent, fmt::join(usedDistortion(in), ", "));
  const calib::GeometricQuality& q = plate.intrinsicsQuality;
  fmt::print(out, "  fit:        {}: rms reprojection {:.3g} px over {} views ({} corners)\n",
             q.date, q.rmsReprojectionPx, q.views, q.corners);
}

void printPose(std::ostream& out, const calib::PlateCamera& plate) {
  if (!plate.pose) {
    fmt::print(out, "pose:         none (run vemcalib plate pose)\n");
    return;
  }
  fmt::print(out, "pose:         camera at {}\n", describePose(*plate.pose));
  const calib::GeometricQuality& q = plate.poseQuality;
  fmt::print(out, "  fit:        {}: rms reprojection {:.3g} px ({} corners of the floor board)\n",
             q.date, q.rmsReprojectionPx, q.corners);
}

void printProbeAndColour(std::ostream& out, const calib::PlateCamera& plate) {
  if (plate.probeYawDate.empty() && plate.probeYawRad == 0.0) {
    fmt::print(out, "probe yaw:    none (run vemcalib plate probe-yaw)\n");
  } else {
    fmt::print(out, "probe yaw:    {:.4g} deg ({}): dir_plate_world = RotY(yaw) dir_probe_world\n",
               plate.probeYawRad * kDegPerRad, plate.probeYawDate);
  }
  if (!plate.colour) {
    fmt::print(out, "colour:       none (run vemcalib plate colour)\n");
    return;
  }
  const calib::PlateColourMatch& c = *plate.colour;
  fmt::print(out,
             "colour:       plate linear = gain x probe radiance, gain R {:.6g}, G {:.6g}, "
             "B {:.6g} per cd/m2\n",
             c.gainRgb[0], c.gainRgb[1], c.gainRgb[2]);
  fmt::print(out, "  fit:        {}: {} patches, rms residual {:.3g} %\n", c.date, c.patches,
             c.rmsResidualPercent);
}

// One value beside the truth's and their difference; `unit` is " px", " mm", " deg" or "" (then
// the columns keep their places).
void row(std::ostream& out, const std::string& name, double fitted, double truth,
         const std::string& unit, int decimals) {
  const std::string pad = unit.empty() ? "   " : unit;
  std::string line =
      fmt::format("  {:<28} {:>14.{}f}{} {:>14.{}f}{} {:>+12.{}f}{}", name, fitted, decimals, pad,
                  truth, decimals, pad, fitted - truth, decimals, unit);
  fmt::print(out, "{}\n", line);
}

// The angle of the rotation from one camera orientation to the other, degrees.
double rotationDifferenceDeg(const glm::dmat3& a, const glm::dmat3& b) {
  const glm::dmat3 d = a * glm::transpose(b);
  return std::acos(std::clamp((d[0][0] + d[1][1] + d[2][2] - 1.0) / 2.0, -1.0, 1.0)) * kDegPerRad;
}

void printWorldProjection(std::ostream& out, const calib::PlateCamera& fitted,
                          const calib::PlateCamera& truth) {
  constexpr int kCols = 32, kRows = 18;
  constexpr double kFarM = 20.0;
  double worst = 0.0, sum = 0.0;
  int count = 0;
  const calib::PlateIntrinsics& in = truth.intrinsics;
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kCols; ++i) {
      const glm::dvec2 px((i + 0.5) * in.widthPx / kCols - 0.5,
                          (j + 0.5) * in.heightPx / kRows - 0.5);
      const glm::dvec3 dir = calib::worldDirectionFromPlate(in, *truth.pose, px);
      const glm::dvec3& eye = truth.pose->positionWorldM;
      const double toFloor = dir.y < 0.0 ? -eye.y / dir.y : kFarM;
      const glm::dvec3 point = eye + std::min(toFloor, kFarM) * dir;
      const auto seen = calib::plateFromWorld(fitted.intrinsics, *fitted.pose, point);
      const double d = seen ? glm::length(*seen - px) : double(INFINITY);
      worst = std::max(worst, d);
      sum += d * d;
      ++count;
    }
  fmt::print(out, "  {:<28} {:>44.3f} px\n", "world points, max", worst);
  fmt::print(out, "  {:<28} {:>44.3f} px\n", "world points, rms", std::sqrt(sum / count));
  fmt::print(out,
             "  (world points: 32 x 18 pixels of the truth's image, each ray to the floor or "
             "20 m out, seen through the fitted intrinsics and pose)\n");
}

}  // namespace

void printPlateCamera(std::ostream& out, const calib::PlateCamera& plate, const std::string& path) {
  fmt::print(out, "{}: vemcast plate camera file\n", path);
  fmt::print(out, "camera:       {}, serial {}, {} x {} px, {}\n", plate.camera.model,
             plate.camera.serial, plate.camera.sensorWidthPx, plate.camera.sensorHeightPx,
             pixelFormatName(plate.camera.pixelFormat));
  printIntrinsics(out, plate);
  printPose(out, plate);
  printProbeAndColour(out, plate);
}

void printPlateComparison(std::ostream& out, const calib::PlateCamera& fitted,
                          const std::string& path, const calib::PlateCamera& truth,
                          const std::string& truthPath) {
  fmt::print(out, "{} compared with {} (the truth)\n", path, truthPath);
  fmt::print(out, "  {:<28} {:>16} {:>16} {:>14}\n", "value", "fitted", "truth", "difference");
  const calib::PlateIntrinsics& f = fitted.intrinsics;
  const calib::PlateIntrinsics& t = truth.intrinsics;
  fmt::print(out, "intrinsics: {} lens, truth {}\n", calib::plateLensModelName(f.model),
             calib::plateLensModelName(t.model));
  row(out, "fx", f.fxPx, t.fxPx, " px", 3);
  row(out, "fy", f.fyPx, t.fyPx, " px", 3);
  row(out, "cx", f.cxPx, t.cxPx, " px", 3);
  row(out, "cy", f.cyPx, t.cyPx, " px", 3);
  for (std::size_t i = 0; i < usedDistortion(f).size(); ++i)
    row(out, fmt::format("distortion {}", i + 1), f.distortion[i], t.distortion[i], "", 5);
  if (fitted.pose && truth.pose) {
    fmt::print(out, "pose:\n");
    const glm::dvec3 fp = fitted.pose->positionWorldM * 1000.0;
    const glm::dvec3 tp = truth.pose->positionWorldM * 1000.0;
    row(out, "position x", fp.x, tp.x, " mm", 1);
    row(out, "position y (height)", fp.y, tp.y, " mm", 1);
    row(out, "position z", fp.z, tp.z, " mm", 1);
    fmt::print(out, "  {:<28} {:>44.4f} deg\n", "orientation difference",
               rotationDifferenceDeg(fitted.pose->cameraFromWorld, truth.pose->cameraFromWorld));
    printWorldProjection(out, fitted, truth);
  }
  fmt::print(out, "probe:\n");
  row(out, "yaw", fitted.probeYawRad * kDegPerRad, truth.probeYawRad * kDegPerRad, " deg", 4);
  if (fitted.colour && truth.colour) {
    fmt::print(out, "colour:\n");
    for (std::size_t c = 0; c < 3; ++c)
      row(out, fmt::format("gain {} (1/1000 per cd/m2)", "RGB"[c]),
          fitted.colour->gainRgb[c] * 1000.0, truth.colour->gainRgb[c] * 1000.0, "", 6);
  }
}

}  // namespace vem::calibtool
