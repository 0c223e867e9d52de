// The plate camera's views of a checkerboard (checkerboard.h), for tests and `vemcalib simulate
// plate`: boards held in front of the camera for the intrinsics (plate_intrinsics_fit.h) and the
// board lying on the floor for the pose (plate_pose_fit.h), rendered through the truth's
// intrinsics (distortion included) as frames detectCheckerboard reads.
//
// Conventions and units: board poses in the camera frame of plate_camera.h (OpenCV's, which is
// also checkerboard.h's), in mm. A pixel averages options.supersamples^2 rays over its area; each
// ray reads the board's pattern (board_shader.h) in codes: whiteCode on white, blackCode on black,
// sqrt(white * black) on the background. Codes go through a linear sensor (code = value, clipped
// at the format's largest code) with options.noise's Gaussian read noise, deterministic in its
// seed (camera_simulator.h's SensorResponseSimulator).
#pragma once

#include <cstdint>
#include <vector>

#include "calib/core/camera_simulator.h"
#include "calib/core/checkerboard.h"
#include "calib/core/plate_camera.h"
#include "frames/raw_frame.h"

namespace vem::calib {

// The frame the truth camera takes of the board at `pose`; size and format from truth.camera.
[[nodiscard]] RawFrame simulatePlateBoardView(const Checkerboard& board, const BoardPose& pose,
                                              const PlateCamera& truth,
                                              const SimulationOptions& options, double whiteCode,
                                              double blackCode);

// `count` poses of the board in front of the camera for the intrinsics: view 0 faces the camera
// at the image's centre, later views move outward at golden-angle azimuths to 70 % of the way to
// the image's edges, tilted 20 to 45 degrees about a random axis in the board's plane and turned
// up to 15 degrees in it, the board spanning about 45 % of the image's width. Every board, its
// white margin included, lies inside the image with 2 pixels to spare, shows its printed side and
// keeps neighbouring corners 8 pixels apart. Deterministic in `seed`.
[[nodiscard]] std::vector<BoardPose> plateBoardPoses(const Checkerboard& board,
                                                     const PlateIntrinsics& intrinsics, int count,
                                                     std::uint64_t seed);

// Whether the whole board at `pose`, margin included, lies inside the image with 2 pixels to
// spare, printed side toward the camera, no corner seen more than maxObliquityDeg off the board's
// normal (a board on the floor is seen at a grazing angle from afar), neighbouring corners 8
// pixels apart or more.
[[nodiscard]] bool plateSeesWholeBoard(const Checkerboard& board, const BoardPose& pose,
                                       const PlateIntrinsics& intrinsics,
                                       double maxObliquityDeg = 60.0);

}  // namespace vem::calib
