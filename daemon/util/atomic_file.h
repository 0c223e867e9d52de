// Atomic file replacement: the new contents go to a temporary file beside the target (same folder,
// hidden name), reach the disk (fsync), are renamed over the target, and the folder is synced so
// the rename lasts. The path then holds the old file or the new one, never a part of either, even
// after a crash or power loss. POSIX: rename(2) within one folder is atomic.
//
// The two steps are public so tests can stop between them ("a crash before the rename").
#pragma once

#include <expected>
#include <filesystem>
#include <span>
#include <string>

namespace vem::util {

struct FileReplaceFailure {
  int error = 0;        // errno of the failed step
  std::string step;     // "cannot create a temporary file beside it", ...
  std::string message;  // one sentence: "<path>: <step> (<strerror>); any earlier file there is
                        // unchanged"
  // "<step>: <strerror>", for callers that name the file in their own words.
  [[nodiscard]] std::string reason() const;
};

// Replaces `target` by `bytes` (new files get mode 0666 less the umask). On failure no temporary
// file is left behind and `target` is as it was.
[[nodiscard]] std::expected<void, FileReplaceFailure> replaceFileAtomically(
    const std::filesystem::path& target, std::span<const std::byte> bytes);

// Step 1: `bytes` written and synced to a new hidden file beside `target`; its path.
[[nodiscard]] std::expected<std::filesystem::path, FileReplaceFailure> writeTemporarySibling(
    const std::filesystem::path& target, std::span<const std::byte> bytes);
// Step 2: `temporary` renamed over `target` and the folder synced (best effort); on failure
// `temporary` is removed.
[[nodiscard]] std::expected<void, FileReplaceFailure> renameOver(
    const std::filesystem::path& temporary, const std::filesystem::path& target);

}  // namespace vem::util
