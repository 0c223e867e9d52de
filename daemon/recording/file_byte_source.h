// FileByteSource: a recording file as a ByteSource, read with pread(). Its size is the file's
// when opened: a recording still being written is read up to that point.
#pragma once

#include <expected>
#include <filesystem>
#include <string>

#include "recording/byte_source.h"
#include "recording/recording_failure.h"
#include "util/unique_fd.h"

namespace vem::recording {

class FileByteSource final : public ByteSource {
 public:
  // NotFound, or Unreadable (a folder, no permission, ...), with a sentence naming `path`.
  [[nodiscard]] static std::expected<FileByteSource, RecordingFailure> open(
      const std::filesystem::path& path);

  [[nodiscard]] std::uint64_t size() const override { return size_; }
  [[nodiscard]] bool readAt(std::uint64_t offset, std::span<std::byte> out) override;
  // errno of the last failed read, 0 when none failed.
  [[nodiscard]] int lastError() const { return lastError_; }

 private:
  FileByteSource(util::UniqueFd fd, std::uint64_t size) : fd_(std::move(fd)), size_(size) {}
  util::UniqueFd fd_;
  std::uint64_t size_ = 0;
  int lastError_ = 0;
};

}  // namespace vem::recording
