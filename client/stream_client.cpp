#include "client/stream_client.h"

#include <utility>

#include <fmt/format.h>

#include "client/client_state.h"
#include "client/mqtt_transport.h"
#include "client/mqtt_url.h"
#include "client/stream_transport.h"
#include "client/websocket_transport.h"

namespace vem::client {

std::string_view connectionStateName(ConnectionState state) {
  switch (state) {
    case ConnectionState::Connecting: return "connecting";
    case ConnectionState::Connected: return "connected";
    case ConnectionState::Waiting: return "waiting";
    case ConnectionState::Refused: return "refused";
    case ConnectionState::Stopped: return "stopped";
  }
  return "unknown";
}

// The options, what the client knows (shared by both transports) and the transport, destroyed in
// the reverse order: the transport borrows the other two.
struct StreamClient::Impl {
  explicit Impl(StreamClientOptions o) : options(std::move(o)), state(options) {}
  StreamClientOptions options;
  ClientState state;
  std::unique_ptr<StreamTransport> transport;
};

StreamClient::StreamClient(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

StreamClient::~StreamClient() { stop(); }

std::expected<std::unique_ptr<StreamClient>, std::string> StreamClient::start(
    StreamClientOptions options) {
  auto impl = std::make_unique<Impl>(std::move(options));
  const std::string& url = impl->options.url;
  if (!url.starts_with("ws://") && !url.starts_with("wss://") && !isMqttUrl(url)) {
    return std::unexpected(fmt::format(
        "'{}' is not a stream address: the scheme must be ws://, wss://, mqtt:// or mqtts:// "
        "(expected ws://HOST[:PORT][/PATH] or mqtt://[USER@]HOST[:PORT]/PREFIX/CAMERA)",
        url));
  }
  auto transport = isMqttUrl(url) ? startMqttTransport(impl->options, impl->state)
                                  : startWebSocketTransport(impl->options, impl->state);
  if (!transport) return std::unexpected(transport.error());
  impl->transport = std::move(*transport);
  return std::unique_ptr<StreamClient>(new StreamClient(std::move(impl)));
}

void StreamClient::stop() {
  Impl& i = *impl_;
  if (!i.state.markStopped()) return;
  i.transport->stop();
  i.state.failPendingControls("the client stopped before the daemon replied");
  i.state.finishStopped();
}

ConnectionState StreamClient::state() const { return impl_->state.state(); }

std::string StreamClient::stateReason() const { return impl_->state.stateReason(); }

std::optional<Hello> StreamClient::hello() const { return impl_->state.hello(); }

std::optional<Status> StreamClient::status() const { return impl_->state.status(); }

std::optional<Received<LightFrame>> StreamClient::latestLightFrame() const {
  return impl_->state.latestLightFrame();
}

std::optional<Received<EnvironmentFrame>> StreamClient::latestEnvironmentFrame() const {
  return impl_->state.latestEnvironmentFrame();
}

ClientStats StreamClient::stats() const { return impl_->state.stats(); }

std::optional<Received<LightFrame>> StreamClient::waitForLightFrame(
    std::optional<std::uint64_t> afterSeq, std::chrono::milliseconds timeout) const {
  return impl_->state.waitForLightFrame(afterSeq, timeout);
}

bool StreamClient::waitForState(ConnectionState state, std::chrono::milliseconds timeout) const {
  return impl_->state.waitForState(state, timeout);
}

std::future<ControlResult> StreamClient::sendControl(const stream::Control& control) {
  return impl_->transport->sendControl(control);
}

}  // namespace vem::client
