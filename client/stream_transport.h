// StreamTransport: how a StreamClient reaches a camera's stream: WebSocket straight to vemd
// (websocket_transport.h) or MQTT through a broker (mqtt_transport.h). A transport runs its own
// network thread from its start function until stop(), and reports everything it receives and every
// change of state to the client's ClientState (client_state.h), which the StreamClient reads.
#pragma once

#include <future>

#include "client/stream_client.h"
#include "proto/vem_stream.pb.h"

namespace vem::client {

class StreamTransport {
 public:
  virtual ~StreamTransport() = default;
  StreamTransport() = default;
  StreamTransport(const StreamTransport&) = delete;
  StreamTransport& operator=(const StreamTransport&) = delete;

  // Ends the connection politely (bounded) and joins the network thread: no call into the
  // ClientState follows. Called once, after ClientState::markStopped().
  virtual void stop() = 0;
  // Sends a control message without waiting on the network; the future holds the reply or why
  // there is none (one sentence).
  [[nodiscard]] virtual std::future<ControlResult> sendControl(const stream::Control& control) = 0;
};

}  // namespace vem::client
