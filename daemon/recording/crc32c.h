// CRC32C (Castagnoli: polynomial 0x1EDC6F41, reflected, initial value and final xor 0xFFFFFFFF),
// the checksum of every VEM record (docs/vem-format.md). crc32c("123456789") = 0xE3069283.
//
// Computed by Intel's ISA-L (crc32_iscsi, SSE4.2/PCLMUL with a portable fallback): Boost.CRC's
// table-driven crc_optimal gives the same values but runs at about 0.45 GB/s, 3.3 ms for one
// compressed 1280 x 1024 frame, which alone would spend the whole 300 frames/s replay budget.
// The tests check this function against Boost.CRC.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace vem::recording {

// Chains: crc32c(b, crc32c(a)) == crc32c(a followed by b); crc32c({}) == 0.
[[nodiscard]] std::uint32_t crc32c(std::span<const std::byte> bytes, std::uint32_t previous = 0);

}  // namespace vem::recording
