#include "cameras/v4l2/v4l2_controls.h"

#include <algorithm>
#include <cerrno>
#include <cmath>

#include <fmt/format.h>

namespace vem::cameras {

namespace {

std::optional<int> getControl(V4l2Device& device, std::uint32_t id) {
  v4l2_control control{};
  control.id = id;
  if (v4l2Ioctl(device, VIDIOC_G_CTRL, &control) != 0) return std::nullopt;
  return control.value;
}

// Sets `id` and gives the value the driver keeps (read back), or the errno value.
std::expected<int, int> setControl(V4l2Device& device, std::uint32_t id, int value) {
  v4l2_control control{};
  control.id = id;
  control.value = value;
  if (const int error = v4l2Ioctl(device, VIDIOC_S_CTRL, &control)) return std::unexpected(error);
  return getControl(device, id).value_or(control.value);
}

std::optional<std::uint32_t> gainControlId(V4l2Device& device) {
  for (std::uint32_t id : {std::uint32_t(V4L2_CID_ANALOGUE_GAIN), std::uint32_t(V4L2_CID_GAIN)}) {
    if (queryControl(device, id)) return id;
  }
  return std::nullopt;
}

std::expected<void, std::string> setManualMode(V4l2Device& device) {
  if (!queryControl(device, V4L2_CID_EXPOSURE_AUTO)) return {};
  int error = 0;
  for (int mode : {int(V4L2_EXPOSURE_MANUAL), int(V4L2_EXPOSURE_SHUTTER_PRIORITY)}) {
    auto set = setControl(device, V4L2_CID_EXPOSURE_AUTO, mode);
    if (set && *set == mode) return {};
    error = set ? EINVAL : set.error();
  }
  return std::unexpected(fmt::format(
      "the camera refuses manual exposure (V4L2_CID_EXPOSURE_AUTO: {})", errnoText(error)));
}

}  // namespace

int controlValueNear(double wanted, const v4l2_queryctrl& control) {
  const double step = std::max(control.step, 1);
  const double steps = std::round((wanted - double(control.minimum)) / step);
  double value = double(control.minimum) + steps * step;
  // Clamp onto the grid: the largest grid value not above the maximum.
  const double top =
      double(control.minimum) + std::floor(double(control.maximum - control.minimum) / step) * step;
  value = std::clamp(value, double(control.minimum), top);
  return int(value);
}

int gainUnityValue(const v4l2_queryctrl& control) {
  return control.default_value > 0 ? control.default_value : 1;
}

std::optional<v4l2_queryctrl> queryControl(V4l2Device& device, std::uint32_t id) {
  v4l2_queryctrl query{};
  query.id = id;
  if (v4l2Ioctl(device, VIDIOC_QUERYCTRL, &query) != 0) return std::nullopt;
  if (query.flags & V4L2_CTRL_FLAG_DISABLED) return std::nullopt;
  return query;
}

std::expected<double, std::string> applyExposureUs(V4l2Device& device, double exposureUs) {
  const auto control = queryControl(device, V4L2_CID_EXPOSURE_ABSOLUTE);
  if (!control) {
    return std::unexpected(std::string(
        queryControl(device, V4L2_CID_EXPOSURE)
            ? "the camera has only V4L2_CID_EXPOSURE, whose unit its driver defines, not "
              "V4L2_CID_EXPOSURE_ABSOLUTE (100 us)"
            : "the camera has no exposure control (V4L2_CID_EXPOSURE_ABSOLUTE)"));
  }
  if (auto manual = setManualMode(device); !manual) return std::unexpected(manual.error());
  const int value = controlValueNear(exposureUs / kExposureAbsoluteUnitUs, *control);
  auto set = setControl(device, V4L2_CID_EXPOSURE_ABSOLUTE, value);
  if (!set) {
    return std::unexpected(
        fmt::format("the camera refuses exposure {} x 100 us ({})", value, errnoText(set.error())));
  }
  return double(*set) * kExposureAbsoluteUnitUs;
}

std::expected<double, std::string> applyGain(V4l2Device& device, double gain) {
  const auto id = gainControlId(device);
  if (!id) return std::unexpected(std::string("the camera has no gain control (V4L2_CID_GAIN)"));
  const v4l2_queryctrl control = *queryControl(device, *id);
  const int unity = gainUnityValue(control);
  const int value = controlValueNear(gain * unity, control);
  auto set = setControl(device, *id, value);
  if (!set) {
    return std::unexpected(
        fmt::format("the camera refuses gain value {} ({})", value, errnoText(set.error())));
  }
  return double(*set) / unity;
}

std::optional<double> currentExposureUs(V4l2Device& device) {
  const auto value = getControl(device, V4L2_CID_EXPOSURE_ABSOLUTE);
  if (!value) return std::nullopt;
  return double(*value) * kExposureAbsoluteUnitUs;
}

std::optional<double> currentGain(V4l2Device& device) {
  const auto id = gainControlId(device);
  if (!id) return std::nullopt;
  const auto value = getControl(device, *id);
  if (!value) return std::nullopt;
  return double(*value) / gainUnityValue(*queryControl(device, *id));
}

std::expected<double, std::string> applyFrameRate(V4l2Device& device, double rateHz) {
  v4l2_streamparm parm{};
  parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (v4l2Ioctl(device, VIDIOC_G_PARM, &parm) != 0 ||
      !(parm.parm.capture.capability & V4L2_CAP_TIMEPERFRAME)) {
    return std::unexpected(std::string("the camera does not let its frame rate be set"));
  }
  const bool whole = std::abs(rateHz - std::round(rateHz)) < 1e-9;
  parm.parm.capture.timeperframe.numerator = whole ? 1 : 1000;
  parm.parm.capture.timeperframe.denominator =
      std::uint32_t(std::llround(whole ? rateHz : rateHz * 1000.0));
  if (const int error = v4l2Ioctl(device, VIDIOC_S_PARM, &parm)) {
    return std::unexpected(fmt::format("the camera refuses {} Hz ({})", rateHz, errnoText(error)));
  }
  const auto inForce = currentFrameRate(device);
  if (!inForce) return std::unexpected(std::string("the camera does not report its frame rate"));
  return *inForce;
}

std::optional<double> currentFrameRate(V4l2Device& device) {
  v4l2_streamparm parm{};
  parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (v4l2Ioctl(device, VIDIOC_G_PARM, &parm) != 0) return std::nullopt;
  const v4l2_fract& t = parm.parm.capture.timeperframe;
  if (t.numerator == 0 || t.denominator == 0) return std::nullopt;
  return double(t.denominator) / double(t.numerator);
}

}  // namespace vem::cameras
