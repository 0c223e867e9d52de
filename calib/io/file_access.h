// Whole-file reads and atomic writes for the calibration files (internal to vem_calibio), and the
// parse, load and checked save that every TOML file of calib/io builds on them. Every failure is
// one sentence that starts with the path as given.
#pragma once

#include <expected>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

#include "calib/io/calib_file_failure.h"
#include "util/toml_failure.h"
#include "util/toml_reader.h"

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

// `text` parsed as TOML and read from its root table by `read(root, status)`, which gets the
// root's util::TomlReader and the util::TomlStatus that every reader of the file shares: the value
// read, or the first problem as a failure.
template <typename Read>
[[nodiscard]] auto parseTomlText(const std::string& text, const std::string& sourceName, Read read)
    -> std::expected<std::invoke_result_t<Read&, util::TomlReader&, util::TomlStatus&>,
                     CalibFileFailure> {
  const auto document = util::parseToml(text, sourceName);
  if (!document) return std::unexpected(calibFileFailure(document.error()));
  util::TomlStatus status{sourceName, std::nullopt};
  util::TomlReader root(*document, "", status);
  auto value = read(root, status);
  if (!status.ok()) return std::unexpected(calibFileFailure(*status.failure));
  return value;
}

// The file at `path` read whole and given to `parse(text, sourceName)`, which returns a
// std::expected<T, CalibFileFailure>; `kind` names the file in messages ("camera file").
template <typename Parse>
[[nodiscard]] auto loadTextFile(const std::filesystem::path& path, std::string_view kind,
                                Parse parse)
    -> std::invoke_result_t<Parse&, const std::string&, const std::string&> {
  const auto text = readWholeFile(path, kind);
  if (!text) return std::unexpected(text.error());
  return parse(*text, path.string());
}

// writeTextFile, once `parse(text, path.string())` accepts `text`: a file that would not load is
// never written, and the old file stays untouched ("<the parser's sentence>, so nothing was
// written").
template <typename Parse>
[[nodiscard]] std::expected<void, CalibFileFailure> saveCheckedTextFile(
    const std::filesystem::path& path, const std::string& text, std::string_view kind,
    Parse parse) {
  if (auto checked = parse(text, path.string()); !checked)
    return std::unexpected(CalibFileFailure{checked.error().cause,
                                            checked.error().message + ", so nothing was written"});
  return writeTextFile(path, text, kind);
}

}  // namespace vem::calib::io::detail
