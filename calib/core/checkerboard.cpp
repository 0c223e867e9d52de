#include "calib/core/checkerboard.h"
#include "calib/core/board_shader.h"
#include "calib/core/frame_around.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "util/contract.h"

namespace vem::calib {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// The board and its margin stay this far inside the image circle and the sensor's edge.
constexpr double kRimMarginRad = 1.0 * kDegree;
constexpr double kSensorMarginPx = 2.0;
// No corner is seen more obliquely than this (angle between the board's normal and the view ray).
constexpr double kMaxObliquityRad = 60.0 * kDegree;
// Neighbouring corners lie at least this far apart in the image: smaller squares defeat detectors.
constexpr double kMinCornerSpacingPx = 8.0;

// The sensor's pixel box (inclusive) that can see the board and its margin: the bounding box of its
// projected outline, grown by two pixels; the whole sensor when part of the board lies beyond the
// image circle (its outline then does not bound its image).
struct PixelBox {
  int u0, v0, u1, v1;
  [[nodiscard]] bool contains(int u, int v) const {
    return u >= u0 && u <= u1 && v >= v0 && v <= v1;
  }
};

PixelBox boardPixelBox(const Checkerboard& board, const BoardPose& pose,
                       const KannalaBrandtLens& lens, int widthPx, int heightPx) {
  constexpr int kPerEdge = 256;
  double u0 = widthPx, v0 = heightPx, u1 = -1.0, v1 = -1.0;
  const double x0 = -2.0, x1 = board.innerCols + 1.0, y0 = -2.0, y1 = board.innerRows + 1.0;
  for (int i = 0; i <= kPerEdge; ++i) {
    const double t = double(i) / kPerEdge;
    for (const glm::dvec2 q :
         {glm::dvec2(x0 + t * (x1 - x0), y0), glm::dvec2(x0 + t * (x1 - x0), y1),
          glm::dvec2(x0, y0 + t * (y1 - y0)), glm::dvec2(x1, y0 + t * (y1 - y0))}) {
      const auto p =
          lens.sensorFromCamera(cameraFromBoardMm(pose, glm::dvec3(q * board.squareMm, 0.0)));
      if (!p) return {0, 0, widthPx - 1, heightPx - 1};
      u0 = std::min(u0, p->x);
      v0 = std::min(v0, p->y);
      u1 = std::max(u1, p->x);
      v1 = std::max(v1, p->y);
    }
  }
  return {int(std::floor(u0)) - 2, int(std::floor(v0)) - 2, int(std::ceil(u1)) + 2,
          int(std::ceil(v1)) + 2};
}

// A pixel's luminance: the mean over supersamples^2 points of its area. Outside the board's pixel
// box a point reads the background or, beyond the image circle, 0, without tracing its ray (the
// same answer, found faster).
class PixelShader {
 public:
  PixelShader(const Checkerboard& board, const BoardPose& pose, const KannalaBrandtLens& lens,
              int widthPx, int heightPx, double whiteCdM2, double blackCdM2, int supersamples)
      : board_(board, pose, whiteCdM2, blackCdM2),
        lens_(lens),
        box_(boardPixelBox(board, pose, lens, widthPx, heightPx)),
        circleRadiusPx_(lens.radiusPx(lens.maxThetaRad)),
        greyCdM2_(std::sqrt(whiteCdM2 * blackCdM2)),
        supersamples_(supersamples) {}

  [[nodiscard]] double pixelLuminance(int u, int v) const {
    const int s = supersamples_;
    const bool traced = box_.contains(u, v);
    double sum = 0.0;
    for (int j = 0; j < s; ++j) {
      for (int i = 0; i < s; ++i) {
        const glm::dvec2 p(u - 0.5 + (i + 0.5) / s, v - 0.5 + (j + 0.5) / s);
        if (traced) {
          if (const auto ray = lens_.cameraFromSensor(p)) sum += board_.luminance(*ray);
        } else if (insideCircle(p)) {
          sum += greyCdM2_;
        }
      }
    }
    return sum / double(s * s);
  }

