// ByteSource: the bytes of a recording as the pure reading code sees them, a fixed-size sequence
// read at offsets. The shell supplies a file (file_byte_source.h); tests and the fuzzer supply
// memory. A source's size is fixed when it is made: bytes appended later are not seen.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vem::recording {

class ByteSource {
 public:
  virtual ~ByteSource() = default;
  [[nodiscard]] virtual std::uint64_t size() const = 0;
  // Fills `out` with the bytes at [offset, offset + out.size()), which lie within size(); false on
  // an I/O error.
  [[nodiscard]] virtual bool readAt(std::uint64_t offset, std::span<std::byte> out) = 0;

 protected:
  ByteSource() = default;
  ByteSource(const ByteSource&) = default;
  ByteSource& operator=(const ByteSource&) = default;
};

// Borrows the bytes: they must outlive the source.
class MemoryByteSource final : public ByteSource {
 public:
  explicit MemoryByteSource(std::span<const std::byte> bytes) : bytes_(bytes) {}
  [[nodiscard]] std::uint64_t size() const override { return bytes_.size(); }
  [[nodiscard]] bool readAt(std::uint64_t offset, std::span<std::byte> out) override;

 private:
  std::span<const std::byte> bytes_;
};

}  // namespace vem::recording
