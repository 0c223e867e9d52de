// readOwnerOnlyFile: the text of a file holding a secret (a token, a password), refused when group
// or others may read it. `field` names the setting that named the file ("stream.token_file"), for
// the one-sentence refusal. POSIX (stat).
#pragma once

#include <expected>
#include <filesystem>
#include <string>
#include <string_view>

namespace vem::util {

[[nodiscard]] std::expected<std::string, std::string> readOwnerOnlyFile(
    const std::filesystem::path& path, std::string_view field);

}  // namespace vem::util
