#include "client/stream_url.h"

#include <charconv>
#include <optional>

#include <fmt/format.h>

namespace vem::client {
namespace {

std::unexpected<std::string> refuse(std::string_view url, std::string_view why) {
  return std::unexpected(fmt::format(
      "'{}' is not a stream address: {} (expected ws://HOST[:PORT][/PATH] or wss://...)", url, why));
}

bool isHostChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
         c == '.' || c == '_';
}

bool isIpv6Char(char c) {
  return (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F') || (c >= '0' && c <= '9') || c == ':' ||
         c == '.';
}

// HOST or [IPV6], optionally :PORT, into out.host (no brackets) and out.port; why not otherwise.
std::optional<std::string_view> parseHost(std::string_view& authority, StreamUrl& out) {
  if (!authority.starts_with("[")) {
    const std::size_t colon = authority.find(':');
    out.host = std::string(authority.substr(0, colon));
    authority.remove_prefix(colon == std::string_view::npos ? authority.size() : colon);
    for (char c : out.host) {
      if (!isHostChar(c)) return "its host has a bad character";
    }
    return std::nullopt;
  }
  const std::size_t close = authority.find(']');
  if (close == std::string_view::npos) return "its IPv6 address lacks a ']'";
  out.host = std::string(authority.substr(1, close - 1));
  authority.remove_prefix(close + 1);
  for (char c : out.host) {
    if (!isIpv6Char(c)) return "its IPv6 address has a bad character";
  }
  return std::nullopt;
}

std::optional<std::string_view> parseAuthority(std::string_view authority, StreamUrl& out) {
  if (authority.find('@') != std::string_view::npos) return "it has user info";
  if (auto bad = parseHost(authority, out)) return bad;
  if (out.host.empty()) return "it has no host";
  out.port = out.tls ? 443 : 80;
  if (authority.empty()) return std::nullopt;
  if (!authority.starts_with(":")) return "text follows its host";
  const std::string_view text = authority.substr(1);
  unsigned port = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), port);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size() || port == 0 ||
      port > 65535) {
    return "its port must be a number from 1 to 65535";
  }
  out.port = std::uint16_t(port);
  return std::nullopt;
}

}  // namespace

std::string StreamUrl::hostHeader() const {
  const bool ipv6 = host.find(':') != std::string::npos;
  return ipv6 ? fmt::format("[{}]:{}", host, port) : fmt::format("{}:{}", host, port);
}

std::expected<StreamUrl, std::string> parseStreamUrl(std::string_view url) {
  StreamUrl out;
  std::string_view rest = url;
  if (rest.starts_with("ws://")) {
    rest.remove_prefix(5);
  } else if (rest.starts_with("wss://")) {
    out.tls = true;
    rest.remove_prefix(6);
  } else {
    return refuse(url, "the scheme must be ws:// or wss://");
  }
  if (rest.find('#') != std::string_view::npos) return refuse(url, "it has a fragment");
  const std::size_t targetAt = rest.find_first_of("/?");
  if (targetAt != std::string_view::npos) {
    const std::string_view target = rest.substr(targetAt);
    out.target = fmt::format("{}{}", target.front() == '?' ? "/" : "", target);
  }
  if (auto bad = parseAuthority(rest.substr(0, targetAt), out)) return refuse(url, *bad);
  return out;
}

}  // namespace vem::client
