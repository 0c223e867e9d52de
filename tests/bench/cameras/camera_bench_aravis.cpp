// benchAravisFakeCamera (camera_latency.h): Aravis's own fake GigE Vision camera on 127.0.0.1
// serving 1280 x 1024 Mono16 frames of the synthetic sky, read by AravisSource over GVCP/GVSP on
// loopback, each turned into lights by vemd's pipeline on the same thread. Runs only where no
// network interface but loopback is up (the bench's network namespace): the fake camera and
// Aravis must never reach a real network.
#include <arv.h>
#include <ifaddrs.h>
#include <net/if.h>

#include <cmath>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/cameras/camera_latency.h"
#include "calib/io/camera_file.h"
#include "cameras/aravis/aravis_source.h"
#include "support/test_cameras.h"
#include "synth/sky_scene.h"
#include "synth/synthetic_camera.h"
#include "vemd/pipeline.h"
#include "vemd/pipeline_setup.h"

namespace vem::bench {
namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 1024;
constexpr double kRateHz = 20.0;
constexpr int kBuffers = 4;
constexpr int kWarmUpFrames = 10;
constexpr int kDistinctFrames = 4;
constexpr std::uint32_t kMono16Code = 0x01100007u;  // PFNC Mono16

// The test camera's lens with the log response spread over 16-bit codes (black 1024 .. 65535).
calib::CameraCalibration mono16Camera() {
  calib::CameraCalibration camera = testing::cameraTruth(kWidth, kHeight, 1);
  camera.camera.pixelFormat = {1, 16};
  calib::PhotometricCalibration& p = *camera.photometric;
  p.blackLevelCode = 1024.0;
  p.saturationCode = 65535.0;
  const double b = (65535.0 - 1024.0) / std::log(1e8);
  calib::LogResponse log;
  for (std::size_t c = 0; c < 3; ++c) {
    log.bCodePerLn[c] = b;
    log.aCode[c] = 1024.0 + b * std::log(1e3);
  }
  p.response = log;
  return camera;
}

// Non-loopback interfaces that are up (empty inside the bench's namespace).
std::string interfaceUp() {
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) != 0) return "(getifaddrs failed)";
  std::string up;
  for (ifaddrs* i = list; i != nullptr && up.empty(); i = i->ifa_next) {
    if ((i->ifa_flags & IFF_UP) != 0 && (i->ifa_flags & IFF_LOOPBACK) == 0) up = i->ifa_name;
  }
  freeifaddrs(list);
  return up;
}

// The frames the fake camera draws in turn, as Mono16 little-endian bytes.
struct FramePlayer {
  std::mutex mutex;
  std::vector<std::vector<std::uint8_t>> frames;
  std::size_t next = 0;

  static void fill(ArvBuffer* buffer, void* self, guint32 /*exposureUs*/, guint32 /*gain*/,
                   ArvPixelFormat pixelFormat) {
    auto* player = static_cast<FramePlayer*>(self);
    std::lock_guard lock(player->mutex);
    if (pixelFormat != kMono16Code || arv_buffer_get_image_width(buffer) != kWidth ||
        arv_buffer_get_image_height(buffer) != kHeight || player->frames.empty()) {
      return;
    }
    const auto& bytes = player->frames[player->next++ % player->frames.size()];
    std::size_t size = 0;
    auto* data = static_cast<std::uint8_t*>(const_cast<void*>(arv_buffer_get_data(buffer, &size)));
    std::memcpy(data, bytes.data(), bytes.size());
  }
};

std::vector<std::uint8_t> littleEndianBytes(const std::vector<std::uint16_t>& codes) {
  std::vector<std::uint8_t> out(codes.size() * 2);
  for (std::size_t i = 0; i < codes.size(); ++i) {
    out[2 * i] = std::uint8_t(codes[i] & 0xff);
    out[2 * i + 1] = std::uint8_t(codes[i] >> 8);
  }
  return out;
}

struct FakeCameraDeleter {
  void operator()(ArvGvFakeCamera* camera) const { g_object_unref(camera); }
};

}  // namespace

LatencyRun benchAravisFakeCamera(int frames) {
  LatencyRun run;
  run.path = "aravis (fake GigE Vision camera, 127.0.0.1)";
  run.notes = fmt::format(
      "{}x{} Mono16 at {} Hz over loopback (GVSP, packet size as Aravis negotiates), {} "
      "buffers, frames decoded into 16-bit codes by the backend; latency from handover to lights",
      kWidth, kHeight, kRateHz, kBuffers);
  if (const std::string up = interfaceUp(); !up.empty()) {
    run.error = fmt::format(
        "refused: interface {} is up; run inside a network namespace with "
        "loopback only (unshare -n)",
        up);
    return run;
  }
  const calib::CameraCalibration camera = mono16Camera();
  const std::string cameraToml = calib::io::formatCameraFile(camera);
  FramePlayer player;
  {
    synth::SyntheticCamera simulated(camera);
    const synth::SkyScene scene;
    for (int i = 0; i < kDistinctFrames; ++i) {
      player.frames.push_back(
          littleEndianBytes(simulated.render(scene.at(2.0 * i), std::uint64_t(i)).codes));
    }
  }
  std::unique_ptr<ArvGvFakeCamera, FakeCameraDeleter> fake(
      arv_gv_fake_camera_new_full("lo", "VEMBENCH", nullptr));
  if (!fake || !arv_gv_fake_camera_is_running(fake.get())) {
    run.error = "the fake GigE Vision camera did not start on lo";
    return run;
  }
  arv_fake_camera_set_fill_pattern(arv_gv_fake_camera_get_fake_camera(fake.get()),
                                   &FramePlayer::fill, &player);

  cameras::CameraSettings settings;
  settings.pixelFormat = "Mono16";
  settings.widthPx = kWidth;
  settings.heightPx = kHeight;
  settings.frameRateHz = kRateHz;
  settings.buffers = kBuffers;
  settings.timeoutMs = 1000;
  settings.calibrationToml = cameraToml;
  auto source = cameras::AravisSource::open("127.0.0.1", settings);
  if (!source) {
    run.error = source.error().message;
    return run;
  }
  auto pipeline = vemd::pipelineFromCameraFile((*source)->describe().calibrationToml,
                                               "aravis bench", cameraBenchProcessing());
  if (!pipeline) {
    run.error = pipeline.error();
    return run;
  }
  measureFrameToLights(**source, *pipeline, kWarmUpFrames, frames, run);
  const cameras::AravisCounters counters = (*source)->counters();
  run.framesLost = counters.incomplete + counters.lost;
  return run;
}

}  // namespace vem::bench
