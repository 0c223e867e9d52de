// AravisSource: a GenICam camera (GigE Vision or USB3 Vision) read through Aravis 0.8, as vemd's
// FrameSource (daemon/frames/frame_source.h); `vemd --source aravis:ID`. docs/cameras.md has the
// user's side (specs, network and USB set-up).
//
// - ID: a dotted IPv4 address ("192.168.1.20", "127.0.0.1") opens that GigE Vision camera
//   directly, never broadcasting (a unicast GVCP probe, then arv_gv_device_new); any other ID is
//   a device id as Aravis names it ("Basler-21234567", "Aravis-Fake-GV01"; `vemd --list-devices`
//   shows them) and is found through Aravis's discovery, which broadcasts on every interface.
// - Settings: CameraSettings (cameras/camera_settings.h) as aravis_camera_setup.h applies them:
//   pixel format, size, frame rate, exposure (us), gain (linear, converted to the camera's dB).
//   What the camera does not offer is refused at open() with one sentence (NoDevice).
// - Frames: a pool of settings.buffers Aravis buffers; each finished buffer is decoded
//   (aravis_pixel_formats.h: Mono8/10/12/16 incl. packed, RGB8) into the frame's codes and given
//   back to the stream at once; recycle() keeps spent frames' storage, so a steady stream
//   allocates nothing.
// - seq: the camera's frame id unwrapped (frame_id_unwrapper.h): strictly increasing across
//   16-bit wraps and reopens; gaps are frames lost before vemd saw them.
// - captureTsNs: Aravis's system timestamp of the buffer (when its first packet arrived on this
//   host), which Aravis 0.8 takes from g_get_real_time() (CLOCK_REALTIME, microseconds). It is
//   moved to CLOCK_MONOTONIC by the offset between the two clocks read at handover, so it is
//   comparable with arrivalNs (a clock step between arrival and handover shifts one frame's
//   timestamp by the step). arrivalNs is monotonicNowNs() at handover.
// - exposureUs, gain: read back from the camera after every change (setExposure); a frame carries
//   the new values when its whole exposure started after the change was read back, the old ones
//   before. With ExposureAuto or GainAuto on, they are read back for every frame.
// - Errors: a buffer that is not complete (missing packets, aborted, timeout, wrong size or
//   format) is BadFrame, counted in counters().incomplete. next() waits at most
//   settings.timeoutMs (Timeout); interrupt() from another thread ends one wait (kept when none
//   is under way). The camera is lost (NoDevice) when the control channel is lost or after
//   kTimeoutsBeforeLost timeouts in a row; each later next() makes one reopen attempt with the
//   same settings (the daemon backs off between calls) and streaming resumes when it succeeds.
//   A reopen by address blocks at most settings.timeoutMs when the camera is absent; one by
//   device id may take Aravis's discovery time (about 1 s). A lost camera's Aravis objects are
//   released on a thread of their own (Aravis 0.8.26 waits about 7.5 s of GVCP timeouts there);
//   the destructor joins those threads.
#pragma once

#include <cstdint>
#include <expected>
#include <memory>
#include <string>
#include <vector>

#include "cameras/camera_settings.h"
#include "frames/frame_source.h"

namespace vem::cameras {

struct AravisCounters {
  std::uint64_t completed = 0;   // frames delivered
  std::uint64_t incomplete = 0;  // buffers that came back unusable (BadFrame)
  std::uint64_t lost = 0;        // frame ids skipped: frames that never reached a buffer
  std::uint64_t reopened = 0;    // successful reopens after the camera was lost
};

class AravisSource final : public FrameSource {
 public:
  static constexpr int kTimeoutsBeforeLost = 3;

  // Opens the camera `id` (what follows "aravis:") with `settings` and starts streaming.
  // NoDevice with one sentence when it is absent or refuses the settings.
  [[nodiscard]] static std::expected<std::unique_ptr<AravisSource>, SourceError> open(
      const std::string& id, const CameraSettings& settings);
  ~AravisSource() override;
  AravisSource(const AravisSource&) = delete;
  AravisSource& operator=(const AravisSource&) = delete;

  [[nodiscard]] SourceDescription describe() const override;
  [[nodiscard]] std::expected<CapturedFrame, SourceError> next() override;
  void recycle(CapturedFrame&& spent) override;
  void interrupt() override;
  [[nodiscard]] std::expected<void, std::string> setExposure(double exposureUs,
                                                             double gain) override;

  // Any thread.
  [[nodiscard]] AravisCounters counters() const;

 private:
  struct Impl;
  explicit AravisSource(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace vem::cameras
