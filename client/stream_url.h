// The address of a vemd stream: ws://HOST[:PORT][/PATH][?QUERY] or wss://... (TLS), as
// `vemtool subscribe` and vemview take it. HOST is a name, an IPv4 address or a bracketed IPv6
// address ([::1]); PORT defaults to 80 (ws) or 443 (wss); the target defaults to "/". Anything
// else (another scheme, user info, a fragment, a bad port) is refused with one sentence.
// Pure; the parser is small because Boost.URL is not in Debian 12's Boost 1.74.
#pragma once

#include <cstdint>
#include <expected>
#include <string>
#include <string_view>

namespace vem::client {

struct StreamUrl {
  bool tls = false;     // wss://
  std::string host;     // as given, without IPv6 brackets: what the resolver and TLS names use
  std::uint16_t port = 0;
  std::string target = "/";  // path and query, as sent in the handshake's request line

  // The Host header's value: host (bracketed when IPv6) and ":port".
  [[nodiscard]] std::string hostHeader() const;
};

[[nodiscard]] std::expected<StreamUrl, std::string> parseStreamUrl(std::string_view url);

}  // namespace vem::client
