#include "calib/core/plate_camera.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <opencv2/calib3d.hpp>

#include "util/contract.h"

namespace vem::calib {
namespace {

// Normalised coordinates (x, y) -> distorted normalised coordinates (plate_camera.h's formulas).
glm::dvec2 distortNormalised(const PlateIntrinsics& in, const glm::dvec2& xy) {
  const std::array<double, 5>& d = in.distortion;
  const double r2 = glm::dot(xy, xy);
  if (in.model == PlateLensModel::KannalaBrandt) {
    const double r = std::sqrt(r2);
    if (r < 1e-12) return xy;
    const double theta = std::atan(r);
    const double t2 = theta * theta;
    const double thetaD = theta * (1.0 + t2 * (d[0] + t2 * (d[1] + t2 * (d[2] + t2 * d[3]))));
    return xy * (thetaD / r);
  }
  const double radial = 1.0 + r2 * (d[0] + r2 * (d[1] + r2 * d[4]));
  const double x = xy.x, y = xy.y;
  return {x * radial + 2.0 * d[2] * x * y + d[3] * (r2 + 2.0 * x * x),
          y * radial + d[2] * (r2 + 2.0 * y * y) + 2.0 * d[3] * x * y};
}

glm::dvec2 pixelFromNormalised(const PlateIntrinsics& in, const glm::dvec2& xy) {
  return {in.fxPx * xy.x + in.cxPx, in.fyPx * xy.y + in.cyPx};
}

glm::dvec2 normalisedFromPixel(const PlateIntrinsics& in, const glm::dvec2& px) {
  return {(px.x - in.cxPx) / in.fxPx, (px.y - in.cyPx) / in.fyPx};
}

cv::Matx33d cameraMatrix(const PlateIntrinsics& in) {
  return {in.fxPx, 0.0, in.cxPx, 0.0, in.fyPx, in.cyPx, 0.0, 0.0, 1.0};
}

}  // namespace

const char* plateLensModelName(PlateLensModel model) {
  switch (model) {
    case PlateLensModel::BrownConrady: return "brown-conrady";
    case PlateLensModel::KannalaBrandt: return "kannala-brandt";
  }
  VEM_UNREACHABLE("a PlateLensModel has one of two values");
}

std::optional<PlateLensModel> parsePlateLensModel(std::string_view name) {
  if (name == "brown-conrady") return PlateLensModel::BrownConrady;
  if (name == "kannala-brandt") return PlateLensModel::KannalaBrandt;
  return std::nullopt;
}

int distortionCount(PlateLensModel model) { return model == PlateLensModel::BrownConrady ? 5 : 4; }

glm::dvec3 cameraFromWorldM(const PlatePose& pose, const glm::dvec3& pointWorldM) {
  return pose.cameraFromWorld * (pointWorldM - pose.positionWorldM);
}

std::optional<glm::dvec2> plateFromCamera(const PlateIntrinsics& intrinsics,
                                          const glm::dvec3& pointCamera) {
  if (!(pointCamera.z > 0.0)) return std::nullopt;
  const glm::dvec2 xy(pointCamera.x / pointCamera.z, pointCamera.y / pointCamera.z);
  return pixelFromNormalised(intrinsics, distortNormalised(intrinsics, xy));
}

std::optional<glm::dvec2> plateFromWorld(const PlateIntrinsics& intrinsics, const PlatePose& pose,
                                         const glm::dvec3& pointWorldM) {
  return plateFromCamera(intrinsics, cameraFromWorldM(pose, pointWorldM));
}

std::optional<glm::dvec2> plateFromWorldDirection(const PlateIntrinsics& intrinsics,
                                                  const PlatePose& pose,
                                                  const glm::dvec3& dirWorld) {
  return plateFromCamera(intrinsics, pose.cameraFromWorld * dirWorld);
}

glm::dvec2 distortedFromIdealPx(const PlateIntrinsics& intrinsics, const glm::dvec2& idealPx) {
  return pixelFromNormalised(
      intrinsics, distortNormalised(intrinsics, normalisedFromPixel(intrinsics, idealPx)));
}

std::vector<glm::dvec2> idealFromDistortedPx(const PlateIntrinsics& intrinsics,
                                             std::span<const glm::dvec2> distortedPx) {
  VEM_EXPECTS(!intrinsicsDefect(intrinsics));
  std::vector<glm::dvec2> ideal(distortedPx.size());
  if (distortedPx.empty()) return ideal;
  std::vector<cv::Point2d> in(distortedPx.size()), out;
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = {distortedPx[i].x, distortedPx[i].y};
  const cv::Matx33d k = cameraMatrix(intrinsics);
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-10);
  if (intrinsics.model == PlateLensModel::KannalaBrandt) {
    const cv::Vec4d d(intrinsics.distortion[0], intrinsics.distortion[1], intrinsics.distortion[2],
                      intrinsics.distortion[3]);
    cv::fisheye::undistortPoints(in, out, k, d, cv::noArray(), k, criteria);
  } else {
    const cv::Vec<double, 5> d(intrinsics.distortion.data());
    cv::undistortPoints(in, out, k, d, cv::noArray(), k, criteria);
  }
  for (std::size_t i = 0; i < out.size(); ++i) ideal[i] = {out[i].x, out[i].y};
  return ideal;
}

