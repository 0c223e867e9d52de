// makeSinks: the sinks a vemd configuration asks for, in a fixed order: the JSON-lines light file,
// the recorder, the preview image (sink.h: they run in this order on the processing thread).
//
// Every file is opened, or the recording created, here, so a bad path fails at start-up with one
// sentence rather than at the first frame. `record` may name a folder: each run then records into
// a new time-stamped file in it (recorder_sink.h, recordingPathFor); a file path must not exist
// yet.
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frames/sink.h"
#include "vemd/sinks/recording_context.h"

namespace vem::vemd {

struct SinkConfig {
  std::optional<std::filesystem::path> jsonl;       // JSON-lines light file (appended)
  std::optional<std::filesystem::path> record;      // a .vem file, or a folder for new ones
  std::optional<std::filesystem::path> previewDir;  // preview.png goes here
  int previewEvery = 30;                            // one preview per this many frames
  bool previewNumbered = false;                     // also keep preview-SEQ.png files
  int previewScale = 2;                             // preview pixels per polar-map pixel
  std::uint32_t recordSyncEveryFrames = 30;         // recording::WriterOptions::syncEveryFrames
};

// The configured sinks (none when nothing is configured), or the first failure as one sentence
// naming the sink, the path and the cause. With `missing` given, a sink that cannot open is left
// out instead, and its sentence appended to *missing (vemd's output.allow_missing).
[[nodiscard]] std::expected<std::vector<std::unique_ptr<Sink>>, std::string> makeSinks(
    const SinkConfig& config, const RecordingContext& recordingContext,
    std::vector<std::string>* missing = nullptr);

}  // namespace vem::vemd
