// Plate-camera files (calib/io/plate_camera_file.h): every field survives a save and a load bit for
// bit, the example in config/ loads, each kind of bad file is refused in one sentence naming the
// file and the field, and a plate that would not load is never written over the old file.
#include "calib/io/plate_camera_file.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <glm/matrix.hpp>

#include "calib/io/camera_file.h"
#include "plate_truth.h"

namespace vem::calib::io {
namespace {

namespace fs = std::filesystem;

const fs::path kExamplePlate = fs::path(VEM_SOURCE_DIR) / "config/plate-camera-example.toml";
const fs::path kExampleCamera = fs::path(VEM_SOURCE_DIR) / "config/camera-example.toml";

class PlateTempDir {
 public:
  PlateTempDir()
      : path_(fs::temp_directory_path() / ("vem_plate_file_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~PlateTempDir() { fs::remove_all(path_); }
  PlateTempDir(const PlateTempDir&) = delete;
  PlateTempDir& operator=(const PlateTempDir&) = delete;
  [[nodiscard]] fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A plate whose numbers have no short decimal form, every section present.
PlateCamera awkwardPlate(PlateLensModel model) {
  PlateCamera plate = testing::plateTruth(model);
  plate.camera.model = "Plate \"cam\" \\ test";
  plate.intrinsics.fxPx = 1000.0 / 3.0 * 2.5;
  plate.intrinsics.cxPx = std::sqrt(2.0) * 300.0;
  plate.intrinsics.distortion[0] = -1.0 / 7.0;
  plate.intrinsicsQuality = {0.1 + 0.2, 12, 648, "2026-12-01T10:00:00Z"};
  plate.poseQuality = {1.0 / 9.0, 1, 54, "2026-12-01T10:05:00Z"};
  plate.probeYawRad = 0.1 + std::numbers::pi / 3.0;
  plate.probeYawDate = "2026-12-01T10:10:00Z";
  plate.colour = PlateColourMatch{{1.0 / 3.0, 0.002, 2e-3 / 7.0}, 0.7, 6, "2026-12-01T10:20:00Z"};
  return plate;
}

void expectSamePlate(const PlateCamera& a, const PlateCamera& b) {
  EXPECT_EQ(a.camera.model, b.camera.model);
  EXPECT_EQ(a.camera.serial, b.camera.serial);
  EXPECT_EQ(a.camera.sensorWidthPx, b.camera.sensorWidthPx);
  EXPECT_EQ(a.camera.pixelFormat, b.camera.pixelFormat);
  EXPECT_EQ(a.intrinsics.widthPx, b.intrinsics.widthPx);
  EXPECT_EQ(a.intrinsics.heightPx, b.intrinsics.heightPx);
  EXPECT_EQ(a.intrinsics.fxPx, b.intrinsics.fxPx);
  EXPECT_EQ(a.intrinsics.fyPx, b.intrinsics.fyPx);
  EXPECT_EQ(a.intrinsics.cxPx, b.intrinsics.cxPx);
  EXPECT_EQ(a.intrinsics.cyPx, b.intrinsics.cyPx);
  EXPECT_EQ(a.intrinsics.model, b.intrinsics.model);
  EXPECT_EQ(a.intrinsics.distortion, b.intrinsics.distortion);
  EXPECT_EQ(a.intrinsicsQuality.rmsReprojectionPx, b.intrinsicsQuality.rmsReprojectionPx);
  EXPECT_EQ(a.intrinsicsQuality.corners, b.intrinsicsQuality.corners);
  EXPECT_EQ(a.intrinsicsQuality.date, b.intrinsicsQuality.date);
  ASSERT_EQ(a.pose.has_value(), b.pose.has_value());
  if (a.pose) {
    EXPECT_EQ(a.pose->cameraFromWorld, b.pose->cameraFromWorld);
    EXPECT_EQ(a.pose->positionWorldM, b.pose->positionWorldM);
  }
  EXPECT_EQ(a.poseQuality.rmsReprojectionPx, b.poseQuality.rmsReprojectionPx);
  EXPECT_EQ(a.probeYawRad, b.probeYawRad);
  EXPECT_EQ(a.probeYawDate, b.probeYawDate);
  ASSERT_EQ(a.colour.has_value(), b.colour.has_value());
  if (a.colour) {
    EXPECT_EQ(a.colour->gainRgb, b.colour->gainRgb);
    EXPECT_EQ(a.colour->rmsResidualPercent, b.colour->rmsResidualPercent);
    EXPECT_EQ(a.colour->patches, b.colour->patches);
    EXPECT_EQ(a.colour->date, b.colour->date);
  }
}

class PlateCameraFileRoundTrip : public ::testing::TestWithParam<PlateLensModel> {};

TEST_P(PlateCameraFileRoundTrip, EveryFieldSurvivesSaveAndLoadBitForBit) {
  const PlateTempDir dir;
  const PlateCamera plate = awkwardPlate(GetParam());
  ASSERT_TRUE(savePlateCameraFile(plate, dir / "plate.toml").has_value());
  const auto loaded = loadPlateCameraFile(dir / "plate.toml");
  ASSERT_TRUE(loaded.has_value()) << loaded.error().message;
  expectSamePlate(*loaded, plate);
}

INSTANTIATE_TEST_SUITE_P(BothLenses, PlateCameraFileRoundTrip,
                         ::testing::Values(PlateLensModel::BrownConrady,
                                           PlateLensModel::KannalaBrandt));

TEST(PlateCameraFile, AFileWithIntrinsicsOnlyKeepsTheOptionalSectionsAbsent) {
  PlateCamera plate = testing::plateTruth();
  plate.pose.reset();
  plate.probeYawRad = 0.0;
  const auto loaded = parsePlateCameraFile(formatPlateCameraFile(plate), "plate.toml");
  ASSERT_TRUE(loaded.has_value()) << loaded.error().message;
  EXPECT_FALSE(loaded->pose.has_value());
  EXPECT_FALSE(loaded->colour.has_value());
  EXPECT_EQ(loaded->probeYawRad, 0.0);
  EXPECT_TRUE(loaded->probeYawDate.empty());
}

TEST(PlateCameraFile, TheExampleLoads) {
  const auto plate = loadPlateCameraFile(kExamplePlate);
  ASSERT_TRUE(plate.has_value()) << plate.error().message;
  EXPECT_EQ(plate->intrinsics.widthPx, 1280);
  EXPECT_EQ(plate->intrinsics.model, PlateLensModel::BrownConrady);
  ASSERT_TRUE(plate->pose.has_value());
  EXPECT_GT(plate->pose->positionWorldM.y, 0.0);
  EXPECT_NEAR(plate->probeYawRad, 35.0 * std::numbers::pi / 180.0, 1e-15);
  EXPECT_TRUE(plate->colour.has_value());
}

// The example's text with `from` replaced by `to` (once), parsed.
std::expected<PlateCamera, CalibFileFailure> exampleWith(const std::string& from,
                                                         const std::string& to) {
  std::string text = readText(kExamplePlate);
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return parsePlateCameraFile(text, "plate.toml");
}

struct Refusal {
  const char* name;
  const char* from;
  const char* to;
  CalibFileError cause;
  const char* message;
};

void PrintTo(const Refusal& refusal, std::ostream* out) { *out << refusal.name; }

class PlateCameraFileRefusal : public ::testing::TestWithParam<Refusal> {};

TEST_P(PlateCameraFileRefusal, IsOneSentenceNamingTheFileAndTheField) {
  const Refusal& r = GetParam();
  const auto plate = exampleWith(r.from, r.to);
  ASSERT_FALSE(plate.has_value());
  EXPECT_EQ(plate.error().cause, r.cause);
  EXPECT_EQ(plate.error().message, r.message);
}

INSTANTIATE_TEST_SUITE_P(
    EachCause, PlateCameraFileRefusal,
    ::testing::Values(
        Refusal{"AnotherFormat", "\"vemcast-plate-camera\"", "\"something\"",
                CalibFileError::BadValue,
                "plate.toml: format: expected \"vemcast-plate-camera\", found \"something\" (not "
                "a vemcast plate camera file)"},
        Refusal{"UnknownVersion", "version = 1", "version = 2", CalibFileError::UnknownVersion,
                "plate.toml: version: unknown version 2 (this build of vemcast reads version 1)"},
        Refusal{"MissingField", "serial = \"PLATE-0001\"", "", CalibFileError::MissingField,
                "plate.toml: camera.serial: missing (expected a string)"},
        Refusal{"WrongUnit", "position = { value = [1.0, 1.2, -1.85], unit = \"m\" }",
                "position = { value = [1000, 1200, -1850], unit = \"mm\" }",
                CalibFileError::WrongUnit,
                "plate.toml: pose.position: expected unit \"m\", found \"mm\""},
        Refusal{"UnknownModel", "\"brown-conrady\"", "\"pinhole\"", CalibFileError::BadValue,
                "plate.toml: intrinsics.model: expected \"brown-conrady\" or \"kannala-brandt\", "
                "found \"pinhole\""},
        Refusal{"DistortionCount", "\"brown-conrady\"", "\"kannala-brandt\"",
                CalibFileError::BadValue,
                "plate.toml: intrinsics.distortion: expected 4 values (k1 to k4 of "
                "kannala-brandt), found 5"},
        Refusal{"FocalLength", "[700.0, 699.4]", "[0.0, 699.4]", CalibFileError::BadValue,
                "plate.toml: intrinsics.focal_length: expected fx and fy above 0, found 0, 699.4"},
        Refusal{"PrincipalPointOffTheSensor", "[645.3, 357.9]", "[645.3, 957.9]",
                CalibFileError::BadValue,
                "plate.toml: intrinsics.principal_point: expected a point on the 1280 x 720 "
                "sensor, found (645.3, 957.9)"},
        Refusal{"NotARotation", "[-0.961523947641, 0.0, -0.274721127897]",
                "[-0.961523947641, 0.0, 0.274721127897]", CalibFileError::BadValue,
                "plate.toml: pose.camera_from_world: expected a rotation (orthonormal rows, "
                "determinant 1, to within 1e-6), found rows that are off by 0.517"},
        Refusal{"CameraUnderTheFloor", "[1.0, 1.2, -1.85]", "[1.0, -1.2, -1.85]",
                CalibFileError::BadValue,
                "plate.toml: pose.position: expected a camera above the floor (y above 0 m), "
                "found y = -1.2 m"},
        Refusal{"Gain", "[0.0021, 0.0019, 0.0024]", "[0.0021, 0.0, 0.0024]",
                CalibFileError::BadValue,
                "plate.toml: colour.gain: expected gains above 0, found 0"},
        Refusal{"UnknownField", "[probe]", "[probes]", CalibFileError::BadValue,
                "plate.toml: probes: unknown field (expected one of: format, version, camera, "
                "intrinsics, pose, probe, colour)"}),
    [](const ::testing::TestParamInfo<Refusal>& param) { return std::string(param.param.name); });

TEST(PlateCameraFile, AMissingFileIsRefusedNamingIt) {
  const auto plate = loadPlateCameraFile("no-such-plate.toml");
  ASSERT_FALSE(plate.has_value());
  EXPECT_EQ(plate.error().cause, CalibFileError::NotFound);
  EXPECT_EQ(plate.error().message, "no-such-plate.toml: no such file");
}

TEST(PlateCameraFile, ALightProbeCameraFileGivenByMistakeIsNamedAsSuch) {
  const auto plate = loadPlateCameraFile(kExampleCamera);
  ASSERT_FALSE(plate.has_value());
  EXPECT_EQ(plate.error().message,
            kExampleCamera.string() +
                ": format: expected \"vemcast-plate-camera\", found \"vemcast-camera\" (a "
                "light-probe camera file, not a plate camera file)");
}

TEST(PlateCameraFile, APlateFileGivenAsALightProbeCameraFileIsNamedAsSuch) {
  const auto camera = loadCameraFile(kExamplePlate);
  ASSERT_FALSE(camera.has_value());
  EXPECT_EQ(camera.error().message,
            kExamplePlate.string() +
                ": format: expected \"vemcast-camera\", found \"vemcast-plate-camera\" (a plate "
                "camera file, not a light-probe camera file)");
}

TEST(PlateCameraFile, APlateThatWouldNotLoadLeavesTheOldFileAsItWas) {
  const PlateTempDir dir;
  ASSERT_TRUE(savePlateCameraFile(testing::plateTruth(), dir / "plate.toml").has_value());
  const std::string before = readText(dir / "plate.toml");
  PlateCamera bad = testing::plateTruth();
  bad.pose->positionWorldM.y = -1.0;  // under the floor
  const auto saved = savePlateCameraFile(bad, dir / "plate.toml");
  ASSERT_FALSE(saved.has_value());
  EXPECT_NE(saved.error().message.find("so nothing was written"), std::string::npos);
  EXPECT_EQ(readText(dir / "plate.toml"), before);
}

}  // namespace
}  // namespace vem::calib::io
