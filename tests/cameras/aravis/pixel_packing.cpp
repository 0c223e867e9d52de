#include "pixel_packing.h"

namespace vem::testing {

namespace {

std::vector<std::uint8_t> bytes(const std::vector<std::uint16_t>& codes) {
  return {codes.begin(), codes.end()};
}

std::vector<std::uint8_t> littleEndianWords(const std::vector<std::uint16_t>& codes) {
  std::vector<std::uint8_t> out;
  for (std::uint16_t c : codes) {
    out.push_back(std::uint8_t(c & 0xff));
    out.push_back(std::uint8_t(c >> 8));
  }
  return out;
}

// GigE Vision Mono10Packed / Mono12Packed: per pixel pair, [p0 high 8][p1 low | p0 low][p1 high 8].
std::vector<std::uint8_t> gigeVisionPacked(const std::vector<std::uint16_t>& codes, int bits) {
  const int low = bits - 8;
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i < codes.size(); i += 2) {
    const unsigned p0 = codes[i];
    const unsigned p1 = i + 1 < codes.size() ? codes[i + 1] : 0;
    out.push_back(std::uint8_t(p0 >> low));
    out.push_back(std::uint8_t((p0 & ((1u << low) - 1)) | ((p1 & ((1u << low) - 1)) << 4)));
    if (i + 1 < codes.size()) out.push_back(std::uint8_t(p1 >> low));
  }
  return out;
}

// PFNC Mono10p / Mono12p: bit i of the stream is bit (i % 8) of byte i / 8.
std::vector<std::uint8_t> pfncPacked(const std::vector<std::uint16_t>& codes, int bits) {
  std::vector<std::uint8_t> out((codes.size() * std::size_t(bits) + 7) / 8, 0);
  std::size_t bit = 0;
  for (std::uint16_t c : codes) {
    for (int b = 0; b < bits; ++b, ++bit) {
      if ((c >> b) & 1u) out[bit / 8] |= std::uint8_t(1u << (bit % 8));
    }
  }
  return out;
}

}  // namespace

std::vector<std::uint8_t> packPixels(std::string_view name,
                                     const std::vector<std::uint16_t>& codes) {
  if (name == "Mono8" || name == "RGB8" || name == "RGB8Packed") return bytes(codes);
  if (name == "Mono10" || name == "Mono12" || name == "Mono16") return littleEndianWords(codes);
  if (name == "Mono10Packed") return gigeVisionPacked(codes, 10);
  if (name == "Mono12Packed") return gigeVisionPacked(codes, 12);
  if (name == "Mono10p") return pfncPacked(codes, 10);
  if (name == "Mono12p") return pfncPacked(codes, 12);
  return {};
}

}  // namespace vem::testing
