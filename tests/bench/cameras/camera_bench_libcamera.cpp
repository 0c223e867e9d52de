// benchLibcameraFakeCamera (camera_latency.h): the libcamera backend's path, LibcameraSource over
// FakeLibcameraPort (tests/cameras/libcamera/), into vemd's pipeline.
#include <cmath>
#include <memory>
#include <utility>

#include <fmt/format.h>

#include "bench/cameras/camera_latency.h"
#include "calib/io/camera_file.h"
#include "cameras/camera_settings.h"
#include "cameras/libcamera/libcamera_pixel_layout.h"
#include "cameras/libcamera/libcamera_source.h"
#include "fake_frame_generators.h"
#include "fake_libcamera_port.h"
#include "synth/default_camera.h"
#include "vemd/pipeline.h"
#include "vemd/pipeline_setup.h"

namespace vem::bench {

namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 1024;
constexpr int kWarmupFrames = 5;
constexpr double kRateHz = 30.0;

// The built-in example camera (1280 x 1024 log sensor behind a 190-degree fisheye) as a Mono16
// camera: what an HDR mono sensor on a libcamera pipeline delivers as R16.
std::expected<calib::CameraCalibration, std::string> monoExampleCamera() {
  auto camera = calib::io::parseCameraFile(std::string(synth::exampleCameraToml()),
                                           std::string(synth::kExampleCameraSource));
  if (!camera) return std::unexpected(camera.error().message);
  camera->camera.pixelFormat = {1, 16};
  return *camera;
}

}  // namespace

LatencyRun benchLibcameraFakeCamera(int frames) {
  LatencyRun run;
  run.path = "libcamera (fake camera behind LibcameraCameraPort)";
  auto camera = monoExampleCamera();
  if (!camera) {
    run.error = camera.error();
    return run;
  }
  const std::string toml = calib::io::formatCameraFile(*camera);

  cameras::testing::FakeLibcameraCamera fake;
  fake.formats = {{cameras::LibcameraRole::Raw, cameras::kLibcameraR16, {{kWidth, kHeight}}}};
  fake.framePeriodNs = std::llround(1e9 / kRateHz);
  auto port = std::make_unique<cameras::testing::FakeLibcameraPort>(
      fake, cameras::testing::syntheticFrames(*camera, "sky", kRateHz));

  cameras::CameraSettings settings;
  settings.pixelFormat = "Mono16";
  settings.buffers = 4;
  settings.timeoutMs = 2000;
  settings.calibrationToml = toml;
  auto source = cameras::LibcameraSource::open(std::move(port), "0", settings);
  if (!source) {
    run.error = source.error().message;
    return run;
  }
  auto pipeline =
      vemd::pipelineFromCameraFile(toml, "the example camera as Mono16", cameraBenchProcessing());
  if (!pipeline) {
    run.error = pipeline.error();
    return run;
  }
  run.notes = fmt::format(
      "R16 {}x{} Raw stream, {} buffers, frames rendered by the synthetic camera on the fake's "
      "thread at up to {} Hz; one copy from the mapped buffer into RawFrame (16-bit words)",
      kWidth, kHeight, settings.buffers, kRateHz);

  measureFrameToLights(**source, *pipeline, kWarmupFrames, frames, run);
  const cameras::LibcameraCounters counters = (*source)->counters();
  run.framesLost = counters.lost + counters.bad;
  return run;
}

}  // namespace vem::bench
