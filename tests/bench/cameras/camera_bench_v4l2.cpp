// benchV4l2FakeDevice (camera_latency.h): the V4L2 path with the in-process fake driver
// (tests/cameras/v4l2/fake_v4l2_camera.h) standing in for the kernel. Frames of the synthetic sky,
// rendered once through the example camera made Mono16 (1280 x 1024), are written as Y16 into the
// fake's mmap buffers; V4l2Source polls, dequeues, widens them into the RawFrame and requeues the
// buffer; vemd's pipeline then makes lights on the same thread. Latency: arrivalNs (V4l2Source
// handed the frame over, after its copy) to the lights being ready.
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "bench/cameras/camera_latency.h"
#include "calib/io/camera_file.h"
#include "cameras/v4l2/fake_v4l2_camera.h"
#include "cameras/v4l2/fake_v4l2_frames.h"
#include "cameras/v4l2/v4l2_source.h"
#include "synth/default_camera.h"
#include "synth/scene_factory.h"
#include "synth/synthetic_camera.h"
#include "vemd/pipeline.h"
#include "vemd/pipeline_setup.h"

namespace vem::bench {

namespace {

constexpr int kWidthPx = 1280;
constexpr int kHeightPx = 1024;
constexpr int kDistinctFrames = 8;
constexpr int kWarmUpFrames = 8;
constexpr int kBuffers = 4;

// The example camera (config/camera-example.toml) as a 16-bit mono sensor: its red channel's
// log response, codes 64 .. 4095 in a 16-bit container, as a Y16 camera delivers them.
std::expected<calib::CameraCalibration, std::string> monoExampleCamera() {
  auto camera = calib::io::parseCameraFile(std::string(synth::exampleCameraToml()),
                                           std::string(synth::kExampleCameraSource));
  if (!camera) return std::unexpected(camera.error().message);
  camera->camera.pixelFormat = vem::PixelFormat{1, 16};
  camera->camera.model = "Fake V4L2 Camera";
  return *camera;
}

// kDistinctFrames frames of the sky scene, 1/30 s apart, as Y16 buffers.
std::vector<std::vector<std::uint8_t>> skyBuffers(const calib::CameraCalibration& camera,
                                                  const v4l2_pix_format& format) {
  auto scene = synth::makeScene("sky", {});
  synth::SyntheticCamera renderer(camera);
  std::vector<std::vector<std::uint8_t>> buffers;
  vem::RawFrame frame;
  for (int i = 0; i < kDistinctFrames; ++i) {
    renderer.render((*scene)->at(double(i) / 30.0), std::uint64_t(i), frame);
    buffers.push_back(testing::encodeFakeFrame(frame.codes, format));
  }
  return buffers;
}

}  // namespace

LatencyRun benchV4l2FakeDevice(int frames) {
  LatencyRun run;
  run.path = "v4l2 (fake driver in process, Y16 1280x1024, mmap)";
  auto camera = monoExampleCamera();
  if (!camera) {
    run.error = camera.error();
    return run;
  }
  const std::string toml = calib::io::formatCameraFile(*camera);

  testing::FakeV4l2Config config;
  config.formats = {{V4L2_PIX_FMT_Y16, {{kWidthPx, kHeightPx}}}};
  testing::FakeV4l2Camera fake(config);
  const auto buffers = skyBuffers(*camera, fake.format());
  // As fast as taken: a buffer is filled (one memcpy of 2.6 MB) whenever the last frame was taken.
  fake.setGenerator(
      [&buffers](std::uint64_t index, const v4l2_pix_format&) {
        testing::FakeFrame f;
        f.bytes = buffers[index % buffers.size()];
        return f;
      },
      0);

  cameras::CameraSettings settings;
  settings.pixelFormat = "Mono16";
  settings.widthPx = kWidthPx;
  settings.heightPx = kHeightPx;
  settings.buffers = kBuffers;
  settings.calibrationToml = toml;
  auto source = cameras::V4l2Source::open("/dev/video0", fake.opener(), settings);
  if (!source) {
    run.error = source.error().message;
    return run;
  }
  auto pipeline =
      vemd::pipelineFromCameraFile((*source)->describe().calibrationToml,
                                   "the example camera as Mono16", cameraBenchProcessing());
  if (!pipeline) {
    run.error = pipeline.error();
    return run;
  }
  run.notes = fmt::format(
      "{} mmap buffers; Y16 widened into the frame before arrivalNs; the fake driver fills a "
      "buffer as soon as the last frame was taken (no pacing); synthetic sky through the example "
      "camera as Mono16",
      (*source)->bufferCount());

  measureFrameToLights(**source, *pipeline, kWarmUpFrames, frames, run);
  const cameras::V4l2Counters& counters = (*source)->counters();
  run.framesLost = counters.lost + counters.shortFrames + counters.corruptFrames;
  return run;
}

}  // namespace vem::bench
