// Why a geometric fit of the plate camera (plate_intrinsics_fit.h, plate_pose_fit.h) was refused:
// a cause and one sentence naming the view and the limit, for the shell to print.
#pragma once

#include <string>

namespace vem::calib {

enum class PlateFitRefusal { TooFewViews, WrongCornerCount, NotConverged, ErrorTooHigh, Behind };

struct PlateFitFailure {
  PlateFitRefusal cause;
  std::string message;
  int view = -1;  // the view at fault (index into the input), -1 when none is
};

}  // namespace vem::calib
