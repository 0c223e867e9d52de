#include "calib/core/plate_board_simulation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "calib/core/board_shader.h"
#include "util/contract.h"

namespace vem::calib {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kImageMarginPx = 2.0;
constexpr double kMinCornerSpacingPx = 8.0;

// The board's outline with its margin (squares from the first inner corner), sampled along edges.
std::vector<glm::dvec3> outlineMm(const Checkerboard& board, int perEdge) {
  std::vector<glm::dvec3> points;
  const double x0 = -2.0, x1 = board.innerCols + 1.0, y0 = -2.0, y1 = board.innerRows + 1.0;
  for (int i = 0; i <= perEdge; ++i) {
    const double t = double(i) / perEdge;
    for (const glm::dvec2 p :
         {glm::dvec2(x0 + t * (x1 - x0), y0), glm::dvec2(x0 + t * (x1 - x0), y1),
          glm::dvec2(x0, y0 + t * (y1 - y0)), glm::dvec2(x1, y0 + t * (y1 - y0))})
      points.emplace_back(p.x * board.squareMm, p.y * board.squareMm, 0.0);
  }
  return points;
}

struct PixelBox {
  int u0, v0, u1, v1;
};

// The pixels that can see the board and its margin (the whole image when part of it is behind).
PixelBox boardPixelBox(const Checkerboard& board, const BoardPose& pose,
                       const PlateIntrinsics& in) {
  double u0 = in.widthPx, v0 = in.heightPx, u1 = -1.0, v1 = -1.0;
  for (const glm::dvec3& p : outlineMm(board, 64)) {
    const std::optional<glm::dvec2> px = plateFromCamera(in, cameraFromBoardMm(pose, p));
    if (!px) return {0, 0, in.widthPx - 1, in.heightPx - 1};
    u0 = std::min(u0, px->x);
    v0 = std::min(v0, px->y);
    u1 = std::max(u1, px->x);
    v1 = std::max(v1, px->y);
  }
  return {std::max(0, int(std::floor(u0)) - 2), std::max(0, int(std::floor(v0)) - 2),
          std::min(in.widthPx - 1, int(std::ceil(u1)) + 2),
          std::min(in.heightPx - 1, int(std::ceil(v1)) + 2)};
}

// A sensor whose code is the value it is given: linear, black 0, clipped at the largest code.
CameraCalibration linearSensor(const PlateCamera& truth, const SimulationOptions& options) {
  CameraCalibration sensor;
  sensor.camera = truth.camera;
  const double g = 1.0 / (options.exposureUs * options.gain);
  sensor.photometric = PhotometricCalibration{LinearResponse{{g, g, g}}, 0.0,
                                              double(truth.camera.pixelFormat.maxCode())};
  return sensor;
}

// Mean value over each pixel's area along one row of the box.
std::vector<double> rowValues(const BoardShader& shader, const PlateIntrinsics& in,
                              const PixelBox& box, int v, int s) {
  std::vector<glm::dvec2> samples;
  for (int u = box.u0; u <= box.u1; ++u)
    for (int j = 0; j < s; ++j)
      for (int i = 0; i < s; ++i)
        samples.emplace_back(u - 0.5 + (i + 0.5) / s, v - 0.5 + (j + 0.5) / s);
  const std::vector<glm::dvec2> ideal = idealFromDistortedPx(in, samples);
  std::vector<double> values(std::size_t(box.u1 - box.u0 + 1), 0.0);
  for (std::size_t k = 0; k < ideal.size(); ++k) {
    const glm::dvec3 ray((ideal[k].x - in.cxPx) / in.fxPx, (ideal[k].y - in.cyPx) / in.fyPx, 1.0);
    values[k / std::size_t(s * s)] += shader.luminance(ray) / double(s * s);
  }
  return values;
}

glm::dmat3 rotationAbout(const glm::dvec3& axis, double angleRad) {
  return glm::mat3_cast(glm::angleAxis(angleRad, glm::normalize(axis)));
}

}  // namespace

RawFrame simulatePlateBoardView(const Checkerboard& board, const BoardPose& pose,
                                const PlateCamera& truth, const SimulationOptions& options,
                                double whiteCode, double blackCode) {
  const PlateIntrinsics& in = truth.intrinsics;
  VEM_EXPECTS(!intrinsicsDefect(in) && in.widthPx == truth.camera.sensorWidthPx &&
              in.heightPx == truth.camera.sensorHeightPx);
  VEM_EXPECTS(whiteCode > blackCode && blackCode > 0.0);
  RawFrame frame = RawFrame::blank(in.widthPx, in.heightPx, truth.camera.pixelFormat);
  frame.exposureUs = options.exposureUs;
  frame.gain = options.gain;
  SensorResponseSimulator sensor(linearSensor(truth, options), options);
  const BoardShader shader(board, pose, whiteCode, blackCode);
  const PixelBox box = boardPixelBox(board, pose, in);
  const double grey = std::sqrt(whiteCode * blackCode);
  const int s = std::max(1, options.supersamples);
  for (int v = 0; v < frame.height; ++v) {
    const bool rowInBox = v >= box.v0 && v <= box.v1;
    const std::vector<double> values =
        rowInBox ? rowValues(shader, in, box, v, s) : std::vector<double>{};
    for (int u = 0; u < frame.width; ++u) {
      const bool traced = rowInBox && u >= box.u0 && u <= box.u1;
      const double value = traced ? values[std::size_t(u - box.u0)] : grey;
      for (int c = 0; c < frame.format.channels; ++c)
        frame.codes[frame.index(u, v, c)] = sensor.code(c, value);
    }
  }
  return frame;
}

