#include "calib/core/board_detection.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace vem::calib {
namespace {

// The refinement's patch: kPatchPx square, +-kPatchHalfSquares of a square around the corner on the
// board plane (0.03 squares per patch pixel). The saddle is found coarse to fine: a quadratic
// fitted over a wide disc of a well smoothed patch pulls a corner that the detector placed a third
// of a square off back to it, then a narrow disc of a lightly smoothed patch locates it.
constexpr int kPatchPx = 61;
constexpr double kPatchHalfSquares = 0.9;
struct SaddleScale {
  double smoothingPatchPx;
  int radiusPatchPx;
  int iterations;
};
constexpr SaddleScale kCoarse{5.0, 15, 3};
constexpr SaddleScale kFine{2.5, 9, 5};
constexpr double kMaxShiftSquares = 0.35;  // the next saddles lie a whole square away
constexpr double kRecentreSquares = 0.05;

// One grey value per pixel: the code, or the Rec. 709 weighting of the channels' codes.
std::vector<float> greyCodes(const RawFrame& frame) {
  std::vector<float> grey(std::size_t(frame.width) * std::size_t(frame.height));
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      const std::size_t i = std::size_t(v) * std::size_t(frame.width) + std::size_t(u);
      grey[i] = frame.format.channels == 1
                    ? float(frame.at(u, v))
                    : 0.2126f * float(frame.at(u, v, 0)) + 0.7152f * float(frame.at(u, v, 1)) +
                          0.0722f * float(frame.at(u, v, 2));
    }
  }
  return grey;
}

// The frame as 8-bit grey: each pixel's grey value becomes its percentile among the frame's (a rank
// mapping: histogram equalisation), so the board gets grey levels in proportion to its share of the
// pixels wherever it lies in the code range: the black outside the image circle, bright lamps or a
// log sensor's compression cannot squeeze it into a few levels.
cv::Mat rankedGrey(const RawFrame& frame) {
  const std::vector<float> grey = greyCodes(frame);
  std::vector<double> below(65537, 0.0);  // below[c + 1] counts values <= c, after the sum
  for (float g : grey) below[std::size_t(std::lround(g)) + 1] += 1.0;
  for (std::size_t c = 1; c < below.size(); ++c) below[c] += below[c - 1];
  const double total = double(grey.size());
  cv::Mat image(frame.height, frame.width, CV_8UC1);
  for (int v = 0; v < frame.height; ++v) {
    auto* row = image.ptr<std::uint8_t>(v);
    for (int u = 0; u < frame.width; ++u) {
      const auto c = std::size_t(
          std::lround(grey[std::size_t(v) * std::size_t(frame.width) + std::size_t(u)]));
      const double midRank = 0.5 * (below[c] + below[c + 1]);  // ties share their middle rank
      row[u] = cv::saturate_cast<std::uint8_t>(255.0 * midRank / total);
    }
  }
  return image;
}

std::optional<std::vector<cv::Point2f>> findCorners(const cv::Mat& image, cv::Size patternSize) {
  std::vector<cv::Point2f> corners;
  if (cv::findChessboardCornersSB(image, patternSize, corners, cv::CALIB_CB_EXHAUSTIVE)) {
    return corners;
  }
  // The classic detector as a fallback; its fast check keeps frames without a board quick.
  if (cv::findChessboardCorners(
          image, patternSize, corners,
          cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_FAST_CHECK)) {
    cv::cornerSubPix(image, corners, cv::Size(5, 5), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::EPS | cv::TermCriteria::COUNT, 50, 0.001));
    return corners;
  }
  return std::nullopt;
}

// Twice the signed area enclosed by the grid's outer corners, in image coordinates (v down):
// positive when the board's +X and +Y appear as the image's +u and +v do, i.e. as seen from the
// printed side.
double signedGridArea(const std::vector<glm::dvec2>& c, int cols, int rows) {
  std::vector<glm::dvec2> ring;
  for (int col = 0; col < cols; ++col) ring.push_back(c[std::size_t(col)]);
  for (int row = 1; row < rows; ++row) ring.push_back(c[std::size_t(row * cols + cols - 1)]);
  for (int col = cols - 2; col >= 0; --col) ring.push_back(c[std::size_t((rows - 1) * cols + col)]);
  for (int row = rows - 2; row > 0; --row) ring.push_back(c[std::size_t(row * cols)]);
  double area = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const glm::dvec2& a = ring[i];
    const glm::dvec2& b = ring[(i + 1) % ring.size()];
    area += a.x * b.y - b.x * a.y;
  }
  return area;
}

