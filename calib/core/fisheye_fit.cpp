#include "calib/core/fisheye_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include "calib/core/board_detection.h"
#include "util/contract.h"
#include "calib/core/frame_around.h"

namespace vem::calib {
namespace {

// Lens parameters in the fit's order: k1..k5 (px), cx, cy (px), aspect.
constexpr int kLensParams = 8;
using LensValues = std::array<double, kLensParams>;
using LensMask = std::array<bool, kLensParams>;
constexpr LensMask kScaleAndCentre{true, false, false, false, false, true, true, false};
constexpr LensMask kWholeLens{true, true, true, true, true, true, true, true};
constexpr int kPoseParams = 6;  // rotation vector (rad), translation (mm)
constexpr int kMaxIterations = 300;
constexpr double kStepTolerance = 1e-10;
constexpr int kRefinementRounds = 2;  // corners measured again on the board plane, then refitted
constexpr double kRightBasinRmsPx = 2.0;  // a fit this good did not start from a wrong guess

LensValues valuesOf(const KannalaBrandtLens& lens) {
  const auto& k = lens.kPx;
  return {k[0],       k[1], k[2], k[3], k[4], lens.principalPointPx.x, lens.principalPointPx.y,
          lens.aspect};
}

KannalaBrandtLens lensOf(const LensValues& v, double maxThetaRad) {
  KannalaBrandtLens lens;
  lens.kPx = {v[0], v[1], v[2], v[3], v[4]};
  lens.principalPointPx = {v[5], v[6]};
  lens.aspect = v[7];
  lens.maxThetaRad = maxThetaRad;
  return lens;
}

double maxThetaRad(const FisheyeFitOptions& options) {
  return 0.5 * options.fovDeg * std::numbers::pi / 180.0;
}

struct Pose {
  cv::Vec3d rotation;  // Rodrigues vector of cameraFromBoard
  cv::Vec3d translationMm;
};

glm::dmat3 glmFrom(const cv::Matx33d& m) {
  glm::dmat3 g;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) g[c][r] = m(r, c);  // glm indexes [column][row]
  }
  return g;
}

cv::Matx33d cvFrom(const glm::dmat3& g) {
  cv::Matx33d m;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m(r, c) = g[c][r];
  }
  return m;
}

BoardPose boardPoseOf(const Pose& pose) {
  cv::Matx33d rotation;
  cv::Rodrigues(pose.rotation, rotation);
  const cv::Vec3d& t = pose.translationMm;
  return {glmFrom(rotation), glm::dvec3(t[0], t[1], t[2])};
}

// The reprojection residuals (detected minus projected, px) of one view: 2 per corner.
void viewResiduals(const KannalaBrandtLens& lens, const Pose& pose,
                   std::span<const glm::dvec3> boardMm, std::span<const glm::dvec2> corners,
                   double* out) {
  const BoardPose board = boardPoseOf(pose);
  for (std::size_t i = 0; i < boardMm.size(); ++i) {
    const std::optional<glm::dvec2> p = lens.sensorFromCamera(cameraFromBoardMm(board, boardMm[i]));
    const glm::dvec2 d = p ? corners[i] - *p : glm::dvec2(1e6);
    out[2 * i] = d.x;
    out[2 * i + 1] = d.y;
  }
}

// The fit's unknowns: the free lens parameters, then six per view; the fixed ones kept aside.
struct Unknowns {
  LensValues lens;
  std::vector<Pose> poses;
};

class Packing {
 public:
  explicit Packing(const LensMask& mask) : mask_(mask) {}

  [[nodiscard]] int freeLensCount() const {
    return int(std::count(mask_.begin(), mask_.end(), true));
  }

  [[nodiscard]] cv::Mat pack(const Unknowns& u) const {
    cv::Mat x(freeLensCount() + kPoseParams * int(u.poses.size()), 1, CV_64F);
    auto* p = x.ptr<double>();
    for (int i = 0; i < kLensParams; ++i) {
      if (mask_[std::size_t(i)]) *p++ = u.lens[std::size_t(i)];
    }
    for (const Pose& pose : u.poses) {
      for (int i = 0; i < 3; ++i) *p++ = pose.rotation[i];
      for (int i = 0; i < 3; ++i) *p++ = pose.translationMm[i];
    }
    return x;
  }

