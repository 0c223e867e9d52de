#include "calib/core/plate_intrinsics_fit.h"

#include <cmath>
#include <string>

#include <fmt/format.h>
#include <opencv2/calib3d.hpp>

#include "util/contract.h"

namespace vem::calib {
namespace {

struct OpenCvViews {
  std::vector<std::vector<cv::Point3d>> objectMm;
  std::vector<std::vector<cv::Point2d>> imagePx;
};

OpenCvViews openCvViews(std::span<const std::vector<glm::dvec2>> cornersPerView,
                        const Checkerboard& board) {
  OpenCvViews views;
  std::vector<cv::Point3d> object;
  for (const glm::dvec3& p : boardCornersMm(board)) object.emplace_back(p.x, p.y, p.z);
  for (const std::vector<glm::dvec2>& corners : cornersPerView) {
    views.objectMm.push_back(object);
    std::vector<cv::Point2d> image;
    for (const glm::dvec2& c : corners) image.emplace_back(c.x, c.y);
    views.imagePx.push_back(std::move(image));
  }
  return views;
}

// calibrateCamera reads float points only.
template <typename Out, typename In>
std::vector<std::vector<Out>> asFloat(const std::vector<std::vector<In>>& views) {
  std::vector<std::vector<Out>> out;
  for (const auto& view : views) out.emplace_back(view.begin(), view.end());
  return out;
}

BoardPose boardPoseFrom(const cv::Vec3d& rvec, const cv::Vec3d& tvec) {
  cv::Matx33d r;
  cv::Rodrigues(rvec, r);
  BoardPose pose;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) pose.cameraFromBoard[col][row] = r(row, col);
  pose.boardOriginCameraMm = {tvec[0], tvec[1], tvec[2]};
  return pose;
}

struct OpenCvFit {
  cv::Matx33d k;
  std::vector<double> distortion;
  std::vector<cv::Vec3d> rvecs, tvecs;
};

// The OpenCV fit itself; throws cv::Exception when it cannot proceed.
OpenCvFit runOpenCv(const OpenCvViews& views, cv::Size size, PlateLensModel model) {
  OpenCvFit fit;
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 200, 1e-12);
  if (model == PlateLensModel::KannalaBrandt) {
    cv::Vec4d d;
    const int flags = cv::fisheye::CALIB_RECOMPUTE_EXTRINSIC | cv::fisheye::CALIB_FIX_SKEW;
    cv::fisheye::calibrate(views.objectMm, views.imagePx, size, fit.k, d, fit.rvecs, fit.tvecs,
                           flags, criteria);
    fit.distortion = {d[0], d[1], d[2], d[3], 0.0};
  } else {
    cv::Mat d;
    cv::calibrateCamera(asFloat<cv::Point3f>(views.objectMm), asFloat<cv::Point2f>(views.imagePx),
                        size, fit.k, d, fit.rvecs, fit.tvecs, 0, criteria);
    fit.distortion.assign(d.begin<double>(), d.end<double>());
    fit.distortion.resize(5, 0.0);
  }
  return fit;
}

PlateIntrinsics intrinsicsFrom(const OpenCvFit& fit, int widthPx, int heightPx,
                               PlateLensModel model) {
  PlateIntrinsics in;
  in.widthPx = widthPx;
  in.heightPx = heightPx;
  in.fxPx = fit.k(0, 0);
  in.fyPx = fit.k(1, 1);
  in.cxPx = fit.k(0, 2);
  in.cyPx = fit.k(1, 2);
  in.model = model;
  for (std::size_t i = 0; i < in.distortion.size(); ++i) in.distortion[i] = fit.distortion[i];
  return in;
}

