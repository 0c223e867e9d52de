// Handshake authorization: whether a WebSocket upgrade request may connect, and whether that
// connection may send control messages (docs/protocol.md, "Security").
//
// The token comes as "Authorization: Bearer T" or, for browsers that cannot set headers, as
// "?token=T" in the request target (percent-decoded). Tokens are compared in constant time.
// - A token presented that is not the configured one (or any token when none is configured): 401.
// - No token: 401 when the policy requires one to connect (a listener beyond loopback), else the
//   connection is accepted without control.
// - The right token: accepted with control.
// Pure: no I/O; no <expected>.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace vem::stream {

struct AuthPolicy {
  std::string token;                    // "": none configured (control is then never possible)
  bool tokenRequiredToConnect = false;  // true for a listener beyond loopback
};

struct HandshakeDecision {
  bool accept = false;
  bool controlAllowed = false;
  std::string refusal;  // the 401 body when !accept
};

// The token of an Authorization header value "Bearer T" (scheme case-insensitive), or nullopt.
[[nodiscard]] std::optional<std::string> bearerToken(std::string_view authorization);
// The percent-decoded value of the "token" query parameter of `target`, or nullopt.
[[nodiscard]] std::optional<std::string> queryToken(std::string_view target);
[[nodiscard]] bool tokensEqual(std::string_view a, std::string_view b);

// `presented`: the header's token, else the query's, else nullopt.
[[nodiscard]] HandshakeDecision decideHandshake(const AuthPolicy& policy,
                                                const std::optional<std::string>& presented);

}  // namespace vem::stream
