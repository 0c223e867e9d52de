// The WebSocket transport of a StreamClient (stream_transport.h): straight to vemd over ws:// or
// wss:// (Boost.Beast; TLS through OpenSSL, the peer verified against the system's CAs or
// options.caFile, and its host name). It sends `Authorization: Bearer TOKEN` when it has a token,
// subscribes after the daemon's Hello (the connection is Connected then), and decodes every message
// (server_message_decoder.h). When the connection fails or drops, or a message is refused (the
// connection is closed with status 1002 and the reason), it reconnects after an exponential backoff
// (util/backoff.h); it stops for good, Refused with one sentence, when the daemon speaks another
// protocol major or refuses the token (HTTP 401 or 403). stop() closes with a closing handshake
// (code 1000; the socket is dropped if the daemon does not answer within 1 s).
#pragma once

#include <expected>
#include <memory>
#include <string>

#include "client/client_state.h"
#include "client/stream_transport.h"

namespace vem::client {

// Checks the URL (stream_url.h) and the CA file and starts the I/O thread; one sentence when they
// are unusable. Borrows `options` and `state`, which must outlive the transport.
[[nodiscard]] std::expected<std::unique_ptr<StreamTransport>, std::string> startWebSocketTransport(
    const StreamClientOptions& options, ClientState& state);

}  // namespace vem::client
