// Reading (and saving) plate-camera files: the fields of plate_camera_file.h, each checked as it is
// read.
#include "calib/io/plate_camera_file.h"

#include <cmath>

#include <fmt/format.h>
#include <glm/matrix.hpp>

#include "calib/io/calibration_fields.h"
#include "calib/io/camera_file_fields.h"
#include "calib/io/file_access.h"
#include "calib/io/plate_camera_file_fields.h"
#include "util/toml_reader.h"

namespace vem::calib::io {
namespace {

using util::shortestText;
using FieldReader = util::TomlReader;

constexpr detail::FileHeader kPlateCameraFileHeader{
    detail::kPlateCameraFormatName, kPlateCameraFileVersion, detail::kCameraFormatName,
    " (a light-probe camera file, not a plate camera file)", " (not a vemcast plate camera file)"};

PlateLensModel readLensModel(FieldReader& r) {
  const std::string name = r.string("model");
  const std::optional<PlateLensModel> model = parsePlateLensModel(name);
  r.require(!r.ok() || model.has_value(), "model",
            "expected \"brown-conrady\" or \"kannala-brandt\", found \"" + name + "\"");
  return model.value_or(PlateLensModel::BrownConrady);
}

PlateIntrinsics readIntrinsics(FieldReader r, const CameraIdentity& camera,
                               GeometricQuality& quality) {
  r.onlyKeys({"model", "focal_length", "principal_point", "distortion", "fit"});
  PlateIntrinsics in;
  in.widthPx = camera.sensorWidthPx;
  in.heightPx = camera.sensorHeightPx;
  in.model = readLensModel(r);
  const std::vector<double> focal = r.quantityArray("focal_length", detail::kUnitPx, {2, "fx, fy"});
  in.fxPx = focal[0];
  in.fyPx = focal[1];
  r.require(
      in.fxPx > 0.0 && in.fyPx > 0.0, "focal_length",
      "expected fx and fy above 0, found " + shortestText(in.fxPx) + ", " + shortestText(in.fyPx));
  const glm::dvec2 centre = detail::readPrincipalPoint(r, camera);
  in.cxPx = centre.x;
  in.cyPx = centre.y;
  const bool brown = in.model == PlateLensModel::BrownConrady;
  const std::vector<double> d = r.quantityArray(
      "distortion", detail::kUnitOne,
      {std::size_t(distortionCount(in.model)),
       brown ? "k1, k2, p1, p2, k3 of brown-conrady" : "k1 to k4 of kannala-brandt"});
  for (std::size_t i = 0; i < d.size() && i < in.distortion.size(); ++i) in.distortion[i] = d[i];
  quality = detail::readGeometricQuality(r.section("fit"));
  return in;
}

// The rows of a rotation: orthonormal, determinant +1.
glm::dmat3 readRotation(FieldReader& r, std::string_view key) {
  const auto rows = r.quantityRows(key, detail::kUnitOne, {3, "three rows"}, {3, "x, y, z"});
  glm::dmat3 m(1.0);
  if (!r.ok()) return m;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[col][row] = rows[std::size_t(row)][std::size_t(col)];
  const glm::dmat3 product = m * glm::transpose(m);
  double worst = std::abs(glm::determinant(m) - 1.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) worst = std::max(worst, std::abs(product[i][j] - (i == j)));
  r.require(worst <= detail::kRotationTolerance, key,
            fmt::format("expected a rotation (orthonormal rows, determinant 1, to within 1e-6), "
                        "found rows that are off by {:.3g}",
                        worst));
  return m;
}

PlatePose readPose(FieldReader r, GeometricQuality& quality) {
  r.onlyKeys({"camera_from_world", "position", "fit"});
  PlatePose pose;
  pose.cameraFromWorld = readRotation(r, "camera_from_world");
  const std::vector<double> p = r.quantityArray("position", detail::kUnitMetre, {3, "x, y, z"});
  pose.positionWorldM = {p[0], p[1], p[2]};
  r.require(!r.ok() || pose.positionWorldM.y > 0.0, "position",
            "expected a camera above the floor (y above 0 m), found y = " +
                shortestText(pose.positionWorldM.y) + " m");
  quality = detail::readGeometricQuality(r.section("fit"));
  return pose;
}

void readProbe(FieldReader r, PlateCamera& plate) {
  r.onlyKeys({"yaw", "date"});
  plate.probeYawRad = r.angleRad("yaw");
  r.require(std::abs(plate.probeYawRad) <= 2.0 * std::numbers::pi, "yaw",
            "expected an angle from -360 to 360 deg, found " +
                shortestText(plate.probeYawRad * 180.0 / std::numbers::pi) + " deg");
  plate.probeYawDate = r.dateText("date");
}

PlateColourMatch readColour(FieldReader r) {
  r.onlyKeys({"gain", "rms_residual", "patches", "date"});
  PlateColourMatch colour;
  const std::vector<double> gain = r.quantityArray("gain", detail::kUnitColourGain, {3, "R, G, B"});
  for (const double g : gain)
    r.require(g > 0.0, "gain", "expected gains above 0, found " + shortestText(g));
  for (std::size_t c = 0; c < gain.size() && c < 3; ++c) colour.gainRgb[c] = gain[c];
  colour.rmsResidualPercent = r.quantity("rms_residual", detail::kUnitPercent);
  r.require(colour.rmsResidualPercent >= 0.0, "rms_residual",
            "expected a percentage of 0 or more, found " + shortestText(colour.rmsResidualPercent));
  colour.patches = int(r.integer("patches", 0, 1'000'000));
  colour.date = r.dateText("date");
  return colour;
}

PlateCamera readPlate(FieldReader& root) {
  root.onlyKeys({"format", "version", "camera", "intrinsics", "pose", "probe", "colour"});
  PlateCamera plate;
  plate.camera = detail::readCameraIdentity(root.section("camera"));
  plate.intrinsics =
      readIntrinsics(root.section("intrinsics"), plate.camera, plate.intrinsicsQuality);
  if (std::optional<FieldReader> pose = root.optionalSection("pose"))
    plate.pose = readPose(*pose, plate.poseQuality);
  if (std::optional<FieldReader> probe = root.optionalSection("probe")) readProbe(*probe, plate);
  if (std::optional<FieldReader> colour = root.optionalSection("colour"))
    plate.colour = readColour(*colour);
  return plate;
}

}  // namespace

std::expected<PlateCamera, CalibFileFailure> parsePlateCameraFile(const std::string& text,
                                                                  const std::string& sourceName) {
  return detail::parseTomlText(text, sourceName, [](FieldReader& root, util::TomlStatus&) {
    // The header first: a newer file is refused for its version, not for its new fields.
    detail::readFileHeader(root, kPlateCameraFileHeader);
    return readPlate(root);
  });
}

std::expected<PlateCamera, CalibFileFailure> loadPlateCameraFile(
    const std::filesystem::path& path) {
  return detail::loadTextFile(path, "plate camera file", parsePlateCameraFile);
}

std::expected<void, CalibFileFailure> savePlateCameraFile(const PlateCamera& plate,
                                                          const std::filesystem::path& path) {
  return detail::saveCheckedTextFile(path, formatPlateCameraFile(plate), "plate camera file",
                                     parsePlateCameraFile);
}

}  // namespace vem::calib::io
