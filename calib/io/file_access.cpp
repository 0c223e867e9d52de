#include "calib/io/file_access.h"

#include <fstream>
#include <iterator>

#include "util/atomic_file.h"

namespace vem::calib::io::detail {

CalibFileFailure fileFailure(CalibFileError cause, const std::filesystem::path& path,
                             std::string_view what) {
  return {cause, path.string() + ": " + std::string(what)};
}

std::expected<std::string, CalibFileFailure> readWholeFile(const std::filesystem::path& path,
                                                           std::string_view kind) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found)
    return std::unexpected(fileFailure(CalibFileError::NotFound, path, "no such file"));
  if (std::filesystem::is_directory(status))
    return std::unexpected(
        fileFailure(CalibFileError::Unreadable, path, "a folder, not a " + std::string(kind)));
  std::ifstream in(path, std::ios::binary);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (!in.is_open() || in.bad())
    return std::unexpected(
        fileFailure(CalibFileError::Unreadable, path, "cannot be read (check its permissions)"));
  return text;
}

CalibFileFailure calibFileFailure(const util::TomlFailure& failure) {
  switch (failure.cause) {
    case util::TomlProblem::BadSyntax: return {CalibFileError::BadSyntax, failure.message};
    case util::TomlProblem::UnknownVersion:
      return {CalibFileError::UnknownVersion, failure.message};
    case util::TomlProblem::MissingField: return {CalibFileError::MissingField, failure.message};
    case util::TomlProblem::WrongUnit: return {CalibFileError::WrongUnit, failure.message};
    case util::TomlProblem::BadValue: break;
  }
  return {CalibFileError::BadValue, failure.message};
}

std::expected<void, CalibFileFailure> writeWholeFile(const std::filesystem::path& path,
                                                     std::span<const unsigned char> bytes,
                                                     std::string_view kind) {
  const auto written = util::replaceFileAtomically(path, std::as_bytes(bytes));
  if (written) return {};
  return std::unexpected(fileFailure(CalibFileError::WriteFailed, path,
                                     "cannot write the " + std::string(kind) + " (" +
                                         written.error().reason() +
                                         "), so any earlier file there is unchanged"));
}

std::expected<void, CalibFileFailure> writeTextFile(const std::filesystem::path& path,
                                                    std::string_view text, std::string_view kind) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
  return writeWholeFile(path, {bytes, text.size()}, kind);
}

}  // namespace vem::calib::io::detail
