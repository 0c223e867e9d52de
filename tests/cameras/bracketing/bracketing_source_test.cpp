// BracketingSource around a fake LDR camera that applies exposure requests late
// (ldr_camera_fake.h): grouping by reported exposure, drops and their reasons, timestamps, errors,
// settings, describe().
#include "cameras/bracketing/bracketing_source.h"

#include <cmath>
#include <map>
#include <memory>

#include <gtest/gtest.h>

#include "calib/core/bracket_simulation.h"
#include "calib/io/camera_file.h"
#include "cameras/bracketing/ldr_camera_fake.h"
#include "support/test_cameras.h"
#include "synth/sky_scene.h"

namespace vem::cameras {
namespace {

using testing::LdrFakeCamera;
using testing::LdrFakeOptions;

constexpr int kWidth = 40;
constexpr int kHeight = 32;

BracketSettings threeByTwo() {
  BracketSettings s;
  s.count = 3;
  s.stopsApart = 2.0;
  s.baseExposureUs = 100.0;
  return s;
}

// A fake camera the test keeps a pointer to while the source owns it.
struct Rig {
  LdrFakeCamera* camera = nullptr;
  std::unique_ptr<BracketingSource> source;
};

std::unique_ptr<LdrFakeCamera> makeCamera(LdrFakeOptions options = {}) {
  // The sky's zenith (1 cd/m^2) reads code 128 at 400 us.
  const double scale = calib::scaleForCode(calib::ldrCameraResponse(), 128, 1.0, 400.0);
  return std::make_unique<LdrFakeCamera>(testing::ldrCamera(kWidth, kHeight, 3, scale),
                                         std::make_shared<synth::SkyScene>(), options);
}

Rig makeRig(LdrFakeOptions options = {}, BracketSettings settings = threeByTwo()) {
  auto camera = makeCamera(options);
  Rig rig{camera.get(), nullptr};
  auto made = BracketingSource::create(std::move(camera), settings);
  EXPECT_TRUE(made.has_value()) << (made ? "" : made.error().message);
  if (made) rig.source = std::move(*made);
  return rig;
}

// The camera frame whose capture time the merged frame carries (odd K: the middle frame).
std::uint64_t middleSeq(const LdrFakeCamera& camera, std::int64_t captureTsNs) {
  return std::uint64_t(std::llround(double(captureTsNs - camera.captureTsNs(0)) * 30.0 / 1e9));
}

void expectInvariant(const BracketingSource& source) {
  const BracketCounters& c = source.counters();
  EXPECT_EQ(c.framesDropped, c.droppedOutOfCycle + c.droppedForGap + c.droppedForError);
  EXPECT_GE(c.framesIn, c.groups * std::uint64_t(source.settings().count) + c.framesDropped);
  EXPECT_LT(c.framesIn, (c.groups + 1) * std::uint64_t(source.settings().count) + c.framesDropped);
}

TEST(BracketingSource, GroupsByReportedExposureWhenTheCameraAppliesRequestsTwoFramesLate) {
  Rig rig = makeRig();
  ASSERT_TRUE(rig.source);
  for (std::uint64_t group = 0; group < 4; ++group) {
    auto frame = rig.source->next();
    ASSERT_TRUE(frame.has_value()) << frame.error().message;
    EXPECT_EQ(frame->seq, group);
    // Frames 0 and 1 are still at the camera's initial 10 ms: the first group is frames 2, 3, 4.
    const std::uint64_t middle = 3 + 3 * group;
    EXPECT_EQ(frame->captureTsNs, rig.camera->captureTsNs(middle));
    EXPECT_EQ(frame->arrivalNs, rig.camera->captureTsNs(middle + 1) + 2'000'000);
    EXPECT_EQ(frame->frame.format, (vem::PixelFormat{3, 16}));
    EXPECT_EQ(frame->frame.gain, 1.0);
    EXPECT_DOUBLE_EQ(frame->frame.exposureUs, 100.0 + 400.0 + 1600.0);
    rig.source->recycle(std::move(*frame));
  }
  const BracketCounters& c = rig.source->counters();
  EXPECT_EQ(c.groups, 4u);
  EXPECT_EQ(c.framesIn, 14u);
  EXPECT_EQ(c.framesDropped, 2u);
  EXPECT_EQ(c.droppedOutOfCycle, 2u);
  EXPECT_EQ(rig.camera->recycled, 14);  // every camera frame went back to the camera
  // The requests cycled in order, one per frame taken.
  ASSERT_GE(rig.camera->requests.size(), 7u);
  for (std::size_t i = 1; i < rig.camera->requests.size(); ++i) {
    EXPECT_DOUBLE_EQ(rig.camera->requests[i].first, 100.0 * std::exp2(2.0 * double((i - 1) % 3)));
  }
  expectInvariant(*rig.source);
}

TEST(BracketingSource, FramesAtABracketExposureBeforeTheCycleReachesThemAreDropped) {
  LdrFakeOptions options;
  options.initialExposureUs = 1600.0;  // the longest bracket exposure, out of order
  Rig rig = makeRig(options);
  auto frame = rig.source->next();
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(middleSeq(*rig.camera, frame->captureTsNs), 3u);
  EXPECT_EQ(rig.source->counters().droppedOutOfCycle, 2u);
}

TEST(BracketingSource, ALostFrameDropsItsGroupAndNoGroupSpansTheGap) {
  Rig rig = makeRig();
  rig.camera->lostFrames = {6};
  std::map<std::uint64_t, int> middles;
  for (int group = 0; group < 5; ++group) {
    auto frame = rig.source->next();
    ASSERT_TRUE(frame.has_value()) << frame.error().message;
    const std::uint64_t m = middleSeq(*rig.camera, frame->captureTsNs);
    // Every group is three delivered, consecutive frames.
    EXPECT_FALSE(rig.camera->lostFrames.contains(m - 1) || rig.camera->lostFrames.contains(m) ||
                 rig.camera->lostFrames.contains(m + 1))
        << "group around frame " << m;
    ++middles[m];
  }
  EXPECT_GE(rig.source->counters().droppedForGap, 1u);
  EXPECT_EQ(middles.count(6), 0u);
  expectInvariant(*rig.source);
}

TEST(BracketingSource, AFrameAtAnUnexpectedExposureDropsItsGroup) {
  Rig rig = makeRig();
  rig.camera->exposureOverrideUs = {{6, 700.0}};  // frame 6 should be the 400 us one
  std::vector<std::uint64_t> middles;
  for (int group = 0; group < 3; ++group) {
    auto frame = rig.source->next();
    ASSERT_TRUE(frame.has_value());
    middles.push_back(middleSeq(*rig.camera, frame->captureTsNs));
  }
  EXPECT_EQ(middles, (std::vector<std::uint64_t>{3, 9, 12}));  // the group 5, 6, 7 is gone
  const BracketCounters& c = rig.source->counters();
  EXPECT_EQ(c.droppedOutOfCycle, 2u + 3u);  // frames 0, 1; then 5, 6 and 7 (7 cannot start one)
  expectInvariant(*rig.source);
}

TEST(BracketingSource, InnerErrorsPassThroughAndResetTheGroupInProgress) {
  Rig rig = makeRig();
  rig.camera->errorsAtCall = {
      {3, vem::SourceError{vem::SourceErrorCause::NoDevice, "fake-ldr:cam0: camera unplugged"}}};
  auto error = rig.source->next();  // calls 0, 1, 2 give frames 0, 1 (dropped) and 2; call 3 fails
  ASSERT_FALSE(error.has_value());
  EXPECT_EQ(error.error().cause, vem::SourceErrorCause::NoDevice);
  EXPECT_EQ(error.error().message, "fake-ldr:cam0: camera unplugged");
  EXPECT_EQ(rig.source->counters().droppedForError, 1u);  // frame 2, the group's start
  auto frame = rig.source->next();                        // the stream goes on
  ASSERT_TRUE(frame.has_value()) << frame.error().message;
  EXPECT_EQ(frame->seq, 0u);
  expectInvariant(*rig.source);
}

TEST(BracketingSource, ACameraThatStopsTakingRequestsYieldsABadFrameSentenceNotAHang) {
  LdrFakeOptions options;
  options.latencyFrames = 0;
  Rig rig = makeRig(options);
  rig.camera->refuseRequests = true;  // stuck at the base exposure from now on
  auto result = rig.source->next();
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error().cause, vem::SourceErrorCause::BadFrame);
  EXPECT_NE(result.error().message.find("no complete bracket"), std::string::npos);
  EXPECT_NE(result.error().message.find("exposure is locked"), std::string::npos);
  EXPECT_GT(rig.source->counters().exposureRequestsRefused, 0u);
}

TEST(BracketingSource, InvalidSettingsAreRefusedWithASentence) {
  BracketSettings bad = threeByTwo();
  bad.count = 12;
  auto made = BracketingSource::create(makeCamera(), bad);
  ASSERT_FALSE(made.has_value());
  EXPECT_EQ(made.error().cause, vem::SourceErrorCause::NoDevice);
  EXPECT_EQ(made.error().message,
            "fake-ldr:cam0: bracketing count is 12: expected 2 to 9 exposures per group");
}

TEST(BracketingSource, ACameraWithoutExposureControlIsRefused) {
  auto camera = makeCamera();
  camera->refuseRequests = true;
  auto made = BracketingSource::create(std::move(camera), threeByTwo());
  ASSERT_FALSE(made.has_value());
  EXPECT_NE(made.error().message.find("takes no exposure requests"), std::string::npos);
}

// A source whose camera file has a log (HDR) response, or none.
class DescribedSource final : public vem::FrameSource {
 public:
  explicit DescribedSource(std::string toml) : toml_(std::move(toml)) {}
  vem::SourceDescription describe() const override {
    vem::SourceDescription d;
    d.spec = "described";
    d.pixelFormat = {3, 12};
    d.calibrationToml = toml_;
    return d;
  }
  std::expected<vem::CapturedFrame, vem::SourceError> next() override {
    return std::unexpected(vem::SourceError{vem::SourceErrorCause::Timeout, "none"});
  }
  void recycle(vem::CapturedFrame&&) override {}
  void interrupt() override {}
  std::expected<void, std::string> setExposure(double, double) override { return {}; }