// Mean grey of a 3 x 3 window around the centre of the square between corner (col, row) and
// corner (col + 1, row + 1).
double squareGrey(const cv::Mat& image, const std::vector<glm::dvec2>& c, int cols, int col,
                  int row) {
  const auto at = [&](int dc, int dr) { return c[std::size_t((row + dr) * cols + col + dc)]; };
  const glm::dvec2 centre = 0.25 * (at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1));
  double sum = 0.0;
  for (int dv = -1; dv <= 1; ++dv) {
    for (int du = -1; du <= 1; ++du) {
      const int u = std::clamp(int(std::lround(centre.x)) + du, 0, image.cols - 1);
      const int v = std::clamp(int(std::lround(centre.y)) + dv, 0, image.rows - 1);
      sum += image.at<std::uint8_t>(v, u);
    }
  }
  return sum / 9.0;
}

// Puts OpenCV's corners in the board's order (see the header).
void orderLikeBoard(std::vector<glm::dvec2>& c, const cv::Mat& image, int cols, int rows) {
  // Mirrored (rows running right to left): findChessboardCornersSB keeps the image's handedness
  // itself; this guards the classic fallback.
  if (signedGridArea(c, cols, rows) < 0.0) {
    for (int row = 0; row < rows; ++row) {
      std::reverse(c.begin() + row * cols, c.begin() + (row + 1) * cols);
    }
  }
  const bool colourTellsEnds = (cols + rows) % 2 == 1;
  if (colourTellsEnds &&
      squareGrey(image, c, cols, 0, 0) > squareGrey(image, c, cols, cols - 2, rows - 2)) {
    std::reverse(c.begin(), c.end());  // turned by 180 degrees: the first square must be black
  }
}

// The saddle point of the quadratic least-squares fit to `image` over a disc around `centre`
// (x = column, y = row); nullopt when the fit has no saddle there.
std::optional<glm::dvec2> quadraticSaddle(const cv::Mat& image, const glm::dvec2& centre, int r) {
  const int u0 = int(std::lround(centre.x)), v0 = int(std::lround(centre.y));
  if (u0 < r || v0 < r || u0 + r >= image.cols || v0 + r >= image.rows) return std::nullopt;
  // f = a x^2 + b x y + c y^2 + d x + e y + g, in pixels from (u0, v0): normal equations.
  cv::Matx66d normal = cv::Matx66d::zeros();
  cv::Vec6d rhs = cv::Vec6d::all(0.0);
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy > r * r) continue;
      const cv::Vec6d basis(dx * dx, dx * dy, dy * dy, dx, dy, 1.0);
      normal += basis * basis.t();
      rhs += basis * double(image.at<float>(v0 + dy, u0 + dx));
    }
  }
  cv::Vec6d q;
  if (!cv::solve(normal, rhs, q, cv::DECOMP_CHOLESKY)) return std::nullopt;
  const double det = 4.0 * q[0] * q[2] - q[1] * q[1];
  if (!(det < 0.0)) return std::nullopt;  // an extremum or a ridge, not a saddle
  // Zero gradient: [2a b; b 2c] (x, y) = -(d, e).
  return glm::dvec2(u0 + (q[1] * q[4] - 2.0 * q[2] * q[3]) / det,
                    v0 + (q[1] * q[3] - 2.0 * q[0] * q[4]) / det);
}

// The corner's saddle on the smoothed board-plane patch, iterated as the disc recentres; in
// squares from the corner, or nullopt.
std::optional<glm::dvec2> saddleOffsetSquares(const cv::Mat& patch) {
  const double middle = 0.5 * (kPatchPx - 1);
  glm::dvec2 saddle(middle);
  for (const SaddleScale& scale : {kCoarse, kFine}) {
    cv::Mat smoothed;
    cv::GaussianBlur(patch, smoothed, cv::Size(0, 0), scale.smoothingPatchPx);
    for (int i = 0; i < scale.iterations; ++i) {
      const std::optional<glm::dvec2> next = quadraticSaddle(smoothed, saddle, scale.radiusPatchPx);
      if (!next) return std::nullopt;
      saddle = *next;
    }
  }
  const glm::dvec2 offset = (saddle - middle) * (2.0 * kPatchHalfSquares / (kPatchPx - 1));
  if (glm::length(offset) > kMaxShiftSquares) return std::nullopt;
  return offset;
}

// The board-plane point (mm) that the lens and pose put at sensor point `p`: where p's ray meets
// the board; nullopt when it misses the board's front.
std::optional<glm::dvec3> boardPointAt(const KannalaBrandtLens& lens, const BoardPose& pose,
                                       const glm::dvec2& p) {
  const std::optional<glm::dvec3> ray = lens.cameraFromSensor(p);
  if (!ray) return std::nullopt;
  const glm::dvec3 normal = pose.cameraFromBoard[2];
  const double distance = glm::dot(normal, pose.boardOriginCameraMm) / glm::dot(normal, *ray);
  if (!(distance > 0.0) || !std::isfinite(distance)) return std::nullopt;
  glm::dvec3 boardMm =
      glm::transpose(pose.cameraFromBoard) * (distance * *ray - pose.boardOriginCameraMm);
  boardMm.z = 0.0;
  return boardMm;
}

