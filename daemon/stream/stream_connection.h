// The server's view of one WebSocket connection and of the server a session reports to
// (stream_server.h's internals; used only by stream_server.cpp and websocket_session.h).
// Everything here lives on the server's io thread.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "stream/client_message_handler.h"
#include "stream/cubemap_pacing.h"
#include "stream/outbox.h"
#include "stream/stream_server.h"
#include "stream/subscription.h"

namespace vem::stream {

// Who ended a connection: the server counts closes by this, never by the wording of `why`.
enum class ConnectionEndCause {
  ClosedByVemd,    // vemd closed it: its close frame, an oversized message, a send timeout
  ClosedByClient,  // the client's closing handshake
  Lost,            // the WebSocket handshake, a read or a write failed, or the client vanished
};

// How a connection ended: its cause, and one phrase for the log.
struct ConnectionEnd {
  ConnectionEndCause cause;
  std::string why;
};

// How the server paced one connection (client_lag.h).
struct ConnectionPacing {
  std::uint64_t holds = 0;          // times the server held messages because the client was behind
  bool tooSlow = false;             // closed for reading too slowly
  std::int64_t minRoundTripNs = 0;  // of the probes (0 before the first pong)
  std::int64_t maxRoundTripNs = 0;
};

class Connection {
 public:
  Connection(std::uint64_t id, bool controlAllowed, std::string peer)
      : id_(id), controlAllowed_(controlAllowed), peer_(std::move(peer)) {}
  virtual ~Connection() = default;
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  // Writes what the outbox holds, when no write is pending.
  virtual void wake() = 0;
  // Sends a close frame with `code` and `reason` (after the write in flight), then ends.
  virtual void closeWith(std::uint16_t code, std::string reason) = 0;
  [[nodiscard]] virtual ConnectionPacing pacing() const = 0;

  [[nodiscard]] std::uint64_t id() const { return id_; }
  [[nodiscard]] bool controlAllowed() const { return controlAllowed_; }
  [[nodiscard]] const std::string& peer() const { return peer_; }

  Outbox outbox;
  Subscription subscription;
  CubemapPacing environmentPacing;
  bool open = false;  // the WebSocket handshake completed

 private:
  std::uint64_t id_;
  bool controlAllowed_;
  std::string peer_;
};

// What a session tells the server; implemented by StreamServer::Impl.
class SessionHost {
 public:
  [[nodiscard]] virtual const StreamServerOptions& options() const = 0;
  // The WebSocket handshake completed.
  virtual void opened(Connection& connection) = 0;
  // The connection ended; called once.
  virtual void ended(Connection& connection, const ConnectionEnd& end) = 0;
  virtual void received(Connection& connection, ClientAction action) = 0;
  // The connection is being closed for reading too slowly (its close frame is on its way).
  virtual void tooSlow(Connection& connection, std::int64_t lagMs) = 0;

 protected:
  ~SessionHost() = default;
};

}  // namespace vem::stream
