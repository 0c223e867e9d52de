// StreamSettings: the stream server's settings as vemd's [stream] section gives them
// (config/vemd.toml documents every key), and the rules for the values that need one: what a
// token must be and what a listen address looks like. vemd's configuration (vemd/vemd_config.h)
// holds a StreamSettings as its StreamConfig; the stream's setup (stream_setup.h) reads it.
//
// Units are in the names: ...Ms milliseconds, ...Hz per second, ...Px pixels, ...Bytes bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace vem::stream {

// [stream]: the WebSocket server for render clients (stream_server.h, docs/protocol.md). Listening
// beyond loopback needs a token (checked when the file is read), and a token given here must pass
// streamTokenProblem (below).
struct StreamSettings {
  bool enabled = true;
  std::string listen = "127.0.0.1:8765";  // "IPV4:PORT" or "[IPV6]:PORT"; port 0: any; "": off
  std::string token;                      // the bearer token; "": none (or token_file)
  std::string tokenFile;  // a file holding the token; must not be readable by group or others
  std::string tlsCert;    // PEM certificate chain: wss:// (with tls_key)
  std::string tlsKey;     // PEM private key
  std::int64_t maxClients = 64;
  std::int64_t sendTimeoutMs = 10'000;  // a send pending longer closes that client
  std::int64_t cubemapZstdLevel = 3;
  std::int64_t handshakeTimeoutMs = 3'000;    // TLS + upgrade request must end within
  std::int64_t maxHandshakes = 128;           // connections in their handshake at most
  std::int64_t maxHandshakesPerAddress = 32;  // of those from one address (more: 503)
  std::int64_t maxClientLagMs = 5'000;        // a client further behind is closed
  std::int64_t sendBufferBytes = 256 * 1024;  // SO_SNDBUF of each client socket
  std::int64_t cubemapMaxFacePx = 256;        // for clients without the token
  double cubemapMaxRateHz = 10.0;             // for clients without the token
  std::string recordDir;  // where control's start_recording writes; "": output.record's folder
                          // (when it is one), else output.dir
  friend bool operator==(const StreamSettings&, const StreamSettings&) = default;
};

// What vemd accepts as a stream token (stream.token, or the contents of stream.token_file), on
// every listener: on loopback too, where the token grants control (light count, filter,
// recordings) and any local user can connect. 16 visible ASCII characters are at least 64 bits
// even as hex, beyond guessing through WebSocket handshakes, and refuse typed words ("secret");
// `openssl rand -hex 32` makes a 64-character (256-bit) one. White space and control or non-ASCII
// bytes are refused: HTTP trims or mangles them, so no client could present such a token. At most
// 1024 bytes, so "Authorization: Bearer TOKEN" fits an HTTP request head.
inline constexpr std::size_t kMinStreamTokenBytes = 16;
inline constexpr std::size_t kMaxStreamTokenBytes = 1024;
// "a token of 16 to 1024 visible ASCII characters ...", for messages.
[[nodiscard]] std::string streamTokenExpected();
// What is wrong with `token` ("a token of 3 bytes", "white space at byte 5"), never quoting it (it
// is a secret); nullopt when vemd accepts it.
[[nodiscard]] std::optional<std::string> streamTokenProblem(std::string_view token);

// A parsed [stream] listen value.
struct ListenAddress {
  std::string host;  // the IP address without brackets
  std::uint16_t port = 0;
  bool loopback = false;  // 127.0.0.0/8 or ::1
};
// "127.0.0.1:8765", "[::1]:0", "0.0.0.0:8765"; nullopt when not of that form.
[[nodiscard]] std::optional<ListenAddress> parseListenAddress(const std::string& text);

}  // namespace vem::stream
