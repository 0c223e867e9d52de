#include "stream_e2e/small_camera.h"

#include "calib/io/camera_file.h"
#include "support/test_cameras.h"

namespace vem::e2e {

std::string smallCameraToml() {
  return calib::io::formatCameraFile(
      testing::cameraTruth(kSmallCameraWidthPx, kSmallCameraHeightPx, 3));
}

}  // namespace vem::e2e
