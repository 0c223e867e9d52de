#include "stream/handshake_auth.h"

#include <openssl/crypto.h>

#include <cctype>

namespace vem::stream {

namespace {

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string percentDecoded(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size()) {
      const int high = hexValue(text[i + 1]);
      const int low = hexValue(text[i + 2]);
      if (high >= 0 && low >= 0) {
        out.push_back(char(high * 16 + low));
        i += 2;
        continue;
      }
    }
    out.push_back(text[i] == '+' ? ' ' : text[i]);
  }
  return out;
}

}  // namespace

std::optional<std::string> bearerToken(std::string_view authorization) {
  constexpr std::string_view kScheme = "bearer ";
  if (authorization.size() <= kScheme.size()) return std::nullopt;
  for (std::size_t i = 0; i < kScheme.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(authorization[i])) != kScheme[i]) {
      return std::nullopt;
    }
  }
  std::string_view token = authorization.substr(kScheme.size());
  while (!token.empty() && token.front() == ' ') token.remove_prefix(1);
  while (!token.empty() && token.back() == ' ') token.remove_suffix(1);
  if (token.empty()) return std::nullopt;
  return std::string(token);
}

std::optional<std::string> queryToken(std::string_view target) {
  const std::size_t question = target.find('?');
  if (question == std::string_view::npos) return std::nullopt;
  std::string_view query = target.substr(question + 1);
  while (!query.empty()) {
    const std::size_t amp = query.find('&');
    const std::string_view pair = query.substr(0, amp);
    if (pair.starts_with("token=")) return percentDecoded(pair.substr(6));
    if (amp == std::string_view::npos) break;
    query.remove_prefix(amp + 1);
  }
  return std::nullopt;
}

bool tokensEqual(std::string_view a, std::string_view b) {
  // Constant time in the contents, through OpenSSL (the length of the configured token is not a
  // secret worth hiding: it is compared first).
  if (a.size() != b.size()) return false;
  return CRYPTO_memcmp(a.data(), b.data(), a.size()) == 0;
}

HandshakeDecision decideHandshake(const AuthPolicy& policy,
                                  const std::optional<std::string>& presented) {
  HandshakeDecision decision;
  if (presented) {
    if (!policy.token.empty() && tokensEqual(*presented, policy.token)) {
      decision.accept = true;
      decision.controlAllowed = true;
    } else {
      decision.refusal = "the token is wrong";
    }
    return decision;
  }
  if (policy.tokenRequiredToConnect) {
    decision.refusal = "this server needs a token (Authorization: Bearer T, or ?token=T)";
    return decision;
  }
  decision.accept = true;
  return decision;
}

}  // namespace vem::stream
