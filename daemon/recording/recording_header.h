// RecordingHeader: what a VEM recording says about itself in its first record: the format
// version, the camera and the calibration in force, the frames' size and pixel format, the
// nominal rate. Encoded as the protobuf message vem.proto.RecordingHeader (proto/vem_recording.proto).
//
// Units: sensor sizes in pixels, nominalRateHz in frames per second (0 = unknown), createdUnixNs in
// ns since 1970-01-01 UTC. calibrationToml is a whole camera file (calib/io/camera_file.h), or
// empty when no calibration was in force.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "frames/raw_frame.h"
#include "recording/read_limits.h"

namespace vem::recording {

// The version this library writes and the only one it reads.
inline constexpr std::uint32_t kFormatVersion = 1;

struct RecordingHeader {
  std::uint32_t formatVersion = kFormatVersion;
  std::string cameraModel;
  std::string cameraSerial;
  int sensorWidthPx = 0;
  int sensorHeightPx = 0;
  PixelFormat pixelFormat;
  double nominalRateHz = 0.0;
  std::string calibrationToml;
  std::int64_t createdUnixNs = 0;
  std::string writerName;
  std::string writerVersion;

  friend bool operator==(const RecordingHeader&, const RecordingHeader&) = default;
};

// Bytes of one frame's codes, uncompressed: width x height x channels x 2.
[[nodiscard]] std::uint64_t frameBytes(const RecordingHeader& header);

// Empty when the header can describe a recording; else what is wrong, as a sentence fragment
// ("the sensor is 0 x 1024 pixels (expected 1 to 65535 on each side)").
[[nodiscard]] std::string headerProblem(const RecordingHeader& header, const ReadLimits& limits);

// The header record (record header and payload).
[[nodiscard]] std::vector<std::byte> encodeHeaderRecord(const RecordingHeader& header);

enum class HeaderStatus { Ok, Malformed, UnknownVersion, BadValues };

struct DecodedHeader {
  HeaderStatus status = HeaderStatus::Malformed;
  RecordingHeader header;  // as far as it could be read (formatVersion for UnknownVersion)
  std::string problem;     // for BadValues: headerProblem()
};

// Decodes a header record's payload and checks its version and values.
[[nodiscard]] DecodedHeader decodeHeaderPayload(std::span<const std::byte> payload,
                                                const ReadLimits& limits);

}  // namespace vem::recording