  // Overwrites the free values of `u` (whose fixed values stay) from x.
  void unpack(const double* x, Unknowns& u) const {
    for (int i = 0; i < kLensParams; ++i) {
      if (mask_[std::size_t(i)]) u.lens[std::size_t(i)] = *x++;
    }
    for (Pose& pose : u.poses) {
      for (int i = 0; i < 3; ++i) pose.rotation[i] = *x++;
      for (int i = 0; i < 3; ++i) pose.translationMm[i] = *x++;
    }
  }

 private:
  LensMask mask_;
};

struct Observations {
  std::vector<glm::dvec3> boardMm;
  std::span<const std::vector<glm::dvec2>> corners;
  [[nodiscard]] int residualCount() const { return int(2 * boardMm.size() * corners.size()); }
};

// Residuals of every view for the unknowns (the lens unbounded in theta during the fit).
void allResiduals(const Observations& obs, const Unknowns& u, double* out) {
  const KannalaBrandtLens lens = lensOf(u.lens, std::numbers::pi);
  const std::size_t perView = 2 * obs.boardMm.size();
  for (std::size_t v = 0; v < u.poses.size(); ++v) {
    viewResiduals(lens, u.poses[v], obs.boardMm, obs.corners[v], out + v * perView);
  }
}

// Residuals and their Jacobian by central differences; a pose's columns touch its view's rows only.
class Residuals : public cv::LMSolver::Callback {
 public:
  Residuals(const Observations& obs, const Packing& packing, const Unknowns& fixed)
      : obs_(obs), packing_(packing), fixed_(fixed) {}

  bool compute(cv::InputArray param, cv::OutputArray err, cv::OutputArray jacobian) const override {
    const cv::Mat x = param.getMat();
    Unknowns u = fixed_;
    packing_.unpack(x.ptr<double>(), u);
    err.create(obs_.residualCount(), 1, CV_64F);
    allResiduals(obs_, u, err.getMat().ptr<double>());
    if (jacobian.needed()) {
      jacobian.create(obs_.residualCount(), x.rows, CV_64F);
      cv::Mat j = jacobian.getMat();
      j.setTo(0.0);
      fillJacobian(x, j);
    }
    return true;
  }

 private:
  void fillJacobian(const cv::Mat& x, cv::Mat& j) const {
    const int lensCount = packing_.freeLensCount();
    const int perView = int(2 * obs_.boardMm.size());
    std::vector<double> plus(std::size_t(obs_.residualCount())), minus(plus.size());
    for (int c = 0; c < x.rows; ++c) {
      const bool lensColumn = c < lensCount;
      const int view = lensColumn ? -1 : (c - lensCount) / kPoseParams;
      const double h = 1e-6 * std::max(1.0, std::abs(x.at<double>(c)));
      cv::Mat xp = x.clone(), xm = x.clone();
      xp.at<double>(c) += h;
      xm.at<double>(c) -= h;
      evaluate(xp, view, plus.data());
      evaluate(xm, view, minus.data());
      const int first = lensColumn ? 0 : view * perView;
      const int last = lensColumn ? obs_.residualCount() : first + perView;
      for (int r = first; r < last; ++r) {
        j.at<double>(r, c) = (plus[std::size_t(r)] - minus[std::size_t(r)]) / (2.0 * h);
      }
    }
  }

  // All residuals (view < 0) or one view's, at their places in `out`.
  void evaluate(const cv::Mat& x, int view, double* out) const {
    Unknowns u = fixed_;
    packing_.unpack(x.ptr<double>(), u);
    if (view < 0) return allResiduals(obs_, u, out);
    const std::size_t perView = 2 * obs_.boardMm.size();
    viewResiduals(lensOf(u.lens, std::numbers::pi), u.poses[std::size_t(view)], obs_.boardMm,
                  obs_.corners[std::size_t(view)], out + std::size_t(view) * perView);
  }

  const Observations& obs_;
  const Packing& packing_;
  Unknowns fixed_;
};

