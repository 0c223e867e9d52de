// The scene ("plate") camera of mixed reality: the second camera that films the real scene into
// which vemcast's synthetic objects are composited (issue 21). Its intrinsics (OpenCV's pinhole
// camera with Brown-Conrady distortion, or OpenCV's cv::fisheye, i.e. Kannala-Brandt), its pose in
// the world of the light probe, the light probe's yaw in that world and its colour match with the
// probe. The fits are plate_intrinsics_fit.h, plate_pose_fit.h, plate_probe_yaw.h and
// plate_colour_fit.h; the file is calib/io/plate_camera_file.h; docs/calibration.md, "Plate
// camera", describes the procedure.
//
// Conventions and units:
// - Pixels: OpenCV's, pixel centres at integer coordinates (as raw_frame.h), +x right, +y down.
// - Camera frame: OpenCV's: +X right, +Y down, +Z forward (out of the lens), metres.
// - World frame: vemcast's (docs/conventions.md): right-handed, +Y up, metres, fixed by the board
//   lying printed side up on the floor: world X = board X, world Z = board Y, world Y = -board Z
//   (the board's +Z points into the board, checkerboard.h), origin at the board's first inner
//   corner. The floor is y = 0 and the camera, above it, has positionWorldM.y > 0 (plate_pose_fit.h
//   turns the board frame when the corners come in mirrored order).
// - Distortion, OpenCV's formulas on the normalised coordinates (x, y) = (X / Z, Y / Z):
//   BrownConrady (cv::calibrateCamera): r^2 = x^2 + y^2,
//     x_d = x (1 + k1 r^2 + k2 r^4 + k3 r^6) + 2 p1 x y + p2 (r^2 + 2 x^2),
//     y_d = y (1 + k1 r^2 + k2 r^4 + k3 r^6) + p1 (r^2 + 2 y^2) + 2 p2 x y;
//   KannalaBrandt (cv::fisheye): theta = atan(r), theta_d = theta (1 + k1 theta^2 + k2 theta^4 +
//     k3 theta^6 + k4 theta^8), (x_d, y_d) = (theta_d / r) (x, y);
//   then u = fx x_d + cx, v = fy y_d + cy. The "ideal" pixel of a point is its pixel without
//   distortion: (fx x + cx, fy y + cy).
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "calib/core/camera_calibration.h"

