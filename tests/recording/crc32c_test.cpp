// The record checksum is CRC32C as Boost.CRC defines it (the reference implementation here).
#include <cstdint>
#include <random>
#include <vector>

#include <boost/crc.hpp>
#include <gtest/gtest.h>

#include "recording/crc32c.h"

namespace vem::testing {
namespace {

using BoostCrc32c = boost::crc_optimal<32, 0x1EDC6F41, 0xFFFFFFFF, 0xFFFFFFFF, true, true>;

std::uint32_t boostCrc(const std::vector<std::byte>& bytes) {
  BoostCrc32c crc;
  crc.process_bytes(bytes.data(), bytes.size());
  return crc.checksum();
}

TEST(Crc32c, MatchesTheCastagnoliCheckValue) {
  const std::string text = "123456789";
  EXPECT_EQ(recording::crc32c(std::as_bytes(std::span(text))), 0xE3069283u);
  EXPECT_EQ(recording::crc32c({}), 0u);
}

TEST(Crc32c, AgreesWithBoostCrcOnRandomBuffersOfEveryAlignmentAndLength) {
  std::mt19937 random(7);
  std::vector<std::byte> buffer(5000);
  for (std::byte& b : buffer) b = std::byte(random());
  for (std::size_t start : {0, 1, 3, 7}) {
    for (std::size_t length : {0, 1, 2, 15, 16, 17, 255, 256, 1023, 4093}) {
      const std::vector<std::byte> part(buffer.begin() + std::ptrdiff_t(start),
                                        buffer.begin() + std::ptrdiff_t(start + length));
      EXPECT_EQ(recording::crc32c(std::span(buffer).subspan(start, length)), boostCrc(part))
          << start << " " << length;
    }
  }
}

TEST(Crc32c, ChainingEqualsOneCallOverTheConcatenation) {
  std::vector<std::byte> bytes(1000);
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = std::byte(i * 31 + 7);
  const auto all = std::span<const std::byte>(bytes);
  EXPECT_EQ(recording::crc32c(all.subspan(400), recording::crc32c(all.first(400))),
            recording::crc32c(all));
}

}  // namespace
}  // namespace vem::testing
