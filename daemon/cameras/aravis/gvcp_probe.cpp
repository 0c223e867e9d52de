#include "cameras/aravis/gvcp_probe.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstring>

#include <fmt/format.h>
#include <boost/asio/ip/address_v4.hpp>

#include "util/unique_fd.h"

namespace vem::cameras {

namespace {

constexpr std::uint8_t kGvcpKey = 0x42;
constexpr std::uint8_t kFlagAckRequired = 0x01;
constexpr std::uint16_t kReadRegCmd = 0x0080;
constexpr std::uint16_t kReadRegAck = 0x0081;
constexpr std::uint32_t kVersionRegister = 0x0000;
constexpr std::uint16_t kProbeRequestId = 0x7e11;

// A new UDP socket (invalid when socket(2) failed, errno set).
util::UniqueFd openUdpSocket() {
  return util::UniqueFd(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0));
}

sockaddr_in socketAddress(std::uint32_t address, std::uint16_t port) {
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(port);
  sa.sin_addr.s_addr = htonl(address);
  return sa;
}

std::string dotted(std::uint32_t address) {
  return fmt::format("{}.{}.{}.{}", address >> 24, (address >> 16) & 0xff, (address >> 8) & 0xff,
                     address & 0xff);
}

std::expected<void, std::string> connectTo(const util::UniqueFd& socket, std::uint32_t address) {
  if (!socket.valid())
    return std::unexpected(fmt::format("cannot open a UDP socket: {}", std::strerror(errno)));
  const sockaddr_in sa = socketAddress(address, kGvcpPort);
  if (::connect(socket.get(), reinterpret_cast<const sockaddr*>(&sa), sizeof sa) != 0) {
    return std::unexpected(
        fmt::format("no route to {} ({})", dotted(address), std::strerror(errno)));
  }
  return {};
}

bool isOurAck(const std::uint8_t* reply, ssize_t size) {
  if (size < 8) return false;
  const std::uint16_t answer = std::uint16_t((reply[2] << 8) | reply[3]);
  const std::uint16_t ackId = std::uint16_t((reply[6] << 8) | reply[7]);
  return answer == kReadRegAck && ackId == kProbeRequestId;
}

}  // namespace

std::optional<std::uint32_t> parseIpv4(const std::string& text) {
  boost::system::error_code error;
  const boost::asio::ip::address_v4 address = boost::asio::ip::make_address_v4(text, error);
  if (error) return std::nullopt;
  return address.to_uint();
}

std::expected<std::string, std::string> localAddressToward(std::uint32_t deviceAddress) {
  const util::UniqueFd socket = openUdpSocket();
  if (auto connected = connectTo(socket, deviceAddress); !connected) {
    return std::unexpected(connected.error());
  }
  sockaddr_in local{};
  socklen_t size = sizeof local;
  if (::getsockname(socket.get(), reinterpret_cast<sockaddr*>(&local), &size) != 0) {
    return std::unexpected(fmt::format("cannot find the local address toward {} ({})",
                                       dotted(deviceAddress), std::strerror(errno)));
  }
  return dotted(ntohl(local.sin_addr.s_addr));
}

std::expected<void, std::string> probeGvcp(std::uint32_t deviceAddress, int waitMs) {
  const util::UniqueFd socket = openUdpSocket();
  if (auto connected = connectTo(socket, deviceAddress); !connected) {
    return std::unexpected(connected.error());
  }
  const std::array<std::uint8_t, 12> request{kGvcpKey,
                                             kFlagAckRequired,
                                             kReadRegCmd >> 8,
                                             kReadRegCmd & 0xff,
                                             0,
                                             4,
                                             kProbeRequestId >> 8,
                                             kProbeRequestId & 0xff,
                                             kVersionRegister >> 24,
                                             (kVersionRegister >> 16) & 0xff,
                                             (kVersionRegister >> 8) & 0xff,
                                             kVersionRegister & 0xff};
  if (::send(socket.get(), request.data(), request.size(), 0) < 0) {
    return std::unexpected(fmt::format("cannot send to {}:{} ({})", dotted(deviceAddress),
                                       kGvcpPort, std::strerror(errno)));
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(waitMs);
  std::array<std::uint8_t, 576> reply{};
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd pfd{socket.get(), POLLIN, 0};
    if (left.count() <= 0 || ::poll(&pfd, 1, int(left.count())) <= 0) break;
    const ssize_t got = ::recv(socket.get(), reply.data(), reply.size(), 0);
    if (got < 0 && errno == ECONNREFUSED) break;  // nothing listens on that port
    if (isOurAck(reply.data(), got)) return {};
  }
  return std::unexpected(fmt::format("no GigE Vision camera answers at {} (GVCP, UDP port {})",
                                     dotted(deviceAddress), kGvcpPort));
}

}  // namespace vem::cameras