 private:
  // Exactly where cameraFromSensor has an answer.
  [[nodiscard]] bool insideCircle(const glm::dvec2& p) const {
    const glm::dvec2 d = p - lens_.principalPointPx;
    return std::hypot(d.x, d.y / lens_.aspect) <= circleRadiusPx_;
  }

  BoardShader board_;
  const KannalaBrandtLens& lens_;
  PixelBox box_;
  double circleRadiusPx_;
  double greyCdM2_;
  int supersamples_;
};

glm::dmat3 rotationAbout(const glm::dvec3& axis, double angleRad) {
  return glm::mat3_cast(glm::angleAxis(angleRad, glm::normalize(axis)));
}

glm::dvec3 directionAt(double thetaRad, double phiRad) {
  return {std::sin(thetaRad) * std::cos(phiRad), std::sin(thetaRad) * std::sin(phiRad),
          std::cos(thetaRad)};
}

// The board's outline with its margin, sampled, and its inner corners (board frame, mm).
std::vector<glm::dvec3> boardCheckPointsMm(const Checkerboard& board) {
  std::vector<glm::dvec3> points = boardCornersMm(board);
  const double x0 = -2.0, x1 = board.innerCols + 1.0, y0 = -2.0, y1 = board.innerRows + 1.0;
  constexpr int kPerEdge = 24;
  for (int i = 0; i <= kPerEdge; ++i) {
    const double t = double(i) / kPerEdge;
    for (const glm::dvec2 p :
         {glm::dvec2(x0 + t * (x1 - x0), y0), glm::dvec2(x0 + t * (x1 - x0), y1),
          glm::dvec2(x0, y0 + t * (y1 - y0)), glm::dvec2(x1, y0 + t * (y1 - y0))}) {
      points.emplace_back(p.x * board.squareMm, p.y * board.squareMm, 0.0);
    }
  }
  return points;
}

struct PoseCheck {
  const Checkerboard& board;
  const KannalaBrandtLens& lens;
  int widthPx;
  int heightPx;
  std::vector<glm::dvec3> pointsMm;
  std::size_t cornerCount;

  // Margin inside the circle and the sensor, printed side toward the camera, no grazing corner,
  // no square too small.
  [[nodiscard]] bool fits(const BoardPose& pose) const {
    return withinImage(pose) && squaresLargeEnough(pose);
  }

  [[nodiscard]] bool squaresLargeEnough(const BoardPose& pose) const {
    const auto image = [&](int col, int row) {
      return *lens.sensorFromCamera(
          cameraFromBoardMm(pose, glm::dvec3(col * board.squareMm, row * board.squareMm, 0.0)));
    };
    for (int row = 0; row < board.innerRows; ++row) {
      for (int col = 0; col < board.innerCols; ++col) {
        const glm::dvec2 p = image(col, row);
        if (col + 1 < board.innerCols && glm::length(image(col + 1, row) - p) < kMinCornerSpacingPx)
          return false;
        if (row + 1 < board.innerRows && glm::length(image(col, row + 1) - p) < kMinCornerSpacingPx)
          return false;
      }
    }
    return true;
  }