std::optional<PlateFitFailure> checkInputs(std::span<const std::vector<glm::dvec2>> cornersPerView,
                                           const Checkerboard& board,
                                           const PlateIntrinsicsFitOptions& options) {
  if (int(cornersPerView.size()) < options.minViews)
    return PlateFitFailure{PlateFitRefusal::TooFewViews,
                           fmt::format("{} view(s) of the board; the fit needs at least {}",
                                       cornersPerView.size(), options.minViews)};
  const std::size_t expected = std::size_t(board.innerCols * board.innerRows);
  for (std::size_t v = 0; v < cornersPerView.size(); ++v)
    if (cornersPerView[v].size() != expected)
      return PlateFitFailure{
          PlateFitRefusal::WrongCornerCount,
          fmt::format("{} corners were found where the {}x{} board has {}",
                      cornersPerView[v].size(), board.innerCols, board.innerRows, expected),
          int(v)};
  return std::nullopt;
}

}  // namespace

double boardReprojectionRmsPx(std::span<const glm::dvec2> corners, const Checkerboard& board,
                              const PlateIntrinsics& intrinsics, const BoardPose& pose) {
  const std::vector<glm::dvec3> boardMm = boardCornersMm(board);
  VEM_EXPECTS(corners.size() == boardMm.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const std::optional<glm::dvec2> p =
        plateFromCamera(intrinsics, cameraFromBoardMm(pose, boardMm[i]));
    if (!p) return INFINITY;
    const glm::dvec2 d = *p - corners[i];
    sum += d.x * d.x + d.y * d.y;
  }
  return std::sqrt(sum / double(corners.size()));
}

std::expected<PlateIntrinsicsFit, PlateFitFailure> fitPlateIntrinsics(
    std::span<const std::vector<glm::dvec2>> cornersPerView, const Checkerboard& board, int widthPx,
    int heightPx, const PlateIntrinsicsFitOptions& options) {
  VEM_EXPECTS(widthPx > 0 && heightPx > 0 && options.minViews >= 1);
  if (auto failure = checkInputs(cornersPerView, board, options)) return std::unexpected(*failure);
  OpenCvFit cvFit;
  try {
    cvFit = runOpenCv(openCvViews(cornersPerView, board), {widthPx, heightPx}, options.model);
  } catch (const cv::Exception& e) {
    return std::unexpected(PlateFitFailure{
        PlateFitRefusal::NotConverged,
        fmt::format("OpenCV's fit did not converge ({}); give views with the board tilted "
                    "differently and covering the image",
                    e.err)});
  }
  PlateIntrinsicsFit fit;
  fit.intrinsics = intrinsicsFrom(cvFit, widthPx, heightPx, options.model);
  if (intrinsicsDefect(fit.intrinsics))
    return std::unexpected(PlateFitFailure{
        PlateFitRefusal::NotConverged,
        "OpenCV's fit gave unusable intrinsics; give views with the board tilted differently"});
  double sum = 0.0;
  for (std::size_t v = 0; v < cornersPerView.size(); ++v) {
    fit.poses.push_back(boardPoseFrom(cvFit.rvecs[v], cvFit.tvecs[v]));
    fit.viewRmsPx.push_back(
        boardReprojectionRmsPx(cornersPerView[v], board, fit.intrinsics, fit.poses.back()));
    sum += fit.viewRmsPx.back() * fit.viewRmsPx.back();
  }
  fit.quality.views = int(cornersPerView.size());
  fit.quality.corners = fit.quality.views * board.innerCols * board.innerRows;
  fit.quality.rmsReprojectionPx = std::sqrt(sum / double(cornersPerView.size()));
  for (std::size_t v = 0; v < fit.viewRmsPx.size(); ++v)
    if (!(fit.viewRmsPx[v] <= options.maxRmsPx))
      return std::unexpected(PlateFitFailure{
          PlateFitRefusal::ErrorTooHigh,
          fmt::format("the view's RMS reprojection error is {:.3f} px, above the limit of {:g} px "
                      "(overall {:.3f} px)",
                      fit.viewRmsPx[v], options.maxRmsPx, fit.quality.rmsReprojectionPx),
          int(v)});
  return fit;
}

}  // namespace vem::calib