glm::dvec2 idealFromDistortedPx(const PlateIntrinsics& intrinsics, const glm::dvec2& distortedPx) {
  return idealFromDistortedPx(intrinsics, std::span(&distortedPx, 1)).front();
}

glm::dvec3 cameraDirectionFromPlate(const PlateIntrinsics& intrinsics,
                                    const glm::dvec2& distortedPx) {
  const glm::dvec2 xy =
      normalisedFromPixel(intrinsics, idealFromDistortedPx(intrinsics, distortedPx));
  return glm::normalize(glm::dvec3(xy, 1.0));
}

glm::dvec3 worldDirectionFromPlate(const PlateIntrinsics& intrinsics, const PlatePose& pose,
                                   const glm::dvec2& distortedPx) {
  return glm::transpose(pose.cameraFromWorld) * cameraDirectionFromPlate(intrinsics, distortedPx);
}

glm::dmat3 worldFromBoard() {
  // Columns: the board's X, Y and Z axes in the world.
  return {glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 0.0, 1.0), glm::dvec3(0.0, -1.0, 0.0)};
}

PlatePose plateLookingAt(const glm::dvec3& positionWorldM, const glm::dvec3& targetWorldM) {
  const glm::dvec3 forward = glm::normalize(targetWorldM - positionWorldM);
  const glm::dvec3 sideways = glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0));
  VEM_EXPECTS(glm::length(sideways) > 1e-9);
  const glm::dvec3 right = glm::normalize(sideways);
  const glm::dvec3 down = glm::cross(forward, right);
  // Rows of cameraFromWorld: the camera's +X, +Y and +Z in the world.
  return PlatePose{glm::transpose(glm::dmat3(right, down, forward)), positionWorldM};
}

std::optional<const char*> intrinsicsDefect(const PlateIntrinsics& intrinsics) {
  if (intrinsics.widthPx < 1 || intrinsics.heightPx < 1) return "the sensor has no pixels";
  for (const double v : {intrinsics.fxPx, intrinsics.fyPx, intrinsics.cxPx, intrinsics.cyPx})
    if (!std::isfinite(v)) return "a camera-matrix value is not finite";
  if (!(intrinsics.fxPx > 0.0) || !(intrinsics.fyPx > 0.0)) return "fx and fy must be above 0";
  for (const double d : intrinsics.distortion)
    if (!std::isfinite(d)) return "a distortion coefficient is not finite";
  if (intrinsics.model == PlateLensModel::KannalaBrandt && intrinsics.distortion[4] != 0.0)
    return "a Kannala-Brandt lens has 4 coefficients (the fifth must be 0)";
  return std::nullopt;
}

}  // namespace vem::calib