 private:
  std::string toml_;
};

TEST(BracketingSource, AnHdrCameraOrOneWithoutCameraFileIsRefused) {
  const std::string logToml = calib::io::formatCameraFile(testing::cameraTruth(64, 48, 3));
  auto hdr = BracketingSource::create(std::make_unique<DescribedSource>(logToml), threeByTwo());
  ASSERT_FALSE(hdr.has_value());
  EXPECT_NE(hdr.error().message.find("log response"), std::string::npos);
  auto none = BracketingSource::create(std::make_unique<DescribedSource>(""), threeByTwo());
  ASSERT_FALSE(none.has_value());
  EXPECT_NE(none.error().message.find("no camera file"), std::string::npos);
}

TEST(BracketingSource, DescribesAVirtualLogCameraWhoseFileLoadsBackExactly) {
  Rig rig = makeRig();
  const vem::SourceDescription d = rig.source->describe();
  EXPECT_EQ(d.spec, "bracket:3@2+fake-ldr:cam0");
  EXPECT_EQ(d.pixelFormat, (vem::PixelFormat{3, 16}));
  EXPECT_DOUBLE_EQ(d.nominalRateHz, 10.0);
  EXPECT_EQ(d.cameraModel, "simulated LDR");
  auto loaded = calib::io::parseCameraFile(d.calibrationToml, d.spec);
  ASSERT_TRUE(loaded.has_value()) << loaded.error().message;
  ASSERT_TRUE(loaded->photometric.has_value());
  const auto& log = std::get<calib::LogResponse>(loaded->photometric->response);
  const VirtualHdrSensor& sensor = rig.source->sensor();
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_EQ(log.aCode[c], sensor.response.aCode[c]);
    EXPECT_EQ(log.bCodePerLn[c], sensor.response.bCodePerLn[c]);
  }
  EXPECT_EQ(loaded->photometric->saturationCode, 65535.0);
  EXPECT_EQ(loaded->photometric->blackLevelCode, 0.0);
  EXPECT_EQ(loaded->camera.pixelFormat, (vem::PixelFormat{3, 16}));
  ASSERT_TRUE(loaded->lens.has_value());
  EXPECT_EQ(loaded->lens->kPx, testing::wideLensTruth(kWidth, kHeight).kPx);
}

