#include "stream/handshake_slots.h"

#include <algorithm>
#include <tuple>

#include "util/contract.h"

namespace vem::stream {

HandshakeSlots::HandshakeSlots(std::size_t total, std::size_t perAddress)
    : total_(std::max<std::size_t>(total, 1)), perAddress_(std::max<std::size_t>(perAddress, 1)) {}

HandshakeAdmission HandshakeSlots::admit(const std::string& address, std::uint64_t id) {
  HandshakeAdmission admission;
  if (pendingFrom(address) >= perAddress_) return admission;
  if (addressOf_.size() >= total_) {
    // The address holding the most slots; among equals, the one whose oldest is the oldest.
    auto heaviest = byAddress_.end();
    for (auto it = byAddress_.begin(); it != byAddress_.end(); ++it) {
      if (heaviest == byAddress_.end() ||
          std::tuple(it->second.size(), -std::int64_t(*it->second.begin())) >
              std::tuple(heaviest->second.size(), -std::int64_t(*heaviest->second.begin()))) {
        heaviest = it;
      }
    }
    VEM_EXPECTS(heaviest != byAddress_.end());
    admission.evict = *heaviest->second.begin();
    erase(*admission.evict);
  }
  byAddress_[address].insert(id);
  addressOf_.emplace(id, address);
  admission.admitted = true;
  return admission;
}

void HandshakeSlots::release(std::uint64_t id) { erase(id); }

std::size_t HandshakeSlots::pendingFrom(const std::string& address) const {
  const auto it = byAddress_.find(address);
  return it == byAddress_.end() ? 0 : it->second.size();
}

void HandshakeSlots::erase(std::uint64_t id) {
  const auto it = addressOf_.find(id);
  if (it == addressOf_.end()) return;
  const auto slots = byAddress_.find(it->second);
  slots->second.erase(id);
  if (slots->second.empty()) byAddress_.erase(slots);
  addressOf_.erase(it);
}

}  // namespace vem::stream
