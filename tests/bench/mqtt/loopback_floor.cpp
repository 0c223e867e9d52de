#include "bench/mqtt/loopback_floor.h"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <span>
#include <thread>
#include <vector>

#include "bench/measurements.h"
#include "util/unique_fd.h"
#include "util/write_all.h"

namespace vem::bench {

namespace {

// Reads exactly `size` bytes; false at the end of the stream or an error.
bool readAll(int fd, char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::read(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= std::size_t(n);
  }
  return true;
}

// TCP_NODELAY, and reads that give up after 5 s (a stuck peer ends the measurement).
void configure(int fd) {
  const int one = 1;
  (void)::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  const timeval timeout{5, 0};
  (void)::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
}

sockaddr_in loopback(std::uint16_t port) {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  return address;
}

}  // namespace

std::expected<LoopbackLatency, std::string> loopbackLatency(std::size_t bytes,
                                                            std::size_t messages) {
  if (bytes < sizeof(std::int64_t)) bytes = sizeof(std::int64_t);
  util::UniqueFd listener(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  sockaddr_in address = loopback(0);
  socklen_t length = sizeof address;
  if (!listener.valid() ||
      ::bind(listener.get(), reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0 ||
      ::listen(listener.get(), 1) != 0 ||
      ::getsockname(listener.get(), reinterpret_cast<sockaddr*>(&address), &length) != 0) {
    return std::unexpected(std::string("cannot listen on 127.0.0.1: ") + std::strerror(errno));
  }
  util::UniqueFd sender(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  if (!sender.valid() ||
      ::connect(sender.get(), reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    return std::unexpected(std::string("cannot connect on 127.0.0.1: ") + std::strerror(errno));
  }
  util::UniqueFd receiver(::accept4(listener.get(), nullptr, nullptr, SOCK_CLOEXEC));
  if (!receiver.valid()) return std::unexpected(std::string("accept failed"));
  configure(sender.get());
  configure(receiver.get());

  std::vector<double> latenciesUs;
  latenciesUs.reserve(messages);
  std::thread reader([&] {
    std::vector<char> message(bytes);
    for (std::size_t i = 0; i < messages; ++i) {
      if (!readAll(receiver.get(), message.data(), bytes)) return;
      const std::int64_t receivedNs = realtimeNs();
      std::int64_t sentNs = 0;
      std::memcpy(&sentNs, message.data(), sizeof sentNs);
      latenciesUs.push_back(double(receivedNs - sentNs) * 1e-3);
      const char ack = 1;
      if (!util::writeAll(receiver.get(), std::as_bytes(std::span(&ack, 1)))) return;
    }
  });
  std::vector<char> message(bytes, 'x');
  for (std::size_t i = 0; i < messages; ++i) {
    const std::int64_t sentNs = realtimeNs();
    std::memcpy(message.data(), &sentNs, sizeof sentNs);
    char ack = 0;
    if (!util::writeAll(sender.get(), std::as_bytes(std::span(message))) ||
        !readAll(sender.get(), &ack, 1)) {
      break;
    }
  }
  (void)::shutdown(sender.get(), SHUT_RDWR);
  reader.join();
  if (latenciesUs.size() < messages) {
    return std::unexpected("the loopback connection ended after " +
                           std::to_string(latenciesUs.size()) + " messages");
  }
  return LoopbackLatency{bytes, messages, quantile(latenciesUs, 0.5), quantile(latenciesUs, 0.99)};
}

}  // namespace vem::bench
