#include "stream/stream_settings.h"

#include <charconv>
#include <utility>

#include <boost/asio/ip/address_v4.hpp>
#include <boost/asio/ip/address_v6.hpp>
#include <fmt/format.h>

namespace vem::stream {

std::string streamTokenExpected() {
  return fmt::format(
      "a token of {} to {} visible ASCII characters without white space (`openssl rand -hex 32` "
      "makes one)",
      kMinStreamTokenBytes, kMaxStreamTokenBytes);
}

std::optional<std::string> streamTokenProblem(std::string_view token) {
  for (std::size_t i = 0; i < token.size(); ++i) {
    const auto byte = static_cast<unsigned char>(token[i]);
    if (byte == ' ' || (byte >= '\t' && byte <= '\r')) {
      return fmt::format("white space at byte {} of {}", i + 1, token.size());
    }
    if (byte < 0x21 || byte > 0x7e) {
      return fmt::format("a control or non-ASCII byte at byte {} of {}", i + 1, token.size());
    }
  }
  if (token.size() < kMinStreamTokenBytes || token.size() > kMaxStreamTokenBytes) {
    return fmt::format("a token of {} byte{}", token.size(), token.size() == 1 ? "" : "s");
  }
  return std::nullopt;
}

std::optional<ListenAddress> parseListenAddress(const std::string& text) {
  const std::size_t colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0) return std::nullopt;
  std::string host = text.substr(0, colon);
  const std::string portText = text.substr(colon + 1);
  std::uint32_t port = 0;
  const auto [end, ec] = std::from_chars(portText.data(), portText.data() + portText.size(), port);
  if (portText.empty() || ec != std::errc() || end != portText.data() + portText.size() ||
      port > 65535) {
    return std::nullopt;
  }
  ListenAddress address;
  address.port = std::uint16_t(port);
  if (host.front() == '[') {
    if (host.size() < 3 || host.back() != ']') return std::nullopt;
    host = host.substr(1, host.size() - 2);
    // A literal address only: no scope ("%eth0"), which the listener would not take.
    if (host.find('%') != std::string::npos) return std::nullopt;
    boost::system::error_code error;
    const boost::asio::ip::address_v6 v6 = boost::asio::ip::make_address_v6(host, error);
    if (error) return std::nullopt;
    address.loopback = v6.is_loopback();  // ::1
  } else {
    boost::system::error_code error;
    const boost::asio::ip::address_v4 v4 = boost::asio::ip::make_address_v4(host, error);
    if (error) return std::nullopt;
    address.loopback = v4.is_loopback();  // 127.0.0.0/8
  }
  address.host = std::move(host);
  return address;
}

}  // namespace vem::stream