// Levenberg-Marquardt over the parameters `mask` frees (and every pose); false if it did not
// settle.
bool adjust(const Observations& obs, const LensMask& mask, Unknowns& u) {
  const Packing packing(mask);
  cv::Mat x = packing.pack(u);
  const cv::Ptr<cv::LMSolver> solver =
      cv::LMSolver::create(cv::makePtr<Residuals>(obs, packing, u), kMaxIterations, kStepTolerance);
  const int iterations = solver->run(x);
  packing.unpack(x.ptr<double>(), u);
  return iterations > 0 && iterations < kMaxIterations && cv::checkRange(x);
}

// The ray of a sensor point through an equidistant lens, not limited to its image circle.
glm::dvec3 equidistantRay(const LensValues& lens, const glm::dvec2& p) {
  const glm::dvec2 d(p.x - lens[5], (p.y - lens[6]) / lens[7]);
  const double r = std::hypot(d.x, d.y);
  if (r == 0.0) return {0.0, 0.0, 1.0};
  const double theta = std::min(r / lens[0], std::numbers::pi);
  return {std::sin(theta) * d.x / r, std::sin(theta) * d.y / r, std::cos(theta)};
}

// The view's pose from its corners' rays: turned to a frame around their mean ray, the rays become
// an ordinary pinhole view of the plane, solved by IPPE, then turned back.
std::optional<Pose> initialPose(const LensValues& lens, std::span<const glm::dvec3> boardMm,
                                std::span<const glm::dvec2> corners) {
  std::vector<glm::dvec3> rays;
  glm::dvec3 mean(0.0);
  for (const glm::dvec2& c : corners) mean += rays.emplace_back(equidistantRay(lens, c));
  const glm::dmat3 cameraFromLocal = frameAround(glm::normalize(mean));
  const glm::dmat3 localFromCamera = glm::transpose(cameraFromLocal);
  std::vector<cv::Point2d> image;
  std::vector<cv::Point3d> object;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const glm::dvec3 q = localFromCamera * rays[i];
    if (q.z < 0.05) return std::nullopt;  // the corners span nearly 180 degrees: no planar view
    image.emplace_back(q.x / q.z, q.y / q.z);
    object.emplace_back(boardMm[i].x, boardMm[i].y, boardMm[i].z);
  }
  cv::Vec3d rotationLocal, translationLocal;
  if (!cv::solvePnP(object, image, cv::Matx33d::eye(), cv::noArray(), rotationLocal,
                    translationLocal, false, cv::SOLVEPNP_IPPE)) {
    return std::nullopt;
  }
  cv::Matx33d localFromBoard;
  cv::Rodrigues(rotationLocal, localFromBoard);
  const cv::Matx33d toCamera = cvFrom(cameraFromLocal);
  Pose pose;
  cv::Rodrigues(toCamera * localFromBoard, pose.rotation);
  pose.translationMm = toCamera * translationLocal;
  return pose;
}

FisheyeFitFailure failure(FisheyeRefusal cause, std::string message, int view = -1) {
  return {cause, std::move(message), view};
}

double rms(std::span<const double> residuals) {
  double sum = 0.0;
  for (double r : residuals) sum += r * r;
  return std::sqrt(2.0 * sum / double(residuals.size()));  // per corner: two residuals each
}

// The start: an equidistant lens whose image circle is `circleScale` times the sensor's shorter
// side over the field of view, and each view's pose through it.
std::expected<Unknowns, FisheyeFitFailure> startingPoint(const Observations& obs, int widthPx,
                                                         int heightPx, double fovDeg,
                                                         double circleScale) {
  const KannalaBrandtLens guess =
      equidistantLens(widthPx, heightPx, fovDeg, 0.5 * circleScale * std::min(widthPx, heightPx));
  Unknowns u{valuesOf(guess), {}};
  for (std::size_t v = 0; v < obs.corners.size(); ++v) {
    const std::optional<Pose> pose = initialPose(u.lens, obs.boardMm, obs.corners[v]);
    if (!pose) {
      return std::unexpected(failure(FisheyeRefusal::NotConverged,
                                     fmt::format("view {}: no starting pose fits its corners", v),
                                     int(v)));
    }
    u.poses.push_back(*pose);
  }
  return u;
}

