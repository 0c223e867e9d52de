#include "vemd/sinks/recording_context.h"

#ifndef VEM_VERSION
#define VEM_VERSION "unknown"
#endif

namespace vem::vemd {

recording::RecordingHeader recordingHeader(const RecordingContext& context,
                                           std::int64_t createdUnixNs) {
  recording::RecordingHeader header;
  header.cameraModel = context.cameraModel;
  header.cameraSerial = context.cameraSerial;
  header.sensorWidthPx = context.widthPx;
  header.sensorHeightPx = context.heightPx;
  header.pixelFormat = context.pixelFormat;
  header.nominalRateHz = context.nominalRateHz;
  header.calibrationToml = context.calibrationToml;
  header.createdUnixNs = createdUnixNs;
  header.writerName = "vemd";
  header.writerVersion = VEM_VERSION;
  return header;
}

}  // namespace vem::vemd
