// Whole-file reads and atomic writes for the calibration files (internal to vem_calibio). Every
// failure is one sentence that starts with the path as given.
#pragma once

#include <expected>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "calib/io/calib_file_failure.h"
#include "util/toml_failure.h"

namespace vem::calib::io::detail {

// "<path>: <what>" as a failure.
[[nodiscard]] CalibFileFailure fileFailure(CalibFileError cause, const std::filesystem::path& path,
                                           std::string_view what);

// A TOML reader's failure (util/toml_reader.h) as a calibration file's, same cause and sentence.
[[nodiscard]] CalibFileFailure calibFileFailure(const util::TomlFailure& failure);

// The whole file; `kind` names what it should be in messages ("camera file").
[[nodiscard]] std::expected<std::string, CalibFileFailure> readWholeFile(
    const std::filesystem::path& path, std::string_view kind);

// Writes `bytes` beside `path` and renames them over it: on failure the old file is unchanged.
[[nodiscard]] std::expected<void, CalibFileFailure> writeWholeFile(
    const std::filesystem::path& path, std::span<const unsigned char> bytes, std::string_view kind);

// writeWholeFile for text.
[[nodiscard]] std::expected<void, CalibFileFailure> writeTextFile(const std::filesystem::path& path,
                                                                  std::string_view text,
                                                                  std::string_view kind);

}  // namespace vem::calib::io::detail
