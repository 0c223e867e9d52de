// Test side of the wire formats: packs RawFrame codes into the bytes a GenICam camera sends, per
// the layouts aravis_pixel_formats.h states (written from the specifications, independently of the
// backend's decoders, so the two check each other).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace vem::testing {

// Packs `codes` as the GenICam pixel format `genicamName` (Mono8, Mono10, Mono12, Mono16, RGB8,
// Mono10Packed, Mono12Packed, Mono10p, Mono12p); empty for any other name.
[[nodiscard]] std::vector<std::uint8_t> packPixels(std::string_view genicamName,
                                                   const std::vector<std::uint16_t>& codes);

}  // namespace vem::testing