  [[nodiscard]] bool withinImage(const BoardPose& pose) const {
    const glm::dvec3 frontNormal = -pose.cameraFromBoard[2];
    for (std::size_t i = 0; i < pointsMm.size(); ++i) {
      const glm::dvec3 p = cameraFromBoardMm(pose, pointsMm[i]);
      if (std::atan2(std::hypot(p.x, p.y), p.z) > lens.maxThetaRad - kRimMarginRad) return false;
      const std::optional<glm::dvec2> s = lens.sensorFromCamera(p);
      if (!s || s->x < kSensorMarginPx || s->y < kSensorMarginPx ||
          s->x > widthPx - 1.0 - kSensorMarginPx || s->y > heightPx - 1.0 - kSensorMarginPx) {
        return false;
      }
      if (i < cornerCount &&
          glm::dot(frontNormal, -p) < std::cos(kMaxObliquityRad) * glm::length(p)) {
        return false;
      }
    }
    return true;
  }
};

// The shape of one view, drawn at random; only the direction of its centre is left to choose.
struct ViewShape {
  double distanceMm;
  double spinRad;            // about the board's normal
  double tiltRad;            // of the board's normal away from the line of sight
  double tiltAxisOffsetRad;  // of the tilt axis from the tangential direction
};

BoardPose poseFor(const Checkerboard& board, const ViewShape& shape, double thetaRad,
                  double phiRad) {
  const glm::dvec3 centreDir = directionAt(thetaRad, phiRad);
  const glm::dmat3 facing = frameAround(centreDir) * rotationAbout({0.0, 0.0, 1.0}, shape.spinRad);
  // Tangential axis (perpendicular to the centre ray and the optical axis), turned by the offset.
  const glm::dvec3 tangential(-std::sin(phiRad), std::cos(phiRad), 0.0);
  const glm::dvec3 tiltAxis = rotationAbout(centreDir, shape.tiltAxisOffsetRad) * tangential;
  BoardPose pose;
  pose.cameraFromBoard = rotationAbout(tiltAxis, shape.tiltRad) * facing;
  const glm::dvec3 centreBoardMm(0.5 * (board.innerCols - 1) * board.squareMm,
                                 0.5 * (board.innerRows - 1) * board.squareMm, 0.0);
  pose.boardOriginCameraMm = shape.distanceMm * centreDir - pose.cameraFromBoard * centreBoardMm;
  return pose;
}

// The largest centre angle at which the view still fits (bisection), or nullopt if it never does.
std::optional<double> outermostTheta(const PoseCheck& check, const ViewShape& shape,
                                     double phiRad) {
  if (!check.fits(poseFor(check.board, shape, 0.0, phiRad))) return std::nullopt;
  double lo = 0.0, hi = check.lens.maxThetaRad;
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    (check.fits(poseFor(check.board, shape, mid, phiRad)) ? lo : hi) = mid;
  }
  return lo;
}

class Uniform {
 public:
  explicit Uniform(std::uint64_t seed) : engine_(seed) {}
  double operator()(double lo, double hi) {
    return lo + (hi - lo) * double(engine_() >> 11) * 0x1.0p-53;  // portable, unlike <random>'s
  }

 private:
  std::mt19937_64 engine_;
};

// The largest angle from the optical axis of the pose's corners.
double outermostCornerTheta(const PoseCheck& check, const BoardPose& pose) {
  double theta = 0.0;
  for (std::size_t i = 0; i < check.cornerCount; ++i) {
    const glm::dvec3 p = cameraFromBoardMm(pose, check.pointsMm[i]);
    theta = std::max(theta, std::atan2(std::hypot(p.x, p.y), p.z));
  }
  return theta;
}

// A view of random size, spin and tilt whose centre lies at azimuth phi, `reach` (0 to 1) of the
// way from the optical axis to the outermost angle at which it still fits, or nullopt if it does
// not fit even on the axis.
std::optional<BoardPose> drawView(const PoseCheck& check, double reach, double phiRad,
                                  double halfSpanRad, double maxTiltRad, Uniform& uniform) {
  const Checkerboard& board = check.board;
  const double halfDiagonalMm =
      0.5 * board.squareMm * std::hypot(board.innerCols + 3.0, board.innerRows + 3.0);
  const double tiltSign = uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0;
  const ViewShape shape{halfDiagonalMm / std::tan(halfSpanRad),
                        uniform(0.0, 2.0 * std::numbers::pi),
                        tiltSign * uniform(0.4, 1.0) * maxTiltRad, uniform(-30.0, 30.0) * kDegree};
  const std::optional<double> outermost = outermostTheta(check, shape, phiRad);
  if (!outermost) return std::nullopt;
  return poseFor(board, shape, reach * *outermost, phiRad);
}