namespace vem::calib {

// OpenCV's pinhole with k1, k2, p1, p2, k3 ; OpenCV's cv::fisheye k1..k4.
enum class PlateLensModel { BrownConrady, KannalaBrandt };

struct PlateIntrinsics {
  int widthPx = 0, heightPx = 0;
  double fxPx = 0, fyPx = 0, cxPx = 0, cyPx = 0;  // OpenCV's camera matrix
  PlateLensModel model = PlateLensModel::BrownConrady;
  std::array<double, 5> distortion{};  // BrownConrady: k1,k2,p1,p2,k3 ; KannalaBrandt: k1..k4, 0
};

// p_camera = cameraFromWorld * (p_world - positionWorldM).
struct PlatePose {
  glm::dmat3 cameraFromWorld{1.0};  // a rotation
  glm::dvec3 positionWorldM{0.0};   // the camera's centre in the world
};

// plate linear value = gainRgb * probe radiance (the probe's units, cd/m2 per channel).
struct PlateColourMatch {
  std::array<double, 3> gainRgb{1.0, 1.0, 1.0};
  double rmsResidualPercent = 0;
  int patches = 0;
  std::string date;
};

struct PlateCamera {
  CameraIdentity camera;  // model, serial, sensor size (== intrinsics size), pixel format
  PlateIntrinsics intrinsics;
  GeometricQuality intrinsicsQuality;
  std::optional<PlatePose> pose;
  GeometricQuality poseQuality;  // rmsReprojectionPx of the floor board
  // The light probe's world turned about +Y into the plate's world:
  // dir_plateWorld = RotY(probeYawRad) * dir_probeWorld (RotY as glm::rotate about +Y,
  // right-handed). In vemcast's azimuth (phi from +X toward +Z) this is
  // phi_plateWorld = phi_probeWorld - probeYawRad.
  double probeYawRad = 0.0;
  std::string probeYawDate;  // when the yaw was measured (ISO 8601, UTC); empty: never, yaw 0
  std::optional<PlateColourMatch> colour;
};

// "brown-conrady" or "kannala-brandt" (the file's names), and back.
[[nodiscard]] const char* plateLensModelName(PlateLensModel model);
[[nodiscard]] std::optional<PlateLensModel> parsePlateLensModel(std::string_view name);
// The distortion coefficients the model uses: 5 (BrownConrady) or 4 (KannalaBrandt).
[[nodiscard]] int distortionCount(PlateLensModel model);

// The camera-frame point of a world point (metres).
[[nodiscard]] glm::dvec3 cameraFromWorldM(const PlatePose& pose, const glm::dvec3& pointWorldM);

// The distorted pixel of a camera-frame point or direction; nullopt when it is not in front of
// the camera (Z <= 0).
[[nodiscard]] std::optional<glm::dvec2> plateFromCamera(const PlateIntrinsics& intrinsics,
                                                        const glm::dvec3& pointCamera);
// The distorted pixel of a world point (metres); nullopt behind the camera.
[[nodiscard]] std::optional<glm::dvec2> plateFromWorld(const PlateIntrinsics& intrinsics,
                                                       const PlatePose& pose,
                                                       const glm::dvec3& pointWorldM);
// The distorted pixel of a world direction (a point infinitely far away); nullopt behind.
[[nodiscard]] std::optional<glm::dvec2> plateFromWorldDirection(const PlateIntrinsics& intrinsics,
                                                                const PlatePose& pose,
                                                                const glm::dvec3& dirWorld);

// The distorted pixel of an ideal (undistorted) pixel: the lens's distortion applied.
[[nodiscard]] glm::dvec2 distortedFromIdealPx(const PlateIntrinsics& intrinsics,
                                              const glm::dvec2& idealPx);
// The ideal pixel of a distorted pixel: OpenCV's undistortPoints (cv::fisheye::undistortPoints for
// KannalaBrandt) with P = the camera matrix, iterated to 1e-10 px.
[[nodiscard]] glm::dvec2 idealFromDistortedPx(const PlateIntrinsics& intrinsics,
                                              const glm::dvec2& distortedPx);
[[nodiscard]] std::vector<glm::dvec2> idealFromDistortedPx(const PlateIntrinsics& intrinsics,
                                                           std::span<const glm::dvec2> distortedPx);

// The unit camera-frame direction a distorted pixel sees.
[[nodiscard]] glm::dvec3 cameraDirectionFromPlate(const PlateIntrinsics& intrinsics,
                                                  const glm::dvec2& distortedPx);
// The unit world direction a distorted pixel sees (from the camera's centre outward).
[[nodiscard]] glm::dvec3 worldDirectionFromPlate(const PlateIntrinsics& intrinsics,
                                                 const PlatePose& pose,
                                                 const glm::dvec2& distortedPx);

// The world frame's rotation from the floor board's (mm or m alike): world X = board X,
// world Y = -board Z, world Z = board Y.
[[nodiscard]] glm::dmat3 worldFromBoard();

// The pose of a camera at positionWorldM looking at targetWorldM, level: the image's +x stays
// horizontal and the world's +Y points up the image. The target must not lie straight above or
// below the camera.
[[nodiscard]] PlatePose plateLookingAt(const glm::dvec3& positionWorldM,
                                       const glm::dvec3& targetWorldM);

// Why the intrinsics cannot be used (non-finite values, fx or fy not above 0, an empty sensor);
// nullopt when they are fine.
[[nodiscard]] std::optional<const char*> intrinsicsDefect(const PlateIntrinsics& intrinsics);

}  // namespace vem::calib
