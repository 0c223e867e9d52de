#include "mapio/map_codec.h"

namespace vem::mapio::detail {

MapFileFailure fileFailure(MapFileError cause, const std::filesystem::path& path,
                           std::string_view what) {
  return {cause, path.string() + ": " + std::string(what)};
}

std::expected<void, MapFileFailure> checkMapSize(const std::filesystem::path& path,
                                                 std::string_view subject, std::int64_t width,
                                                 std::int64_t height) {
  if (width >= 1 && height >= 1 && width <= kMaxMapWidth && height <= kMaxMapHeight) return {};
  const std::string size = std::string(subject) + " is " + std::to_string(width) + " x " +
                           std::to_string(height) + " pixels";
  const std::string what = width < 1 || height < 1
                               ? size + ", which is empty (expected at least 1 x 1)"
                               : size + " (expected at most " + std::to_string(kMaxMapWidth) +
                                     " x " + std::to_string(kMaxMapHeight) + ")";
  return std::unexpected(fileFailure(MapFileError::BadContents, path, what));
}

}  // namespace vem::mapio::detail
