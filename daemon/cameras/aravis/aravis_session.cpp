#include "cameras/aravis/aravis_session.h"

#include <algorithm>

#include <fmt/format.h>

#include "cameras/aravis/gvcp_probe.h"

namespace vem::cameras {

namespace {

void onStreamEvent(void* userData, ArvStreamCallbackType type, ArvBuffer* /*buffer*/) {
  if (type == ARV_STREAM_CALLBACK_TYPE_BUFFER_DONE)
    static_cast<AravisSession*>(userData)->bufferDone();
}

void onControlLost(ArvDevice* /*device*/, void* userData) {
  static_cast<AravisSession*>(userData)->controlLost();
}

std::expected<GObjectPtr<ArvDevice>, std::string> openByAddress(std::uint32_t address,
                                                                const std::string& id,
                                                                int probeWaitMs) {
  if (auto answered = probeGvcp(address, probeWaitMs); !answered) {
    return std::unexpected(answered.error());
  }
  auto local = localAddressToward(address);
  if (!local) return std::unexpected(local.error());
  GObjectPtr<GInetAddress> interfaceAddress(g_inet_address_new_from_string(local->c_str()));
  GObjectPtr<GInetAddress> deviceAddress(g_inet_address_new_from_string(id.c_str()));
  GErrorSlot error;
  GObjectPtr<ArvDevice> device(
      arv_gv_device_new(interfaceAddress.get(), deviceAddress.get(), error.out()));
  if (!device) {
    return std::unexpected(fmt::format("cannot open the GigE Vision camera at {}: {}", id,
                                       error ? error.message() : "no reason given"));
  }
  return device;
}

std::expected<GObjectPtr<ArvDevice>, std::string> openDevice(const std::string& id,
                                                             int probeWaitMs) {
  if (const auto address = parseIpv4(id)) return openByAddress(*address, id, probeWaitMs);
  GErrorSlot error;
  GObjectPtr<ArvDevice> device(arv_open_device(id.c_str(), error.out()));
  if (!device) {
    return std::unexpected(fmt::format("no camera \"{}\" found{}", id,
                                       error ? " (" + error.message() + ")" : std::string()));
  }
  return device;
}

std::string text(const char* value) {
  return value != nullptr ? std::string(value) : std::string();
}

}  // namespace

std::expected<std::unique_ptr<AravisSession>, std::string> AravisSession::open(
    const std::string& id, const CameraSettings& settings, int probeWaitMs, SessionEvents& events) {
  auto device = openDevice(id, probeWaitMs);
  if (!device) return std::unexpected(device.error());
  std::unique_ptr<AravisSession> session(new AravisSession(std::move(*device), events));
  if (auto started = session->start(settings); !started) return std::unexpected(started.error());
  return session;
}

AravisSession::AravisSession(GObjectPtr<ArvDevice> device, SessionEvents& events)
    : events_(&events), device_(std::move(device)) {
  controlLostHandler_ =
      g_signal_connect(device_.get(), "control-lost", G_CALLBACK(onControlLost), this);
}

void AravisSession::bufferDone() {
  if (SessionEvents* events = events_.load()) events->bufferDone();
}

void AravisSession::controlLost() {
  if (SessionEvents* events = events_.load()) events->controlLost();
}

std::expected<void, std::string> AravisSession::start(const CameraSettings& settings) {
  GErrorSlot error;
  // arv_camera_new_with_device takes its own reference to the device.
  camera_.reset(arv_camera_new_with_device(device_.get(), error.out()));
  if (!camera_) return std::unexpected("cannot make a camera of the device: " + error.message());
  identity_.model = fmt::format("{} {}", text(arv_camera_get_vendor_name(camera_.get(), nullptr)),
                                text(arv_camera_get_model_name(camera_.get(), nullptr)));
  identity_.serial = text(arv_camera_get_device_serial_number(camera_.get(), nullptr));

  auto geometry = applyGeometry(camera_.get(), settings);
  if (!geometry) return std::unexpected(geometry.error());
  geometry_ = *geometry;
  if (auto exposure = applyExposureGain(camera_.get(), settings.exposureUs, settings.gain);
      !exposure) {
    return std::unexpected(exposure.error());
  }
  if (arv_camera_is_gv_device(camera_.get())) {
    arv_camera_gv_auto_packet_size(camera_.get(), error.out());  // the largest the path carries
  }
  const guint payload = arv_camera_get_payload(camera_.get(), error.out());
  if (error) return std::unexpected("cannot read the camera's payload size: " + error.message());
  stream_.reset(arv_camera_create_stream(camera_.get(), onStreamEvent, this, error.out()));
  if (!stream_) return std::unexpected("cannot open the camera's stream: " + error.message());
  if (ARV_IS_GV_STREAM(stream_.get())) {
    g_object_set(stream_.get(), "socket-buffer", ARV_GV_STREAM_SOCKET_BUFFER_AUTO, nullptr);
  }
  for (int i = 0; i < std::max(2, settings.buffers); ++i) {
    arv_stream_push_buffer(stream_.get(), arv_buffer_new_allocate(payload));
  }
  arv_camera_set_acquisition_mode(camera_.get(), ARV_ACQUISITION_MODE_CONTINUOUS, error.out());
  arv_camera_start_acquisition(camera_.get(), error.out());
  if (error) return std::unexpected("cannot start acquisition: " + error.message());
  acquiring_ = true;
  return {};
}

AravisSession::~AravisSession() {
  if (acquiring_ && !abandoned_) arv_camera_stop_acquisition(camera_.get(), nullptr);
  if (controlLostHandler_ != 0) g_signal_handler_disconnect(device_.get(), controlLostHandler_);
  stream_.reset();  // joins the stream thread and frees the buffers
  camera_.reset();
  device_.reset();
}

ArvBuffer* AravisSession::pop(std::uint64_t waitUs) {
  return arv_stream_timeout_pop_buffer(stream_.get(), waitUs);
}

void AravisSession::push(ArvBuffer* buffer) { arv_stream_push_buffer(stream_.get(), buffer); }

}  // namespace vem::cameras