TEST(BracketingSource, InterruptForwardsAndExposureRequestsAreRefused) {
  Rig rig = makeRig();
  rig.source->interrupt();
  EXPECT_EQ(rig.camera->interrupts, 1);
  EXPECT_FALSE(rig.source->setExposure(1000.0, 1.0).has_value());
}

TEST(VirtualHdrSensor, SpansFromTheLongestNoiseFloorToTheShortestSaturation) {
  const calib::PhotometricCalibration ldr = calib::ldrCameraPhotometric(1000.0);
  const std::vector<double> exposures{100.0, 400.0, 1600.0, 6400.0, 25600.0};
  const calib::BracketWeighting w = bracketWeightingFor({3, 8});
  auto sensor = makeVirtualHdrSensor(ldr, {3, 8}, exposures, w);
  ASSERT_TRUE(sensor.has_value());
  const double lo = calib::luminanceFromCode(ldr, 0, 11.0, 25600.0, 1.0);
  const double hi = calib::luminanceFromCode(ldr, 0, 255.0, 100.0, 1.0);
  EXPECT_DOUBLE_EQ(sensor->minCdM2[0], lo);
  EXPECT_DOUBLE_EQ(sensor->maxCdM2[0], hi);
  const calib::PhotometricCalibration p = sensor->photometric();
  EXPECT_NEAR(calib::codeFromLuminance(p, 0, lo, 1.0, 1.0), 1.0, 1e-6);
  EXPECT_NEAR(calib::codeFromLuminance(p, 0, hi, 1.0, 1.0), 65535.0, 1e-6);
  // The quantisation step stated in virtual_hdr_sensor.h for 5 x 2 stops of an 8-bit camera.
  EXPECT_NEAR(sensor->relativeStep(), 1.9e-4, 0.1e-4);
  std::printf("[ sensor   ] 8-bit, 5 x 2 stops: %.3g to %.3g cd/m2 (%.1f stops), step %.3g\n", lo,
              hi, std::log2(hi / lo), sensor->relativeStep());

  // Encoding: below the range reads 0, above it 65535, both counted; inside, within half a step.
  calib::MergedBracket merged;
  merged.width = 4;
  merged.height = 1;
  merged.channels = 3;
  merged.luminanceCdM2 = {
      0.0F, float(lo * 0.5), float(lo),       float(hi * 2.0), float(hi), 1.0F, 2.0F,
      3.0F, -1.0F,           float(lo * 3.7), float(hi / 3.3), 1e-30F};
  vem::RawFrame out;
  const VirtualHdrMergeStats stats = encodeVirtualHdr(merged, *sensor, out);
  EXPECT_EQ(out.codes[0], 0);
  EXPECT_EQ(out.codes[1], 0);
  EXPECT_EQ(out.codes[2], 1);
  EXPECT_EQ(out.codes[3], 65535);
  EXPECT_EQ(out.codes[4], 65535);
  EXPECT_EQ(stats.darkSamples, 4u);  // 0, lo / 2, -1, 1e-30
  EXPECT_EQ(stats.saturatedSamples, 2u);
  for (std::size_t s : {5u, 6u, 7u, 9u, 10u}) {
    const int c = int(s % 3);
    const double read = calib::luminanceFromCode(p, c, out.codes[s], 1.0, 1.0);
    EXPECT_NEAR(read / double(merged.luminanceCdM2[s]), 1.0, 0.5 * sensor->relativeStep() + 1e-6)
        << s;
  }
}

}  // namespace
}  // namespace vem::cameras
