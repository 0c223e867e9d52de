// AravisSession: one opened camera streaming into a pool of buffers: the device, the ArvCamera,
// its stream and settings in force. Private to the Aravis backend (it includes arv.h); the source
// (aravis_source.h) makes a new session after a camera was lost.
//
// - Opening: a dotted IPv4 id is opened directly (arv_gv_device_new toward the local address
//   that routes to it) after a unicast GVCP probe answers within the wait: no broadcast, ever.
//   Any other id goes through arv_open_device (USB3 Vision, then GigE Vision discovery, which
//   broadcasts on every interface when the id is not already known).
// - Events: the stream thread's BUFFER_DONE and the device's "control-lost" signal are passed to
//   a SessionEvents the caller owns, from Aravis's threads, until abandon() (after which the
//   events object may go) or destruction.
// - Closing: a healthy session stops acquisition. Closing an abandoned one (the camera is gone)
//   sends it nothing of ours, but Aravis's own teardown of the stream and device waits out GVCP
//   timeouts: about 7.5 s in Aravis 0.8.26, so the source closes those on a thread of their own.
#pragma once

#include <atomic>
#include <cstdint>
#include <expected>
#include <memory>
#include <string>

#include <arv.h>

#include "cameras/aravis/aravis_camera_setup.h"
#include "cameras/aravis/glib_object.h"
#include "cameras/camera_settings.h"

namespace vem::cameras {

class SessionEvents {
 public:
  virtual ~SessionEvents() = default;
  virtual void bufferDone() = 0;   // the stream thread filled (or gave up on) a buffer
  virtual void controlLost() = 0;  // the heartbeat found the camera gone
};

struct SessionIdentity {
  std::string model;  // vendor and model
  std::string serial;
};

class AravisSession {
 public:
  // Opens `id`, applies `settings` (exposure and gain too), queues settings.buffers buffers and
  // starts acquisition. `probeWaitMs` bounds the probe of an address. One sentence on failure.
  [[nodiscard]] static std::expected<std::unique_ptr<AravisSession>, std::string> open(
      const std::string& id, const CameraSettings& settings, int probeWaitMs,
      SessionEvents& events);
  ~AravisSession();
  AravisSession(const AravisSession&) = delete;
  AravisSession& operator=(const AravisSession&) = delete;

  // A finished buffer, waiting at most waitUs; nullptr when none. Give it back with push().
  [[nodiscard]] ArvBuffer* pop(std::uint64_t waitUs);
  void push(ArvBuffer* buffer);

  [[nodiscard]] ArvCamera* camera() const { return camera_.get(); }
  [[nodiscard]] const CameraGeometry& geometry() const { return geometry_; }
  [[nodiscard]] const SessionIdentity& identity() const { return identity_; }
  // The camera is gone: no more events; the destructor will not stop acquisition.
  void abandon() {
    abandoned_ = true;
    events_.store(nullptr);
  }
  void bufferDone();
  void controlLost();

 private:
  AravisSession(GObjectPtr<ArvDevice> device, SessionEvents& events);
  [[nodiscard]] std::expected<void, std::string> start(const CameraSettings& settings);

  std::atomic<SessionEvents*> events_;
  GObjectPtr<ArvDevice> device_;
  GObjectPtr<ArvCamera> camera_;
  GObjectPtr<ArvStream> stream_;
  gulong controlLostHandler_ = 0;
  CameraGeometry geometry_;
  SessionIdentity identity_;
  bool acquiring_ = false;
  bool abandoned_ = false;
};

}  // namespace vem::cameras
