// RecordingWriter: records frames into a new VEM recording file (docs/vem-format.md).
//
// - create() writes the header record and syncs it; append() writes one frame record with a single
//   write of the whole record at the end of the file; close() appends the index and the footer.
//   Earlier bytes are never rewritten, so a file cut anywhere keeps every frame before the cut.
// - Durability: a crash of the process loses at most the frame being written (every finished
//   append() is in the kernel's hands). The file is fdatasync'ed after the header, every
//   WriterOptions::syncEveryFrames frames and at close(), so a power cut or kernel crash loses at
//   most the frames since the last sync; syncEveryFrames = 1 syncs every frame.
// - Errors (ENOSPC, EIO, EFBIG, ...) come back as values with one sentence. A failed append leaves
//   the file as it was before it (the partial record is cut off again where the file system
//   allows), readable, and the writer usable: a later append or close() may succeed.
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/light.h"
#include "frames/raw_frame.h"
#include "recording/frame_codec.h"
#include "recording/recording_failure.h"
#include "recording/recording_header.h"
#include "recording/recording_index.h"
#include "util/unique_fd.h"

namespace vem::recording {

struct WriterOptions {
  int zstdLevel = kDefaultZstdLevel;
  std::uint32_t syncEveryFrames = 30;  // 0: only at close()
  bool replaceExisting = false;        // else an existing file at the path is refused
};

class RecordingWriter {
 public:
  // Creates the file and writes `header` (its formatVersion is set to kFormatVersion). Fails with
  // BadHeader when the header cannot describe frames, WriteFailed when the file cannot be made.
  [[nodiscard]] static std::expected<RecordingWriter, RecordingFailure> create(
      const std::filesystem::path& path, const RecordingHeader& header, WriterOptions options = {});

  RecordingWriter(RecordingWriter&&) noexcept;
  RecordingWriter& operator=(RecordingWriter&&) noexcept;
  // Closes (index and footer) when close() was not called; errors are then lost.
  ~RecordingWriter();

  // Appends one frame, with the lights computed from it when `lights` is not null. The frame must
  // have the header's size and pixel format (InvalidFrame otherwise) and seq must be greater than
  // the previous frame's.
  [[nodiscard]] std::expected<void, RecordingFailure> append(std::uint64_t seq,
                                                             std::int64_t captureTsNs,
                                                             const RawFrame& frame,
                                                             const LightSet* lights = nullptr);
  // Writes the index and footer, syncs and closes. The writer is closed afterwards even on error
  // (the file then stays readable without an index; `vemtool recover` can add one).
  [[nodiscard]] std::expected<void, RecordingFailure> close();

  [[nodiscard]] std::uint64_t framesWritten() const { return entries_.size(); }
  [[nodiscard]] std::uint64_t bytesWritten() const { return end_; }

 private:
  RecordingWriter(std::filesystem::path path, util::UniqueFd fd, RecordingHeader header,
                  WriterOptions options);
  // Writes `bytes` after the last complete record; on failure cuts a partial write off again and
  // gives the errno.
  [[nodiscard]] std::expected<void, int> writeAtEnd(const std::vector<std::byte>& bytes);
  // "cannot write `what` (cause); the N frames before it stay readable"
  [[nodiscard]] RecordingFailure writeFailure(const std::string& what, int error) const;
  [[nodiscard]] std::string frameProblem(std::uint64_t seq, const RawFrame& frame) const;

  std::filesystem::path path_;
  std::string name_;  // path_ made printable (util/printable.h), for messages
  util::UniqueFd fd_;
  RecordingHeader header_;
  WriterOptions options_;
  FrameCodec codec_;
  std::vector<IndexEntry> entries_;
  std::vector<std::byte> record_;
  std::uint64_t end_ = 0;  // bytes of complete records in the file
  std::uint32_t framesSinceSync_ = 0;
};

}  // namespace vem::recording