// The fitted lens and its errors, or the refusal its errors call for.
std::expected<FisheyeFit, FisheyeFitFailure> judge(const Observations& obs, const Unknowns& u,
                                                   const FisheyeFitOptions& options) {
  FisheyeFit fit;
  fit.lens = lensOf(u.lens, maxThetaRad(options));
  if (const std::optional<const char*> defect = lensDefect(fit.lens)) {
    return std::unexpected(failure(
        FisheyeRefusal::LensFolds,
        fmt::format("the fitted lens is unusable up to max_theta = {:g} degrees (half the field "
                    "of view): {}; views whose boards reach nearer the image circle's edge, or "
                    "the right field of view, would help",
                    0.5 * options.fovDeg, *defect)));
  }
  std::vector<double> residuals(std::size_t(obs.residualCount()));
  allResiduals(obs, u, residuals.data());
  const std::size_t perView = 2 * obs.boardMm.size();
  for (std::size_t v = 0; v < u.poses.size(); ++v) {
    fit.viewRmsPx.push_back(rms(std::span(residuals).subspan(v * perView, perView)));
    fit.poses.push_back(boardPoseOf(u.poses[v]));
  }
  fit.quality = {rms(residuals), int(u.poses.size()), int(residuals.size() / 2), ""};
  const auto worst = std::max_element(fit.viewRmsPx.begin(), fit.viewRmsPx.end());
  if (fit.quality.rmsReprojectionPx > options.maxRmsPx || *worst > options.maxRmsPx) {
    const int view = int(worst - fit.viewRmsPx.begin());
    return std::unexpected(failure(
        FisheyeRefusal::ErrorTooHigh,
        fmt::format("the reprojection error is too high: view {} has an RMS of {:.3f} px (overall "
                    "{:.3f} px), above the limit of {} px",
                    view, *worst, fit.quality.rmsReprojectionPx, options.maxRmsPx),
        view));
  }
  return fit;
}

FisheyeFitFailure notConverged() {
  return failure(FisheyeRefusal::NotConverged,
                 fmt::format("the lens fit did not converge within {} iterations from any start "
                             "(check the field of view and the board's size)",
                             kMaxIterations));
}

// Too few views, or a view without the board's number of corners.
std::optional<FisheyeFitFailure> badInput(std::span<const std::vector<glm::dvec2>> cornersPerView,
                                          const Checkerboard& board,
                                          const FisheyeFitOptions& options) {
  if (int(cornersPerView.size()) < std::max(options.minViews, 1)) {
    return failure(FisheyeRefusal::TooFewViews,
                   fmt::format("{} views with a board were given; the fit needs at least {}",
                               cornersPerView.size(), options.minViews));
  }
  const std::size_t expected = std::size_t(board.innerCols * board.innerRows);
  for (std::size_t v = 0; v < cornersPerView.size(); ++v) {
    if (cornersPerView[v].size() != expected) {
      return failure(
          FisheyeRefusal::BoardNotFound,
          fmt::format("view {} has {} corners; the {}x{} board has {}", v, cornersPerView[v].size(),
                      board.innerCols, board.innerRows, expected),
          int(v));
    }
  }
  return std::nullopt;
}

double rmsOf(const Observations& obs, const Unknowns& u) {
  std::vector<double> residuals(std::size_t(obs.residualCount()));
  allResiduals(obs, u, residuals.data());
  return rms(residuals);
}

// From a start: k1 and the principal point with the poses, then the whole lens.
std::expected<Unknowns, FisheyeFitFailure> solveFrom(const Observations& obs, int widthPx,
                                                     int heightPx, double fovDeg,
                                                     double circleScale) {
  std::expected<Unknowns, FisheyeFitFailure> u =
      startingPoint(obs, widthPx, heightPx, fovDeg, circleScale);
  if (u && (!adjust(obs, kScaleAndCentre, *u) || !adjust(obs, kWholeLens, *u))) {
    return std::unexpected(notConverged());
  }
  return u;
}

