// Atomic file replacement: the new contents go to a temporary file beside the target, reach the
// disk (fsync) and are renamed over the target, so the path holds the old file or the new one,
// never a part of either. POSIX (rename within one folder is atomic).
#pragma once

#include <expected>
#include <filesystem>
#include <span>
#include <string>

namespace vem::mapio::detail {

// On failure the temporary file is removed and the reason returned (without the target's path).
[[nodiscard]] std::expected<void, std::string> replaceFileAtomically(
    const std::filesystem::path& target, std::span<const unsigned char> bytes);

}  // namespace vem::mapio::detail
