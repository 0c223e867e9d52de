#include "calib/io/calib_file_kind.h"

#include "calib/io/camera_file_fields.h"
#include "calib/io/file_access.h"
#include "util/toml_reader.h"

namespace vem::calib::io {

CalibFileKind calibFileKind(const std::filesystem::path& path) {
  const auto text = detail::readWholeFile(path, "calibration file");
  if (!text) return CalibFileKind::Unknown;
  const auto document = util::parseToml(*text, path.string());
  if (!document) return CalibFileKind::Unknown;
  const std::optional<std::string> format = (*document)["format"].value<std::string>();
  if (format == detail::kCameraFormatName) return CalibFileKind::LightProbeCamera;
  if (format == detail::kPlateCameraFormatName) return CalibFileKind::PlateCamera;
  return CalibFileKind::Unknown;
}

}  // namespace vem::calib::io