// The patch around board point `centreMm` (see the header): kPatchPx square, board +X along its
// rows; sensor positions through lens and pose, bilinear samples of `grey`. nullopt when it leaves
// the frame.
std::optional<cv::Mat> boardPlanePatch(const cv::Mat& grey, const Checkerboard& board,
                                       const KannalaBrandtLens& lens, const BoardPose& pose,
                                       const glm::dvec3& centreMm) {
  const double stepMm = 2.0 * kPatchHalfSquares * board.squareMm / (kPatchPx - 1);
  const double middle = 0.5 * (kPatchPx - 1);
  cv::Mat mapU(kPatchPx, kPatchPx, CV_32F), mapV(kPatchPx, kPatchPx, CV_32F);
  for (int j = 0; j < kPatchPx; ++j) {
    for (int i = 0; i < kPatchPx; ++i) {
      const glm::dvec3 q = centreMm + glm::dvec3((i - middle) * stepMm, (j - middle) * stepMm, 0.0);
      const auto p = lens.sensorFromCamera(cameraFromBoardMm(pose, q));
      if (!p || p->x < 0.0 || p->y < 0.0 || p->x > grey.cols - 1.0 || p->y > grey.rows - 1.0) {
        return std::nullopt;
      }
      mapU.at<float>(j, i) = float(p->x);
      mapV.at<float>(j, i) = float(p->y);
    }
  }
  cv::Mat patch;
  cv::remap(grey, patch, mapU, mapV, cv::INTER_LINEAR);
  return patch;
}

// One corner measured again on the board plane around where the detector saw it, or nullopt.
// The patch may reach a little past the lens's rim: it projects through `unbounded`, the same
// lens without its limit.
std::optional<glm::dvec2> refineCorner(const cv::Mat& grey, const Checkerboard& board,
                                       const KannalaBrandtLens& lens,
                                       const KannalaBrandtLens& unbounded, const BoardPose& pose,
                                       const glm::dvec2& detectedPx) {
  std::optional<glm::dvec3> centreMm = boardPointAt(lens, pose, detectedPx);
  if (!centreMm) return std::nullopt;
  // A second patch, centred on the first one's saddle, when that lay off centre.
  for (int pass = 0; pass < 2; ++pass) {
    const std::optional<cv::Mat> patch = boardPlanePatch(grey, board, unbounded, pose, *centreMm);
    if (!patch) return std::nullopt;
    const std::optional<glm::dvec2> offset = saddleOffsetSquares(*patch);
    if (!offset) return std::nullopt;
    *centreMm += glm::dvec3(*offset * board.squareMm, 0.0);
    if (glm::length(*offset) < kRecentreSquares) break;
  }
  return unbounded.sensorFromCamera(cameraFromBoardMm(pose, *centreMm));
}

}  // namespace

std::optional<std::vector<glm::dvec2>> detectCheckerboard(const RawFrame& frame,
                                                          const Checkerboard& board) {
  if (board.innerCols < 2 || board.innerRows < 2 || frame.width == 0 || frame.height == 0) {
    return std::nullopt;
  }
  const cv::Mat image = rankedGrey(frame);
  const std::optional<std::vector<cv::Point2f>> found =
      findCorners(image, cv::Size(board.innerCols, board.innerRows));
  if (!found || found->size() != std::size_t(board.innerCols * board.innerRows))
    return std::nullopt;
  std::vector<glm::dvec2> corners;
  corners.reserve(found->size());
  for (const cv::Point2f& p : *found) corners.emplace_back(double(p.x), double(p.y));
  orderLikeBoard(corners, image, board.innerCols, board.innerRows);
  return corners;
}

std::vector<glm::dvec2> refineCorners(const RawFrame& frame, const Checkerboard& board,
                                      const KannalaBrandtLens& lens, const BoardPose& pose,
                                      std::span<const glm::dvec2> corners) {
  std::vector<float> codes = greyCodes(frame);
  const cv::Mat grey(frame.height, frame.width, CV_32F, codes.data());
  KannalaBrandtLens unbounded = lens;
  unbounded.maxThetaRad = std::numbers::pi;
  std::vector<glm::dvec2> refined(corners.begin(), corners.end());
  for (glm::dvec2& corner : refined) {
    if (const auto p = refineCorner(grey, board, lens, unbounded, pose, corner)) corner = *p;
  }
  return refined;
}

}  // namespace vem::calib
