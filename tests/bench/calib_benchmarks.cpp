#include "calib_benchmarks.h"

#include <algorithm>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "calib/core/camera_simulator.h"
#include "calib/core/polar_remap.h"
#include "support/test_cameras.h"
#include "support/test_maps.h"

namespace vem::bench {
namespace {

constexpr int kSensorWidth = 1280;
constexpr int kSensorHeight = 1024;
constexpr int kMapWidth = 1024;
constexpr int kMapHeight = 256;

struct CalibFixture {
  calib::CameraCalibration camera;
  vem::RawFrame frame;
  calib::PolarRemap remap;
  calib::CodeToLuminanceLut lut;
  EnvMap map;

  explicit CalibFixture(vem::PixelFormat format)
      : camera(testing::cameraTruth(kSensorWidth, kSensorHeight, format.channels)) {
    camera.camera.pixelFormat = format;
    camera.photometric->saturationCode = format.maxCode();
    calib::SimulationOptions options;
    options.supersamples = 1;
    options.noise = {2.0, 0.0, 1};
    frame = calib::simulateFrame(
        calib::radianceFromMap(testing::proceduralSky(MapLayout::Sphere, 512, 256)), camera,
        options);
    remap = calib::buildPolarRemap(*camera.lens, camera.orientation, kSensorWidth, kSensorHeight,
                                   MapLayout::Hemisphere, kMapWidth, kMapHeight);
    lut = calib::buildCodeToLuminanceLut(*camera.photometric, format, 1000.0, 1.0);
  }
};

void registerCalib(const std::string& name, std::function<void(benchmark::State&)> body) {
  benchmark::RegisterBenchmark(("calib/" + name).c_str(), body)
      ->Unit(benchmark::kMicrosecond)
      ->ComputeStatistics("min", [](const std::vector<double>& v) {
        return *std::min_element(v.begin(), v.end());
      });
}

// The baseline: every sensor pixel through the table into a float image, then cv::remap
// (bilinear) with the same sensor positions as float maps.
void registerBaseline(const std::shared_ptr<CalibFixture>& f, const std::string& name) {
  const int channels = f->frame.format.channels;
  auto mapU = std::make_shared<cv::Mat>(kMapHeight, kMapWidth, CV_32FC1);
  auto mapV = std::make_shared<cv::Mat>(kMapHeight, kMapWidth, CV_32FC1);
  for (int y = 0; y < kMapHeight; ++y) {
    for (int x = 0; x < kMapWidth; ++x) {
      const std::size_t i = std::size_t(y) * kMapWidth + std::size_t(x);
      const std::uint32_t tap = f->remap.topLeftTap[i];
      const bool valid = tap != calib::PolarRemap::kInvalid;
      mapU->at<float>(y, x) = valid ? float(tap % kSensorWidth) + f->remap.fractionU[i] : -10.0f;
      mapV->at<float>(y, x) = valid ? float(tap / kSensorWidth) + f->remap.fractionV[i] : -10.0f;
    }
  }
  registerCalib(name, [f, mapU, mapV, channels](benchmark::State& s) {
    cv::Mat luminance(kSensorHeight, kSensorWidth, CV_32FC(channels));
    cv::Mat polar;
    for (auto _ : s) {
      float* out = luminance.ptr<float>();
      const std::size_t n = f->frame.codes.size();
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t c = i % std::size_t(channels);
        out[i] = f->lut.luminanceCdM2[c * f->lut.size + f->frame.codes[i]];
      }
      cv::remap(luminance, polar, *mapU, *mapV, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
      benchmark::DoNotOptimize(polar.data);
    }
  });
}

}  // namespace

void registerCalibrationBenchmarks() {
  for (const vem::PixelFormat format :
       {vem::PixelFormat{1, 16}, vem::PixelFormat{3, 16}, vem::PixelFormat{1, 12}}) {
    auto f = std::make_shared<CalibFixture>(format);
    const std::string suffix = vem::pixelFormatName(format);
    registerCalib("apply_" + suffix, [f](benchmark::State& s) {
      for (auto _ : s) {
        calib::applyPolarRemap(f->remap, f->frame, f->lut, f->map);
        benchmark::DoNotOptimize(f->map.rgb.data());
      }
    });
    registerBaseline(f, "baseline_" + suffix);
    registerCalib("lut_" + suffix, [f, format](benchmark::State& s) {
      for (auto _ : s) {
        benchmark::DoNotOptimize(
            calib::buildCodeToLuminanceLut(*f->camera.photometric, format, 1000.0, 1.0));
      }
    });
    if (format == vem::PixelFormat{1, 16}) {
      registerCalib("build_remap", [f](benchmark::State& s) {
        for (auto _ : s) {
          benchmark::DoNotOptimize(calib::buildPolarRemap(*f->camera.lens, f->camera.orientation,
                                                          kSensorWidth, kSensorHeight,
                                                          MapLayout::Hemisphere, kMapWidth,
                                                          kMapHeight));
        }
      });
    }
  }
}

}  // namespace vem::bench
