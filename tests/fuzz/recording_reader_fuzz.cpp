// libFuzzer target for the recording reader's core (daemon/recording/recording_cursor.h): any
// bytes must open, read, summarise and seek without crashing, without undefined behaviour, and
// without allocating more than the reader's limits allow.
//
//   recording_reader_fuzz --write-seeds=DIR   writes a few small valid recordings into DIR and exits
//   recording_reader_fuzz [libFuzzer flags] CORPUS...
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "recording/byte_source.h"
#include "recording/frame_codec.h"
#include "recording/recording_cursor.h"
#include "recording/recording_header.h"
#include "recording/recording_index.h"
#include "recording/recording_summary.h"
#include "tests/fuzz/seed_option.h"

namespace {

using namespace vem::recording;

// Small limits keep each input fast; the checks they exercise are the same as the defaults'.
ReadLimits fuzzLimits() {
  ReadLimits limits;
  limits.maxFrameBytes = std::uint64_t(4) << 20;
  limits.maxHeaderBytes = std::uint32_t(1) << 20;
  limits.maxFrameMetaBytes = std::uint32_t(1) << 20;
  limits.maxIndexBytes = std::uint32_t(16) << 20;
  return limits;
}

// A valid recording: header, `frames` frames (lights on odd ones), and the trailer if `close`.
std::vector<std::byte> seedRecording(int width, int height, vem::PixelFormat format, int frames,
                                     bool close) {
  RecordingHeader header;
  header.cameraModel = "fuzz";
  header.cameraSerial = "0";
  header.sensorWidthPx = width;
  header.sensorHeightPx = height;
  header.pixelFormat = format;
  header.nominalRateHz = 30.0;
  header.calibrationToml = "format = \"vemcast-camera\"\nversion = 1\n";
  std::vector<std::byte> file = encodeHeaderRecord(header);
  std::vector<IndexEntry> entries;
  FrameCodec codec;
  std::vector<std::byte> record;
  for (int i = 0; i < frames; ++i) {
    vem::RawFrame frame = vem::RawFrame::blank(width, height, format);
    for (std::size_t k = 0; k < frame.codes.size(); ++k) {
      frame.codes[k] = std::uint16_t((k * 37 + std::size_t(i) * 11) & format.maxCode());
    }
    vem::LightSet lights;
    lights.luminanceSr = 3.0 + i;
    lights.lights.push_back({std::uint32_t(i), {0.0F, 1.0F, 0.0F}, {1.0F, 2.0F, 3.0F}});
    codec.encodeRecord(std::uint64_t(i * 2), i * 33'333'333LL, frame, i % 2 == 1 ? &lights : nullptr,
                       record);
    entries.push_back({std::uint64_t(i * 2), i * 33'333'333LL, file.size()});
    file.insert(file.end(), record.begin(), record.end());
  }
  if (close) {
    const std::vector<std::byte> trailer = encodeTrailer(entries, file.size());
    file.insert(file.end(), trailer.begin(), trailer.end());
  }
  return file;
}

void writeSeeds(const std::string& dir) {
  const auto write = [&](const std::string& name, const std::vector<std::byte>& bytes) {
    std::ofstream out(dir + "/" + name, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  };
  write("mono12_closed.vem", seedRecording(16, 8, {1, 12}, 3, true));
  write("rgb16_closed.vem", seedRecording(8, 4, {3, 16}, 2, true));
  write("mono8_open.vem", seedRecording(12, 6, {1, 8}, 3, false));
  std::vector<std::byte> damaged = seedRecording(16, 8, {1, 12}, 4, true);
  damaged[damaged.size() / 2] ^= std::byte{0x20};
  write("mono12_damaged.vem", damaged);
  write("header_only.vem", seedRecording(4, 4, {1, 16}, 0, false));
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  vem::fuzz::handleWriteSeedsOption(*argc, *argv, writeSeeds);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  MemoryByteSource source(std::span(reinterpret_cast<const std::byte*>(data), size));
  RecordingCursor cursor(source, fuzzLimits());
  if (cursor.open() != OpenStatus::Ok) return 0;

  RecordedFrame frame;
  std::uint64_t checksum = 0;
  while (cursor.next(frame) == ReadStep::Frame) {
    // Touch everything a frame claims to hold.
    if (frame.frame.codes.size() != frameBytes(cursor.header()) / 2) std::abort();
    for (std::uint16_t code : frame.frame.codes) checksum += code;
    if (frame.lights) checksum += frame.lights->lights.size();
  }
  const FrameScan scan = scanFrames(cursor);
  const RecordingSummary summary = summarizeRecording(cursor, scan);
  if (summary.frames != scan.entries.size()) std::abort();
  const std::uint64_t target = size > 0 ? data[size - 1] : 0;
  if (cursor.seek(target) == SeekStep::Found) {
    if (cursor.next(frame) == ReadStep::Frame && frame.seq < target && !scan.entries.empty() &&
        cursor.indexStatus() != IndexStatus::Valid) {
      std::abort();  // a scanned index never seeks before the target
    }
  }
  return checksum == 0xDEADBEEFDEADBEEF ? 1 : 0;
}
