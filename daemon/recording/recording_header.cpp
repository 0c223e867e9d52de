#include "recording/recording_header.h"

#include <cmath>
#include <string>

#include "proto/vem_recording.pb.h"
#include "recording/record_format.h"

namespace vem::recording {

std::uint64_t frameBytes(const RecordingHeader& header) {
  return std::uint64_t(std::max(header.sensorWidthPx, 0)) *
         std::uint64_t(std::max(header.sensorHeightPx, 0)) *
         std::uint64_t(std::max(header.pixelFormat.channels, 0)) * 2u;
}

std::string headerProblem(const RecordingHeader& header, const ReadLimits& limits) {
  const auto side = [](int px) { return px >= 1 && std::uint32_t(px) <= kMaxFrameSidePx; };
  if (!side(header.sensorWidthPx) || !side(header.sensorHeightPx)) {
    return "the sensor is " + std::to_string(header.sensorWidthPx) + " x " +
           std::to_string(header.sensorHeightPx) + " pixels (expected 1 to " +
           std::to_string(kMaxFrameSidePx) + " on each side)";
  }
  const std::string format = pixelFormatName(header.pixelFormat);
  if (!parsePixelFormat(format) || parsePixelFormat(format) != header.pixelFormat) {
    return "the pixel format is not one of Mono8/10/12/16 or RGB8/10/12/16";
  }
  if (frameBytes(header) > limits.maxFrameBytes) {
    return "a frame would take " + std::to_string(frameBytes(header)) + " bytes (expected at most " +
           std::to_string(limits.maxFrameBytes) + ")";
  }
  if (!std::isfinite(header.nominalRateHz) || header.nominalRateHz < 0.0) {
    return "the nominal rate is not a finite number of frames per second >= 0";
  }
  return {};
}

std::vector<std::byte> encodeHeaderRecord(const RecordingHeader& header) {
  proto::RecordingHeader message;
  message.set_format_version(header.formatVersion);
  message.set_camera_model(header.cameraModel);
  message.set_camera_serial(header.cameraSerial);
  message.set_sensor_width_px(std::uint32_t(header.sensorWidthPx));
  message.set_sensor_height_px(std::uint32_t(header.sensorHeightPx));
  message.set_pixel_format(pixelFormatName(header.pixelFormat));
  message.set_nominal_rate_hz(header.nominalRateHz);
  message.set_calibration_toml(header.calibrationToml);
  message.set_created_unix_ns(header.createdUnixNs);
  message.set_writer_name(header.writerName);
  message.set_writer_version(header.writerVersion);
  std::vector<std::byte> record;
  beginRecord(record);
  record.resize(kRecordHeaderBytes + message.ByteSizeLong());
  message.SerializeWithCachedSizesToArray(
      reinterpret_cast<std::uint8_t*>(record.data() + kRecordHeaderBytes));
  finishRecord(record, RecordType::Header);
  return record;
}

DecodedHeader decodeHeaderPayload(std::span<const std::byte> payload, const ReadLimits& limits) {
  DecodedHeader decoded;
  proto::RecordingHeader message;
  if (payload.size() > limits.maxHeaderBytes ||
      !message.ParseFromArray(payload.data(), int(payload.size()))) {
    return decoded;
  }
  RecordingHeader& h = decoded.header;
  h.formatVersion = message.format_version();
  if (h.formatVersion != kFormatVersion) {
    decoded.status = HeaderStatus::UnknownVersion;
    return decoded;
  }
  h.cameraModel = message.camera_model();
  h.cameraSerial = message.camera_serial();
  h.sensorWidthPx = int(std::min<std::uint32_t>(message.sensor_width_px(), kMaxFrameSidePx + 1));
  h.sensorHeightPx = int(std::min<std::uint32_t>(message.sensor_height_px(), kMaxFrameSidePx + 1));
  h.nominalRateHz = message.nominal_rate_hz();
  h.calibrationToml = message.calibration_toml();
  h.createdUnixNs = message.created_unix_ns();
  h.writerName = message.writer_name();
  h.writerVersion = message.writer_version();
  const auto format = parsePixelFormat(message.pixel_format());
  if (!format) {
    decoded.status = HeaderStatus::BadValues;
    decoded.problem = "the pixel format '" + message.pixel_format().substr(0, 40) +
                      "' is not one of Mono8/10/12/16 or RGB8/10/12/16";
    return decoded;
  }
  h.pixelFormat = *format;
  decoded.problem = headerProblem(h, limits);
  decoded.status = decoded.problem.empty() ? HeaderStatus::Ok : HeaderStatus::BadValues;
  return decoded;
}

}  // namespace vem::recording
