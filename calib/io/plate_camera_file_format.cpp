// Writing plate-camera files: formatPlateCameraFile (plate_camera_file.h), field by field in the
// documented order, each with a short note for the reader of the file.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "calib/io/calibration_fields.h"
#include "calib/io/camera_file_fields.h"
#include "calib/io/plate_camera_file.h"
#include "calib/io/plate_camera_file_fields.h"
#include "calib/io/toml_writer.h"
#include "util/contract.h"

namespace vem::calib::io {
namespace {

using detail::TomlWriter;

void writeIntrinsics(TomlWriter& w, const PlateIntrinsics& in, const GeometricQuality& quality) {
  const bool brown = in.model == PlateLensModel::BrownConrady;
  w.table("intrinsics");
  w.string("model", plateLensModelName(in.model),
           brown ? "OpenCV's pinhole with radial and tangential distortion (cv::calibrateCamera)"
                 : "OpenCV's fisheye (cv::fisheye)");
  const std::array<double, 2> focal{in.fxPx, in.fyPx};
  w.quantity("focal_length", focal, detail::kUnitPx, "fx, fy");
  const std::array<double, 2> centre{in.cxPx, in.cyPx};
  w.quantity("principal_point", centre, detail::kUnitPx,
             "cx (column), cy (row); pixel centres at integers");
  w.quantity("distortion",
             std::span<const double>(in.distortion).first(std::size_t(distortionCount(in.model))),
             detail::kUnitOne, brown ? "k1, k2, p1, p2, k3" : "k1, k2, k3, k4");
  detail::writeGeometricQuality(w, "intrinsics.fit", quality);
}

void writePose(TomlWriter& w, const PlatePose& pose, const GeometricQuality& quality) {
  w.table("pose");
  std::array<std::array<double, 3>, 3> rows{};
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col)
      rows[std::size_t(row)][std::size_t(col)] = pose.cameraFromWorld[col][row];
  w.quantityRows("camera_from_world", {rows[0], rows[1], rows[2]}, detail::kUnitOne,
                 "rows; p_camera = camera_from_world (p_world - position)");
  const std::array<double, 3> position{pose.positionWorldM.x, pose.positionWorldM.y,
                                       pose.positionWorldM.z};
  w.quantity("position", position, detail::kUnitMetre,
             "the camera's centre in the world (+Y up, floor at y = 0)");
  detail::writeGeometricQuality(w, "pose.fit", quality);
}

void writeProbe(TomlWriter& w, const PlateCamera& plate) {
  w.table("probe");
  detail::writeAngle(w, "yaw", plate.probeYawRad,
                     "dir_plate_world = RotY(yaw) dir_probe_world, about +Y, right-handed");
  w.string("date", plate.probeYawDate, "UTC");
}

void writeColour(TomlWriter& w, const PlateColourMatch& colour) {
  w.table("colour");
  w.quantity("gain", colour.gainRgb, detail::kUnitColourGain,
             "R, G, B: plate linear value = gain x probe radiance");
  w.quantity("rms_residual", colour.rmsResidualPercent, detail::kUnitPercent, "over the patches");
  w.integer("patches", colour.patches);
  w.string("date", colour.date, "UTC");
}

}  // namespace

std::string formatPlateCameraFile(const PlateCamera& plate) {
  VEM_EXPECTS(plate.intrinsics.widthPx == plate.camera.sensorWidthPx &&
              plate.intrinsics.heightPx == plate.camera.sensorHeightPx);
  TomlWriter w;
  w.comment("vemcast plate camera calibration, written by vemcalib plate (docs/calibration.md).");
  w.comment("Every quantity is { value = ..., unit = \"...\" }. Camera frame: OpenCV's (+X right,");
  w.comment(
      "+Y down, +Z forward); world: +Y up, metres, origin at the floor board's first corner.");
  w.string("format", detail::kPlateCameraFormatName);
  w.integer("version", kPlateCameraFileVersion);
  detail::writeCameraIdentity(w, plate.camera);
  writeIntrinsics(w, plate.intrinsics, plate.intrinsicsQuality);
  if (plate.pose) writePose(w, *plate.pose, plate.poseQuality);
  if (!plate.probeYawDate.empty() || plate.probeYawRad != 0.0) writeProbe(w, plate);
  if (plate.colour) writeColour(w, *plate.colour);
  return w.text();
}

}  // namespace vem::calib::io
