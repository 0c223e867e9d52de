#include "mapio/map_file.h"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "mapio/exr_codec.h"
#include "mapio/map_codec.h"
#include "mapio/opencv_codec.h"
#include "util/atomic_file.h"

namespace vem::mapio {
namespace {

using detail::fileFailure;
using detail::MapFormat;
constexpr std::size_t kFileStartBytes = 4096;  // enough for the signature and a PFM or RGBE header

std::expected<MapFormat, MapFileFailure> formatOf(const std::filesystem::path& path) {
  const std::string given = path.extension().string();
  std::string ext = given;
  std::ranges::transform(ext, ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".exr") return MapFormat::Exr;
  if (ext == ".hdr") return MapFormat::RadianceHdr;
  if (ext == ".pfm") return MapFormat::Pfm;
  return std::unexpected(
      fileFailure(MapFileError::UnsupportedFormat, path,
                  (given.empty() ? std::string("the name has no extension")
                                 : "the extension '" + given + "' is not a map format") +
                      " (expected .exr, .hdr or .pfm)"));
}

// The first bytes of the file, or why it cannot be read.
std::expected<std::string, MapFileFailure> readFileStart(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found)
    return std::unexpected(fileFailure(MapFileError::NotFound, path, "no such file"));
  if (std::filesystem::is_directory(status))
    return std::unexpected(fileFailure(MapFileError::Unreadable, path, "a folder, not a map file"));
  std::ifstream in(path, std::ios::binary);
  std::string start(kFileStartBytes, '\0');
  if (in) in.read(start.data(), std::streamsize(start.size()));
  if (!in && !in.eof())
    return std::unexpected(fileFailure(
        MapFileError::Unreadable, path,
        "cannot be read" +
            (error ? " (" + error.message() + ")" : std::string(" (check its permissions)"))));
  start.resize(std::size_t(in.gcount()));
  if (start.empty())
    return std::unexpected(fileFailure(MapFileError::BadContents, path, "the file is empty"));
  return start;
}

}  // namespace

const char* mapFileErrorName(MapFileError error) {
  switch (error) {
    case MapFileError::NotFound: return "not found";
    case MapFileError::Unreadable: return "unreadable";
    case MapFileError::UnsupportedFormat: return "unsupported format";
    case MapFileError::BadContents: return "bad contents";
    case MapFileError::WriteFailed: return "write failed";
  }
  return "unknown";
}

std::optional<MapLayout> defaultLayout(int width, int height) {
  if (height > 0 && width == 2 * height) return MapLayout::Sphere;
  if (height > 0 && width == 4 * height) return MapLayout::Hemisphere;
  return std::nullopt;
}

std::expected<EnvMap, MapFileFailure> loadMap(const std::filesystem::path& path,
                                              std::optional<MapLayout> layout) {
  const auto format = formatOf(path);
  if (!format) return std::unexpected(format.error());
  const auto start = readFileStart(path);
  if (!start) return std::unexpected(start.error());
  auto image = *format == MapFormat::Exr ? detail::readExr(path, *start)
                                         : detail::readWithOpenCv(path, *format, *start);
  if (!image) return std::unexpected(image.error());
  if (auto ok = detail::checkMapSize(path, "the map", image->width, image->height); !ok)
    return std::unexpected(ok.error());
  if (!layout) layout = defaultLayout(image->width, image->height);
  if (!layout)
    return std::unexpected(fileFailure(
        MapFileError::BadContents, path,
        "the map is " + std::to_string(image->width) + " x " + std::to_string(image->height) +
            " pixels, a shape with no default layout (expected width = 2 x height for a sphere, "
            "width = 4 x height for a hemisphere, or a layout given explicitly)"));
  return EnvMap{*layout, image->width, image->height, std::move(image->rgb)};
}

std::expected<void, MapFileFailure> saveMap(const EnvMap& map, const std::filesystem::path& path) {
  const auto format = formatOf(path);
  if (!format) return std::unexpected(format.error());
  if (map.width < 1 || map.height < 1 || map.rgb.size() != map.pixelCount() * 3)
    return std::unexpected(fileFailure(
        MapFileError::BadContents, path,
        "cannot save a " + std::to_string(map.width) + " x " + std::to_string(map.height) +
            " map holding " + std::to_string(map.rgb.size()) +
            " floats (expected at least 1 x 1 and 3 floats per pixel)"));
  const auto bytes =
      *format == MapFormat::Exr ? detail::encodeExr(map) : detail::encodeWithOpenCv(map, *format);
  if (!bytes)
    return std::unexpected(fileFailure(MapFileError::WriteFailed, path,
                                       "cannot encode the map (" + bytes.error() + ")"));
  if (auto done = util::replaceFileAtomically(path, std::as_bytes(std::span(*bytes))); !done)
    return std::unexpected(fileFailure(MapFileError::WriteFailed, path,
                                       "cannot write the map (" + done.error().reason() +
                                           "), so any earlier file there is unchanged"));
  return {};
}

}  // namespace vem::mapio
