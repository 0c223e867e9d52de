// The printed checkerboard as a camera sees it (checkerboard.h): the luminance along a camera-frame
// ray that meets the board, for the simulated views of the light-probe camera (checkerboard.cpp)
// and of the plate camera (plate_board_simulation.h). The printed pattern, its white margin one
// square wide, a grey background sqrt(white * black) around it, and the board's grey back.
//
// Conventions: camera frame and board frame (mm) of checkerboard.h; rays of any length > 0.
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "calib/core/checkerboard.h"

namespace vem::calib {

class BoardShader {
 public:
  BoardShader(const Checkerboard& board, const BoardPose& pose, double whiteCdM2, double blackCdM2)
      : board_(board),
        boardFromCamera_(glm::transpose(pose.cameraFromBoard)),
        normalCamera_(pose.cameraFromBoard[2]),
        originCameraMm_(pose.boardOriginCameraMm),
        whiteCdM2_(whiteCdM2),
        blackCdM2_(blackCdM2),
        greyCdM2_(std::sqrt(whiteCdM2 * blackCdM2)),
        printedSideVisible_(glm::dot(normalCamera_, originCameraMm_) > 0.0) {}

  [[nodiscard]] double luminance(const glm::dvec3& rayCamera) const {
    if (!printedSideVisible_) return greyCdM2_;
    const double distance =
        glm::dot(normalCamera_, originCameraMm_) / glm::dot(normalCamera_, rayCamera);
    if (!(distance > 0.0) || !std::isfinite(distance)) return greyCdM2_;
    const glm::dvec3 boardMm = boardFromCamera_ * (distance * rayCamera - originCameraMm_);
    return pattern(boardMm.x / board_.squareMm, boardMm.y / board_.squareMm);
  }

 private:
  // (x, y) in squares from the first inner corner.
  [[nodiscard]] double pattern(double x, double y) const {
    const double cols = board_.innerCols;
    const double rows = board_.innerRows;
    if (x < -2.0 || x > cols + 1.0 || y < -2.0 || y > rows + 1.0) return greyCdM2_;
    if (x < -1.0 || x >= cols || y < -1.0 || y >= rows) return whiteCdM2_;
    const long parity = (long(std::floor(x)) + long(std::floor(y))) % 2;
    return parity == 0 ? blackCdM2_ : whiteCdM2_;
  }

  Checkerboard board_;
  glm::dmat3 boardFromCamera_;
  glm::dvec3 normalCamera_;  // board +Z
  glm::dvec3 originCameraMm_;
  double whiteCdM2_;
  double blackCdM2_;
  double greyCdM2_;
  bool printedSideVisible_;
};

}  // namespace vem::calib
