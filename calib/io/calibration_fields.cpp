#include "calib/io/calibration_fields.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "calib/io/camera_file_fields.h"

namespace vem::calib::io::detail {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;  // as the reader converts

// Degrees that read back (deg * pi / 180) as exactly `rad`, the shortest such text; none if no
// value near rad * 180 / pi does.
std::optional<double> exactDegrees(double rad) {
  std::optional<double> best;
  double candidate = rad * (180.0 / std::numbers::pi);
  for (int step = 0; step < 8; ++step) candidate = std::nextafter(candidate, -INFINITY);
  for (int step = 0; step < 16; ++step, candidate = std::nextafter(candidate, INFINITY)) {
    if (candidate * kRadPerDeg != rad) continue;
    if (!best || tomlNumber(candidate).size() < tomlNumber(*best).size()) best = candidate;
  }
  return best;
}

PixelFormat readPixelFormat(util::TomlReader& r) {
  const std::string name = r.string("pixel_format");
  const std::optional<PixelFormat> format = parsePixelFormat(name);
  r.require(!r.ok() || format.has_value(), "pixel_format",
            "expected Mono8, Mono10, Mono12, Mono16, RGB8, RGB10, RGB12 or RGB16, found \"" + name +
                "\"");
  return format.value_or(PixelFormat{});
}

bool onSensor(const glm::dvec2& point, const CameraIdentity& camera) {
  return point.x >= -0.5 && point.x <= camera.sensorWidthPx - 0.5 && point.y >= -0.5 &&
         point.y <= camera.sensorHeightPx - 0.5;
}

}  // namespace

void readFileHeader(util::TomlReader& root, const FileHeader& header) {
  const std::string format = root.string("format");
  root.require(
      format == header.formatName, "format",
      "expected \"" + std::string(header.formatName) + "\", found \"" + format + "\"" +
          std::string(format == header.otherFormat ? header.otherNote : header.foreignNote));
  const std::int64_t version = root.integer("version", std::numeric_limits<std::int64_t>::min(),
                                            std::numeric_limits<std::int64_t>::max());
  if (root.ok() && version != header.version)
    root.fail("version", util::TomlProblem::UnknownVersion,
              "unknown version " + std::to_string(version) +
                  " (this build of vemcast reads version " + std::to_string(header.version) + ")");
}

glm::dvec2 readPrincipalPoint(util::TomlReader& r, const CameraIdentity& camera) {
  const std::vector<double> centre = r.quantityArray("principal_point", kUnitPx, {2, "x and y"});
  const glm::dvec2 point{centre[0], centre[1]};
  r.require(onSensor(point, camera), "principal_point",
            "expected a point on the " + std::to_string(camera.sensorWidthPx) + " x " +
                std::to_string(camera.sensorHeightPx) + " sensor, found (" +
                util::shortestText(centre[0]) + ", " + util::shortestText(centre[1]) + ")");
  return point;
}

CameraIdentity readCameraIdentity(util::TomlReader r) {
  r.onlyKeys({"model", "serial", "sensor_width", "sensor_height", "pixel_format"});
  CameraIdentity camera;
  camera.model = r.string("model");
  camera.serial = r.string("serial");
  camera.sensorWidthPx = int(r.integerQuantity("sensor_width", kUnitPx, 1, kMaxSensorSidePx));
  camera.sensorHeightPx = int(r.integerQuantity("sensor_height", kUnitPx, 1, kMaxSensorSidePx));
  camera.pixelFormat = readPixelFormat(r);
  return camera;
}

void writeCameraIdentity(TomlWriter& w, const CameraIdentity& camera) {
  w.table("camera");
  w.string("model", camera.model);
  w.string("serial", camera.serial);
  w.integerQuantity("sensor_width", camera.sensorWidthPx, kUnitPx);
  w.integerQuantity("sensor_height", camera.sensorHeightPx, kUnitPx);
  w.string("pixel_format", pixelFormatName(camera.pixelFormat), "channels and bits per code");
}

GeometricQuality readGeometricQuality(util::TomlReader r) {
  r.onlyKeys({"rms_reprojection", "views", "corners", "date"});
  GeometricQuality quality;
  quality.rmsReprojectionPx = r.quantity("rms_reprojection", kUnitPx);
  r.require(quality.rmsReprojectionPx >= 0.0, "rms_reprojection",
            "expected 0 or more, found " + util::shortestText(quality.rmsReprojectionPx));
  quality.views = int(r.integer("views", 0, 1'000'000));
  quality.corners = int(r.integer("corners", 0, 1'000'000'000));
  quality.date = r.dateText("date");
  return quality;
}

void writeGeometricQuality(TomlWriter& w, std::string_view table, const GeometricQuality& quality) {
  w.table(table);
  w.quantity("rms_reprojection", quality.rmsReprojectionPx, kUnitPx);
  w.integer("views", quality.views);
  w.integer("corners", quality.corners);
  w.string("date", quality.date, "UTC");
}

void writeAngle(TomlWriter& w, std::string_view key, double rad, std::string_view note) {
  if (const std::optional<double> deg = exactDegrees(rad)) {
    w.quantity(key, *deg, kUnitDeg, note);
  } else {
    w.quantity(key, rad, "rad", note);
  }
}

}  // namespace vem::calib::io::detail