bool plateSeesWholeBoard(const Checkerboard& board, const BoardPose& pose,
                         const PlateIntrinsics& intrinsics, double maxObliquityDeg) {
  const glm::dvec3 normalCamera = pose.cameraFromBoard[2];
  if (!(glm::dot(normalCamera, pose.boardOriginCameraMm) > 0.0)) return false;
  for (const glm::dvec3& p : outlineMm(board, 24)) {
    const glm::dvec3 camera = cameraFromBoardMm(pose, p);
    const std::optional<glm::dvec2> px = plateFromCamera(intrinsics, camera);
    if (!px || px->x < kImageMarginPx || px->y < kImageMarginPx ||
        px->x > intrinsics.widthPx - 1 - kImageMarginPx ||
        px->y > intrinsics.heightPx - 1 - kImageMarginPx)
      return false;
    // Beyond strong barrel distortion a far point can fold back into the image: refuse rays at
    // more than 60 degrees from the axis.
    if (camera.z < 0.5 * glm::length(camera)) return false;
  }
  const std::vector<glm::dvec3> corners = boardCornersMm(board);
  std::vector<glm::dvec2> image;
  for (const glm::dvec3& c : corners) {
    const glm::dvec3 camera = cameraFromBoardMm(pose, c);
    if (glm::dot(normalCamera, glm::normalize(camera)) < std::cos(maxObliquityDeg * kDegree))
      return false;
    image.push_back(*plateFromCamera(intrinsics, camera));
  }
  for (int row = 0; row < board.innerRows; ++row)
    for (int col = 0; col < board.innerCols; ++col) {
      const std::size_t i = std::size_t(row * board.innerCols + col);
      if (col + 1 < board.innerCols && glm::length(image[i + 1] - image[i]) < kMinCornerSpacingPx)
        return false;
      if (row + 1 < board.innerRows &&
          glm::length(image[i + std::size_t(board.innerCols)] - image[i]) < kMinCornerSpacingPx)
        return false;
    }
  return true;
}

std::vector<BoardPose> plateBoardPoses(const Checkerboard& board, const PlateIntrinsics& intrinsics,
                                       int count, std::uint64_t seed) {
  VEM_EXPECTS(count >= 1 && !intrinsicsDefect(intrinsics));
  std::mt19937_64 random(seed);
  const auto uniform = [&random](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(random);
  };
  const glm::dvec3 centreMm((board.innerCols - 1) * board.squareMm / 2.0,
                            (board.innerRows - 1) * board.squareMm / 2.0, 0.0);
  const double widthMm = (board.innerCols + 3) * board.squareMm;
  const double goldenRad = std::numbers::pi * (3.0 - std::sqrt(5.0));
  std::vector<BoardPose> poses;
  for (int view = 0; view < count; ++view) {
    double reach = view == 0 ? 0.0 : 0.35 + 0.6 * double((view - 1) % 4) / 3.0;
    double distanceMm = intrinsics.fxPx * widthMm / (0.45 * intrinsics.widthPx);
    for (int attempt = 0;; ++attempt) {
      VEM_EXPECTS(attempt < 400);  // the board always fits at the centre, far enough away
      const double azimuth = view * goldenRad;
      const glm::dvec2 targetPx(
          intrinsics.cxPx + reach * std::cos(azimuth) * intrinsics.widthPx / 2,
          intrinsics.cyPx + reach * std::sin(azimuth) * intrinsics.heightPx / 2);
      const glm::dvec3 ray(
          glm::normalize(glm::dvec3((targetPx.x - intrinsics.cxPx) / intrinsics.fxPx,
                                    (targetPx.y - intrinsics.cyPx) / intrinsics.fyPx, 1.0)));
      const double tiltRad = view == 0 ? 0.0 : uniform(20.0, 45.0) * kDegree;
      const double axisRad = uniform(0.0, 2.0 * std::numbers::pi);
      const glm::dmat3 rotation =
          rotationAbout({std::cos(axisRad), std::sin(axisRad), 0.0}, tiltRad) *
          rotationAbout({0.0, 0.0, 1.0}, uniform(-15.0, 15.0) * kDegree);
      const BoardPose pose{rotation, ray * distanceMm - rotation * centreMm};
      if (plateSeesWholeBoard(board, pose, intrinsics)) {
        poses.push_back(pose);
        break;
      }
      if (attempt % 8 == 7) {  // nearer the centre and further away, a little each time
        reach *= 0.9;
        distanceMm *= 1.05;
      }
    }
  }
  return poses;
}

}  // namespace vem::calib
