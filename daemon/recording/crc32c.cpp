#include "recording/crc32c.h"

#include <algorithm>
#include <climits>

#include <isa-l/crc.h>

namespace vem::recording {

std::uint32_t crc32c(std::span<const std::byte> bytes, std::uint32_t previous) {
  // ISA-L keeps the register un-inverted between calls and takes an int length.
  std::uint32_t state = ~previous;
  while (!bytes.empty()) {
    const std::size_t chunk = std::min<std::size_t>(bytes.size(), std::size_t(INT_MAX) & ~0xFFFu);
    // ISA-L's signature takes a non-const pointer but only reads the buffer.
    auto* data = const_cast<unsigned char*>(reinterpret_cast<const unsigned char*>(bytes.data()));
    state = crc32_iscsi(data, int(chunk), state);
    bytes = bytes.subspan(chunk);
  }
  return ~state;
}

}  // namespace vem::recording