// The image circle is guessed to fill the sensor's shorter side; when the fit from there does not
// converge, or converges to a wrong minimum (an RMS of pixels), circles 1.6 times larger (cropped
// by the sensor) and smaller are tried, and the best fit kept.
std::expected<Unknowns, FisheyeFitFailure> solve(const Observations& obs, int widthPx, int heightPx,
                                                 double fovDeg) {
  std::optional<Unknowns> best;
  double bestRms = INFINITY;
  std::optional<FisheyeFitFailure> firstFailure;
  for (double circleScale : {1.0, 1.6, 0.625}) {
    std::expected<Unknowns, FisheyeFitFailure> u =
        solveFrom(obs, widthPx, heightPx, fovDeg, circleScale);
    if (!u) {
      if (!firstFailure) firstFailure = std::move(u.error());
      continue;
    }
    if (const double rmsPx = rmsOf(obs, *u); rmsPx < bestRms) {
      bestRms = rmsPx;
      best = std::move(*u);
    }
    if (bestRms <= kRightBasinRmsPx) break;
  }
  if (best) return std::move(*best);
  return std::unexpected(std::move(*firstFailure));
}

}  // namespace

std::expected<FisheyeFit, FisheyeFitFailure> fitFisheye(
    std::span<const std::vector<glm::dvec2>> cornersPerView, const Checkerboard& board, int widthPx,
    int heightPx, const FisheyeFitOptions& options) {
  VEM_EXPECTS(options.fovDeg > 0.0 && options.fovDeg <= 360.0);
  if (std::optional<FisheyeFitFailure> bad = badInput(cornersPerView, board, options)) {
    return std::unexpected(std::move(*bad));
  }
  const Observations obs{boardCornersMm(board), cornersPerView};
  std::expected<Unknowns, FisheyeFitFailure> u = solve(obs, widthPx, heightPx, options.fovDeg);
  if (!u) return std::unexpected(std::move(u.error()));
  return judge(obs, *u, options);
}

std::expected<FisheyeFit, FisheyeFitFailure> fitFisheyeRefined(
    std::span<const RawFrame> frames, std::span<const std::vector<glm::dvec2>> detectedCorners,
    const Checkerboard& board, const FisheyeFitOptions& options) {
  VEM_EXPECTS(frames.size() == detectedCorners.size());
  VEM_EXPECTS(options.fovDeg > 0.0 && options.fovDeg <= 360.0);
  if (std::optional<FisheyeFitFailure> bad = badInput(detectedCorners, board, options)) {
    return std::unexpected(std::move(*bad));
  }
  std::vector<std::vector<glm::dvec2>> corners(detectedCorners.begin(), detectedCorners.end());
  const Observations obs{boardCornersMm(board), corners};
  std::expected<Unknowns, FisheyeFitFailure> u =
      solve(obs, frames.front().width, frames.front().height, options.fovDeg);
  if (!u) return std::unexpected(std::move(u.error()));
  for (int round = 0; round < kRefinementRounds; ++round) {
    const KannalaBrandtLens lens = lensOf(u->lens, maxThetaRad(options));
    for (std::size_t v = 0; v < corners.size(); ++v) {
      corners[v] = refineCorners(frames[v], board, lens, boardPoseOf(u->poses[v]), corners[v]);
    }
    if (!adjust(obs, kWholeLens, *u)) return std::unexpected(notConverged());
  }
  return judge(obs, *u, options);
}

std::expected<FisheyeFit, FisheyeFitFailure> calibrateFisheye(std::span<const RawFrame> frames,
                                                              const Checkerboard& board,
                                                              const FisheyeFitOptions& options) {
  std::vector<std::vector<glm::dvec2>> corners;
  for (std::size_t v = 0; v < frames.size(); ++v) {
    std::optional<std::vector<glm::dvec2>> found = detectCheckerboard(frames[v], board);
    if (!found) {
      return std::unexpected(failure(FisheyeRefusal::BoardNotFound,
                                     fmt::format("view {}: no {}x{} checkerboard was found", v,
                                                 board.innerCols, board.innerRows),
                                     int(v)));
    }
    corners.push_back(std::move(*found));
  }
  return fitFisheyeRefined(frames, corners, board, options);
}

}  // namespace vem::calib
