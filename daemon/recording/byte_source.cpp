#include "recording/byte_source.h"

#include <cstring>

#include "util/contract.h"

namespace vem::recording {

bool MemoryByteSource::readAt(std::uint64_t offset, std::span<std::byte> out) {
  VEM_EXPECTS(offset <= bytes_.size() && out.size() <= bytes_.size() - offset);
  if (!out.empty()) std::memcpy(out.data(), bytes_.data() + offset, out.size());
  return true;
}

}  // namespace vem::recording
