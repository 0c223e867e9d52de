// Camera files (calib/io/camera_file.h): every field survives a save and a load bit for bit, the
// example in config/ is a usable camera, and each kind of bad file is refused in one sentence that
// names the file and the field.
#include "calib/io/camera_file.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>

#include <gtest/gtest.h>

namespace vem::calib::io {
namespace {

namespace fs = std::filesystem;

const fs::path kExampleCamera =
    fs::path(VEM_SOURCE_DIR) / "config/camera-example.toml";

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("vem_camera_file_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A calibration whose numbers have no short decimal form.
CameraCalibration awkwardCalibration() {
  CameraCalibration c;
  c.camera = {"HDRC \"VGAx\" \\ test", "sn-0042", 1280, 1024, PixelFormat{3, 12}};
  c.photometric = PhotometricCalibration{LogResponse{{1552.0045579117063, 0.1, 1.0 / 3.0},
                                                     {208.99929058556845, std::numbers::pi, 1e-7}},
                                         64.000000000000014, 4095.0};
  c.photometricQuality = {0.0020923284307239943, 0.1 + 0.2, 5e-324, 6, 2, "2026-01-31T12:00:00Z"};
  KannalaBrandtLens lens;
  lens.kPx = {310.12345678901234, -6.000000000000001, 0.5, -0.05, 0.0020000000000000005};
  lens.principalPointPx = {643.2, 509.59999999999997};
  lens.aspect = 1.0005;
  lens.maxThetaRad = 1.6580627893946132;
  c.lens = lens;
  c.geometricQuality = {0.21000000000000002, 12, 840, "2026-02-01T08:30:00Z"};
  c.orientation = {-12.5, 1.0 / 7.0, 359.99999999999994};
  return c;
}

void expectSameCalibration(const CameraCalibration& a, const CameraCalibration& b) {
  EXPECT_EQ(a.camera.model, b.camera.model);
  EXPECT_EQ(a.camera.serial, b.camera.serial);
  EXPECT_EQ(a.camera.sensorWidthPx, b.camera.sensorWidthPx);
  EXPECT_EQ(a.camera.sensorHeightPx, b.camera.sensorHeightPx);
  EXPECT_EQ(a.camera.pixelFormat, b.camera.pixelFormat);
  ASSERT_EQ(a.photometric.has_value(), b.photometric.has_value());
  if (a.photometric) {
    EXPECT_EQ(a.photometric->blackLevelCode, b.photometric->blackLevelCode);
    EXPECT_EQ(a.photometric->saturationCode, b.photometric->saturationCode);
    EXPECT_EQ(a.photometric->response.index(), b.photometric->response.index());
  }
  EXPECT_EQ(a.photometricQuality.rmsResidualPercent, b.photometricQuality.rmsResidualPercent);
  EXPECT_EQ(a.photometricQuality.maxResidualPercent, b.photometricQuality.maxResidualPercent);
  EXPECT_EQ(a.photometricQuality.maxCheckErrorPercent, b.photometricQuality.maxCheckErrorPercent);
  EXPECT_EQ(a.photometricQuality.fitPatches, b.photometricQuality.fitPatches);
  EXPECT_EQ(a.photometricQuality.checkPatches, b.photometricQuality.checkPatches);
  EXPECT_EQ(a.photometricQuality.date, b.photometricQuality.date);
  ASSERT_EQ(a.lens.has_value(), b.lens.has_value());
  if (a.lens) {
    EXPECT_EQ(a.lens->kPx, b.lens->kPx);
    EXPECT_EQ(a.lens->principalPointPx, b.lens->principalPointPx);
    EXPECT_EQ(a.lens->aspect, b.lens->aspect);
    EXPECT_EQ(a.lens->maxThetaRad, b.lens->maxThetaRad);
  }
  EXPECT_EQ(a.geometricQuality.rmsReprojectionPx, b.geometricQuality.rmsReprojectionPx);
  EXPECT_EQ(a.geometricQuality.views, b.geometricQuality.views);
  EXPECT_EQ(a.geometricQuality.corners, b.geometricQuality.corners);
  EXPECT_EQ(a.geometricQuality.date, b.geometricQuality.date);
  EXPECT_EQ(a.orientation.imageRotationDeg, b.orientation.imageRotationDeg);
  EXPECT_EQ(a.orientation.tiltDeg, b.orientation.tiltDeg);
  EXPECT_EQ(a.orientation.tiltAzimuthDeg, b.orientation.tiltAzimuthDeg);
}

CameraCalibration roundTrip(const CameraCalibration& c) {
  const std::string text = formatCameraFile(c);
  auto back = parseCameraFile(text, "roundtrip.toml");
  EXPECT_TRUE(back.has_value()) << (back ? "" : back.error().message) << "\n" << text;
  return back.value_or(CameraCalibration{});
}

// Replaces the first occurrence of `from` (which must be there) with `to`.
std::string edited(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Removes the first line that starts with `start`.
std::string withoutLine(const std::string& text, const std::string& start) {
  const std::size_t at = text.find('\n' + start);
  EXPECT_NE(at, std::string::npos) << start;
  if (at == std::string::npos) return text;
  const std::size_t end = text.find('\n', at + 1);
  return text.substr(0, at) + text.substr(end);
}

struct Refusal {
  CalibFileError cause;
  std::string message;
};

Refusal refusalOf(const std::string& text) {
  auto parsed = parseCameraFile(text, "config/cam.toml");
  EXPECT_FALSE(parsed.has_value()) << text;
  if (parsed) return {CalibFileError::BadValue, ""};
  EXPECT_EQ(parsed.error().message.rfind("config/cam.toml: ", 0), 0U) << parsed.error().message;
  EXPECT_EQ(parsed.error().message.find('\n'), std::string::npos) << parsed.error().message;
  return {parsed.error().cause, parsed.error().message};
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(CameraFile, RoundTripKeepsEveryNumberBitForBitNotJustToPrintedPrecision) {
  const CameraCalibration c = awkwardCalibration();
  const CameraCalibration back = roundTrip(c);
  expectSameCalibration(c, back);
  const auto& log = std::get<LogResponse>(back.photometric->response);
  EXPECT_EQ(log.aCode, std::get<LogResponse>(c.photometric->response).aCode);
  EXPECT_EQ(log.bCodePerLn, std::get<LogResponse>(c.photometric->response).bCodePerLn);
}

TEST(CameraFile, LinearAndTableModelsRoundTripWithOnlyTheFormatsChannels) {
  CameraCalibration mono = awkwardCalibration();
  mono.camera.pixelFormat = {1, 8};
  mono.photometric = PhotometricCalibration{LinearResponse{{0.0123456789, 0.0, 0.0}}, 3.5, 250.0};
  const CameraCalibration linear = roundTrip(mono);
  expectSameCalibration(mono, linear);
  EXPECT_EQ(std::get<LinearResponse>(linear.photometric->response).gainCodePerCdM2Us[0],
            0.0123456789);

  TabulatedResponse table;
  for (int code = 0; code < 256; ++code)
    table.exposureByCode[0].push_back(std::exp(0.043 * code) - 1.0);
  table.scaleCdM2 = 2.5e-3;
  mono.photometric = PhotometricCalibration{table, 0.0, 255.0};
  const CameraCalibration back = roundTrip(mono);
  expectSameCalibration(mono, back);
  const auto& got = std::get<TabulatedResponse>(back.photometric->response);
  EXPECT_EQ(got.exposureByCode[0], table.exposureByCode[0]);
  EXPECT_EQ(got.scaleCdM2, table.scaleCdM2);
}

TEST(CameraFile, MaxThetaRoundTripsExactlyForAnyAngleNotOnlyWholeDegrees) {
  std::mt19937 random(7);
  CameraCalibration c = awkwardCalibration();
  for (int i = 0; i < 200; ++i) {
    c.lens->maxThetaRad = std::uniform_real_distribution<double>(1.0, 1.7)(random);
    EXPECT_EQ(roundTrip(c).lens->maxThetaRad, c.lens->maxThetaRad);
  }
  c.lens->maxThetaRad = 95.0 * std::numbers::pi / 180.0;
  EXPECT_TRUE(contains(formatCameraFile(c), "max_theta = { value = 95.0, unit = \"deg\" }"))
      << formatCameraFile(c);
}

TEST(CameraFile, SectionsThatWereNotCalibratedStayAbsent) {
  CameraCalibration c = awkwardCalibration();
  c.photometric.reset();
  c.photometricQuality = {};
  c.lens.reset();
  c.geometricQuality = {};
  const std::string text = formatCameraFile(c);
  EXPECT_FALSE(contains(text, "[photometric"));
  EXPECT_FALSE(contains(text, "[geometric"));
  expectSameCalibration(c, roundTrip(c));
}

TEST(CameraFile, ExampleInConfigIsAnHdrcLikeRgb12CameraWithA190DegreeLens) {
  const auto example = loadCameraFile(kExampleCamera);
  ASSERT_TRUE(example.has_value()) << example.error().message;
  EXPECT_EQ(example->camera.sensorWidthPx, 1280);
  EXPECT_EQ(example->camera.sensorHeightPx, 1024);
  EXPECT_EQ(example->camera.pixelFormat, (PixelFormat{3, 12}));
  ASSERT_TRUE(example->photometric && example->lens);
  for (int c = 0; c < 3; ++c) {  // eight decades between black and saturation
    EXPECT_GT(codeFromLuminance(*example->photometric, c, 1e-3, 1000, 1),
              example->photometric->blackLevelCode);
    EXPECT_LT(codeFromLuminance(*example->photometric, c, 1e5, 1000, 1),
              example->photometric->saturationCode);
  }
  EXPECT_NEAR(example->lens->maxThetaRad * 360.0 / std::numbers::pi, 190.0, 1e-9);
  for (std::size_t i = 1; i < 5; ++i) EXPECT_NE(example->lens->kPx[i], 0.0);
  EXPECT_EQ(example->lens->aspect, 1.0005);
  const double r =
      example->lens->radiusPx(example->lens->maxThetaRad);  // the circle is on the sensor
  EXPECT_GT(example->lens->principalPointPx.y - r * example->lens->aspect, 0.0);
  EXPECT_LT(example->lens->principalPointPx.y + r * example->lens->aspect, 1023.0);
}

TEST(CameraFile, SaveThenLoadGivesTheSameCalibration) {
  const TempDir dir;
  ASSERT_TRUE(saveCameraFile(awkwardCalibration(), dir / "cam.toml"));
  const auto back = loadCameraFile(dir / "cam.toml");
  ASSERT_TRUE(back.has_value()) << back.error().message;
  expectSameCalibration(awkwardCalibration(), *back);
}

TEST(CameraFile, UnknownVersionIsRefusedAsSuchBeforeItsNewFieldsAre) {
  const std::string text =
      edited(formatCameraFile(awkwardCalibration()), "version = 1", "version = 2\nnew_thing = 1");
  const Refusal r = refusalOf(text);
  EXPECT_EQ(r.cause, CalibFileError::UnknownVersion);
  EXPECT_TRUE(contains(r.message, "version: unknown version 2")) << r.message;
}

TEST(CameraFile, AnotherFormatIsRefusedByName) {
  const Refusal r = refusalOf(
      edited(formatCameraFile(awkwardCalibration()), "\"vemcast-camera\"", "\"vemcast-patches\""));
  EXPECT_EQ(r.cause, CalibFileError::BadValue);
  EXPECT_TRUE(contains(r.message, "format: expected \"vemcast-camera\"")) << r.message;
}

TEST(CameraFile, EachMissingFieldIsRefusedNamingItsDottedPath) {
  const std::string text = formatCameraFile(awkwardCalibration());
  const std::vector<std::pair<std::string, std::string>> cases{
      {"format = ", "format"},
      {"version = ", "version"},
      {"serial = ", "camera.serial"},
      {"sensor_height = ", "camera.sensor_height"},
      {"pixel_format = ", "camera.pixel_format"},
      {"black_level = ", "photometric.black_level"},
      {"b = ", "photometric.b"},
      {"max_check_error = ", "photometric.fit.max_check_error"},
      {"date = ", "photometric.fit.date"},
      {"principal_point = ", "geometric.principal_point"},
      {"aspect = ", "geometric.aspect"},
      {"corners = ", "geometric.fit.corners"},
      {"tilt_azimuth = ", "orientation.tilt_azimuth"},
      {"[orientation]", "orientation"},
  };
  for (const auto& [line, field] : cases) {
    SCOPED_TRACE(field);
    std::string damaged = withoutLine(text, line);
    if (line == "[orientation]") damaged = damaged.substr(0, damaged.find("\nimage_rotation"));
    const Refusal r = refusalOf(damaged);
    EXPECT_EQ(r.cause, CalibFileError::MissingField) << r.message;
    EXPECT_TRUE(contains(r.message, "config/cam.toml: " + field + ": missing")) << r.message;
  }
}

TEST(CameraFile, WrongUnitIsRefusedNamingTheFieldAndBothUnits) {
  const std::string text = formatCameraFile(awkwardCalibration());
  const Refusal k = refusalOf(edited(text, "0.0020000000000000005], unit = \"px\"",
                                     "0.0020000000000000005], unit = \"mm\""));
  EXPECT_EQ(k.cause, CalibFileError::WrongUnit);
  EXPECT_EQ(k.message, "config/cam.toml: geometric.k: expected unit \"px\", found \"mm\"");
  const Refusal b =
      refusalOf(edited(text, "unit = \"code/ln(cd/m2)\"", "unit = \"code/log10(cd/m2)\""));
  EXPECT_EQ(b.cause, CalibFileError::WrongUnit);
  EXPECT_TRUE(contains(b.message, "photometric.b: expected unit \"code/ln(cd/m2)\"")) << b.message;
  const Refusal noUnit =
      refusalOf(edited(text, "tilt = { value = 0.14285714285714285, unit = \"deg\" }",
                       "tilt = { value = 0.14285714285714285 }"));
  EXPECT_EQ(noUnit.cause, CalibFileError::MissingField);
  EXPECT_TRUE(contains(noUnit.message, "orientation.tilt.unit: missing")) << noUnit.message;
}

TEST(CameraFile, AnglesInRadiansAreConverted) {
  const std::string text = edited(formatCameraFile(awkwardCalibration()),
                                  "tilt = { value = 0.14285714285714285, unit = \"deg\" }",
                                  "tilt = { value = 0.5, unit = \"rad\" }");
  const auto parsed = parseCameraFile(text, "cam.toml");
  ASSERT_TRUE(parsed.has_value()) << parsed.error().message;
  EXPECT_DOUBLE_EQ(parsed->orientation.tiltDeg, 0.5 * 180.0 / std::numbers::pi);
}

TEST(CameraFile, ValuesOfTheWrongTypeAreRefusedSayingWhatWasFound) {
  const std::string text = formatCameraFile(awkwardCalibration());
  const std::vector<std::tuple<std::string, std::string, std::string>> cases{
      {"version = 1", "version = \"1\"", "version: expected an integer, found the string \"1\""},
      {"{ value = 1280, unit = \"px\" }", "{ value = 1280.5, unit = \"px\" }",
       "camera.sensor_width: expected a whole number"},
      {"{ value = 1024, unit = \"px\" }", "1024",
       "camera.sensor_height: expected { value = <integer>"},
      {"aspect = 1.0005", "aspect = \"1.0005\"",
       "geometric.aspect: expected a number, found the string"},
      {"views = 12", "views = 12.0", "geometric.fit.views: expected an integer"},
      {"pixel_format = \"RGB12\"", "pixel_format = \"RGB14\"",
       "camera.pixel_format: expected Mono8"},
      {"model = \"log\"", "model = \"gamma\"",
       "photometric.model: expected \"log\", \"linear\" or \"table\""},
  };
  for (const auto& [from, to, expected] : cases) {
    SCOPED_TRACE(to);
    const Refusal r = refusalOf(edited(text, from, to));
    EXPECT_EQ(r.cause, CalibFileError::BadValue);
    EXPECT_TRUE(contains(r.message, expected)) << r.message;
  }
}

TEST(CameraFile, NonFiniteNumbersAreRefused) {
  const std::string text = formatCameraFile(awkwardCalibration());
  for (const char* bad : {"nan", "inf", "-inf"}) {
    const Refusal r = refusalOf(edited(text, "aspect = 1.0005", std::string("aspect = ") + bad));
    EXPECT_EQ(r.cause, CalibFileError::BadValue);
    EXPECT_TRUE(contains(r.message, "geometric.aspect: expected a finite number")) << r.message;
  }
}

TEST(CameraFile, LensThatFoldsTheImageIsRefusedNamingK) {
  CameraCalibration c = awkwardCalibration();
  c.lens->kPx = {300.0, -60.0, 0.0, 0.0, 0.0};  // r'(theta) = 300 - 180 theta^2 < 0 beyond 74 deg
  const Refusal r = refusalOf(formatCameraFile(c));
  EXPECT_EQ(r.cause, CalibFileError::BadValue);
  EXPECT_TRUE(contains(r.message, "geometric.k: r(theta) stops increasing")) << r.message;
}

TEST(CameraFile, ChannelCountMustMatchThePixelFormat) {
  const std::string text = formatCameraFile(awkwardCalibration());
  const Refusal r =
      refusalOf(edited(text, "a = { value = [1552.0045579117063, 0.1, 0.3333333333333333]",
                       "a = { value = [1552.0045579117063]"));
  EXPECT_EQ(r.cause, CalibFileError::BadValue);
  EXPECT_TRUE(
      contains(r.message, "photometric.a: expected 3 values (one per channel of RGB12), found 1"))
      << r.message;
  const Refusal mono =
      refusalOf(edited(text, "pixel_format = \"RGB12\"", "pixel_format = \"Mono12\""));
  EXPECT_TRUE(contains(mono.message,
                       "photometric.a: expected 1 value (one per channel of Mono12), found 3"))
      << mono.message;
}

TEST(CameraFile, SaturationAtOrBelowBlackOrAboveTheLargestCodeIsRefused) {
  const std::string text = formatCameraFile(awkwardCalibration());
  const Refusal low = refusalOf(
      edited(text, "{ value = 4095.0, unit = \"code\" }", "{ value = 64.0, unit = \"code\" }"));
  EXPECT_TRUE(
      contains(low.message, "photometric.saturation: expected a code above the black level"))
      << low.message;
  const Refusal high = refusalOf(
      edited(text, "{ value = 4095.0, unit = \"code\" }", "{ value = 4096.0, unit = \"code\" }"));
  EXPECT_TRUE(contains(high.message,
                       "photometric.saturation: expected at most 4095, the largest RGB12 code"))
      << high.message;
}

TEST(CameraFile, MisspeltOptionalSectionIsRefusedNotIgnored) {
  const std::string text = formatCameraFile(awkwardCalibration());
  const Refusal section = refusalOf(edited(text, "[geometric]", "[geometrc]"));
  EXPECT_TRUE(contains(section.message, "config/cam.toml: geometrc: unknown field"))
      << section.message;
  const Refusal key = refusalOf(edited(text, "aspect = ", "aspec = "));
  EXPECT_TRUE(contains(key.message, "geometric.aspec: unknown field")) << key.message;
}

TEST(CameraFile, SyntaxErrorIsRefusedWithItsLine) {
  const Refusal r = refusalOf("format = \"vemcast-camera\"\nversion = = 1\n");
  EXPECT_EQ(r.cause, CalibFileError::BadSyntax);
  EXPECT_TRUE(contains(r.message, "config/cam.toml: line 2")) << r.message;
}

TEST(CameraFile, MissingFileAndFolderAreRefusedByCause) {
  const TempDir dir;
  const auto missing = loadCameraFile(dir / "absent.toml");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().cause, CalibFileError::NotFound);
  EXPECT_TRUE(contains(missing.error().message, "absent.toml: no such file"))
      << missing.error().message;
  fs::create_directories(dir / "folder.toml");
  const auto folder = loadCameraFile(dir / "folder.toml");
  ASSERT_FALSE(folder);
  EXPECT_EQ(folder.error().cause, CalibFileError::Unreadable);
}

TEST(CameraFile, SavingAnInvalidCalibrationWritesNothing) {
  const TempDir dir;
  ASSERT_TRUE(saveCameraFile(awkwardCalibration(), dir / "cam.toml"));
  const std::string before = readFile(dir / "cam.toml");
  CameraCalibration bad = awkwardCalibration();
  bad.photometric->saturationCode = 10.0;  // below the black level
  const auto saved = saveCameraFile(bad, dir / "cam.toml");
  ASSERT_FALSE(saved);
  EXPECT_TRUE(contains(saved.error().message, "photometric.saturation")) << saved.error().message;
  EXPECT_EQ(readFile(dir / "cam.toml"), before);
}

// The process may write at most `bytes` bytes per file while this lives (SIGXFSZ ignored).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) : oldHandler_(std::signal(SIGXFSZ, SIG_IGN)) {
    ::getrlimit(RLIMIT_FSIZE, &old_);
    const rlimit limit{bytes, old_.rlim_max};
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, oldHandler_);
  }

 private:
  rlimit old_{};
  void (*oldHandler_)(int);
};

TEST(CameraFile, FailedWriteLeavesTheOldFileByteIdentical) {
  const TempDir dir;
  CameraCalibration small = awkwardCalibration();
  small.lens.reset();
  ASSERT_TRUE(saveCameraFile(small, dir / "cam.toml"));
  const std::string before = readFile(dir / "cam.toml");
  std::expected<void, CalibFileFailure> saved;
  {
    const FileSizeLimit limit(before.size() + 10);  // the old file fits, the longer new one not
    saved = saveCameraFile(awkwardCalibration(), dir / "cam.toml");
  }
  ASSERT_FALSE(saved);
  EXPECT_EQ(saved.error().cause, CalibFileError::WriteFailed);
  EXPECT_TRUE(contains(saved.error().message, "cam.toml: cannot write")) << saved.error().message;
  EXPECT_EQ(readFile(dir / "cam.toml"), before);
}

}  // namespace
}  // namespace vem::calib::io
