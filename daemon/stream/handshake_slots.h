// HandshakeSlots: the TCP connections still in their opening handshake (TLS, then the HTTP upgrade
// request), counted per source address, with the two caps that keep a flood of half-sent requests
// (a slowloris) from locking other clients out:
// - perAddress: a new connection from an address that already has that many handshakes pending is
//   refused (the server answers it 503 at once and closes it);
// - total: when every slot is taken, the oldest pending handshake of the address with the most
//   pending ones is evicted to make room, so a flood from a few addresses cannot hold all slots
//   and a newcomer from elsewhere always gets one.
// Together with the handshake deadline (StreamServerOptions::handshakeTimeout) a legitimate client
// gets through while a flood runs (tests/stream_e2e/flood_e2e_test.cpp).
//
// Connections are named by ids that increase with their arrival (older: smaller). Pure; not
// thread-safe (the server's io thread owns it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace vem::stream {

struct HandshakeAdmission {
  bool admitted = false;               // false: refused (perAddress reached)
  std::optional<std::uint64_t> evict;  // admitted by evicting this pending handshake
};

class HandshakeSlots {
 public:
  // Both caps at least 1.
  HandshakeSlots(std::size_t total, std::size_t perAddress);

  // A new connection `id` from `address`: admitted (perhaps evicting another, which the caller
  // closes and which is released here already) or refused.
  [[nodiscard]] HandshakeAdmission admit(const std::string& address, std::uint64_t id);
  // The handshake of `id` ended (upgraded, refused, failed, timed out); unknown ids are ignored.
  void release(std::uint64_t id);

  [[nodiscard]] std::size_t pending() const { return addressOf_.size(); }
  [[nodiscard]] std::size_t pendingFrom(const std::string& address) const;

 private:
  void erase(std::uint64_t id);

  std::size_t total_;
  std::size_t perAddress_;
  std::map<std::string, std::set<std::uint64_t>> byAddress_;  // oldest first
  std::map<std::uint64_t, std::string> addressOf_;
};

}  // namespace vem::stream