// Views at the rim (reach near 1) take the best of several draws: the one whose corners reach
// furthest out; the others take the first draw that fits.
BoardPose placeView(const PoseCheck& check, double reach, double phiRad, Uniform& uniform) {
  const bool rim = reach > 0.9;
  const int draws = rim ? 12 : 1;
  const double halfSpanRad = (rim ? uniform(20.0, 24.0) : uniform(30.0, 40.0)) * kDegree;
  const double maxTiltRad = 40.0 * kDegree;
  // When no draw fits even on the axis, the board is too large for the sensor or its squares too
  // small for the lens: try it nearer and further, a little more each time.
  for (int attempt = 0; attempt < 40; ++attempt) {
    const double step = std::pow(1.1, (attempt + 1) / 2);
    const double span = std::min(halfSpanRad * (attempt % 2 == 0 ? 1.0 / step : step), 1.4);
    std::optional<BoardPose> best;
    for (int d = 0; d < draws; ++d) {
      const std::optional<BoardPose> pose =
          drawView(check, reach, phiRad, span, maxTiltRad, uniform);
      if (pose &&
          (!best || outermostCornerTheta(check, *pose) > outermostCornerTheta(check, *best))) {
        best = pose;
      }
    }
    if (best) return *best;
  }
  VEM_UNREACHABLE("no pose fits this board, lens and sensor");
}

}  // namespace

std::vector<glm::dvec3> boardCornersMm(const Checkerboard& board) {
  std::vector<glm::dvec3> corners;
  corners.reserve(std::size_t(board.innerCols * board.innerRows));
  for (int row = 0; row < board.innerRows; ++row) {
    for (int col = 0; col < board.innerCols; ++col) {
      corners.emplace_back(col * board.squareMm, row * board.squareMm, 0.0);
    }
  }
  return corners;
}

glm::dvec3 cameraFromBoardMm(const BoardPose& pose, const glm::dvec3& boardMm) {
  return pose.cameraFromBoard * boardMm + pose.boardOriginCameraMm;
}

RawFrame simulateBoardView(const Checkerboard& board, const BoardPose& pose,
                           const CameraCalibration& truth, const SimulationOptions& options,
                           double whiteCdM2, double blackCdM2) {
  VEM_EXPECTS(truth.lens && truth.photometric);
  const CameraIdentity& camera = truth.camera;
  RawFrame frame = RawFrame::blank(camera.sensorWidthPx, camera.sensorHeightPx, camera.pixelFormat);
  frame.exposureUs = options.exposureUs;
  frame.gain = options.gain;
  SensorResponseSimulator sensor(truth, options);
  const PixelShader shader(board, pose, *truth.lens, frame.width, frame.height, whiteCdM2,
                           blackCdM2, std::max(1, options.supersamples));
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      const double luminance = shader.pixelLuminance(u, v) * options.radianceScale;
      for (int c = 0; c < camera.pixelFormat.channels; ++c) {
        frame.codes[frame.index(u, v, c)] = sensor.code(c, luminance);
      }
    }
  }
  return frame;
}

std::vector<BoardPose> boardPosesCoveringLens(const Checkerboard& board,
                                              const KannalaBrandtLens& lens, int widthPx,
                                              int heightPx, int count, std::uint64_t seed) {
  const PoseCheck check{board,
                        lens,
                        widthPx,
                        heightPx,
                        boardCheckPointsMm(board),
                        std::size_t(board.innerCols * board.innerRows)};
  const double goldenAngleRad = std::numbers::pi * (3.0 - std::sqrt(5.0));
  Uniform uniform(seed);
  std::vector<BoardPose> poses;
  for (int view = 0; view < count; ++view) {
    // Radii spaced for equal image areas, but reaching the rim by 60 % of the views: the rim, where
    // the polynomial is least constrained, gets the other 40 %, at azimuths all around.
    const double reach =
        count > 1 ? std::min(1.0, 1.3 * std::sqrt(double(view) / (count - 1))) : 0.0;
    poses.push_back(placeView(check, reach, view * goldenAngleRad + uniform(-0.3, 0.3), uniform));
  }
  return poses;
}

}  // namespace vem::calib
