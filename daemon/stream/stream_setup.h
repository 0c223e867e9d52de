// Streaming setup: from vemd's [stream] configuration (vemd_config.h) to a listening StreamServer,
// the StreamSink and RecordingSwitch that join vemd's sinks, and the StreamControl the loop calls
// between frames.
//
// Refused at start, in one sentence: a token file that cannot be read, is empty, is readable by
// group or others, or holds a token vemd does not accept (vemd::streamTokenProblem: too short,
// white space or control bytes inside; the token itself is never quoted); TLS files that do not
// load. A port that cannot be bound (taken, say) stops vemd too, its sentence naming the address
// and output.allow_missing; with output.allow_missing = true (--allow-missing-outputs) it is a
// warning and vemd runs without streaming. Disabled ([stream] enabled = false or
// listen = ""): nothing is started.
#pragma once

#include <expected>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "stream/stream_control.h"
#include "stream/stream_server.h"
#include "vemd/frame_source.h"
#include "vemd/sink.h"
#include "vemd/vemd_config.h"

namespace vem::stream {

// The token in `path` (surrounding white space removed), or why it cannot be used.
[[nodiscard]] std::expected<std::string, std::string> readTokenFile(
    const std::filesystem::path& path);

// The token clients present: stream.token, or the one in stream.token_file (read now); "" for
// none. vemd asks for it before its long start-up steps, so a bad token file stops it at once.
[[nodiscard]] std::expected<std::string, std::string> streamToken(const vemd::StreamConfig& config);

// "MODEL SERIAL #hash" of the source's camera file (FNV-1a 64 of its text), "none" without one.
[[nodiscard]] std::string calibrationId(const vemd::SourceDescription& source);

[[nodiscard]] std::expected<StreamServerOptions, std::string> serverOptions(
    const vemd::StreamConfig& config, const vemd::SourceDescription& source);

// Where control's start_recording writes (see vemd_config.h, StreamConfig::recordDir).
[[nodiscard]] std::filesystem::path controlRecordingFolder(const vemd::VemdConfig& config);

struct Streaming {
  std::unique_ptr<StreamServer> server;    // null: streaming is off
  std::unique_ptr<StreamControl> control;  // null with it
};

// Starts the server and appends its sinks to `sinks`; an empty Streaming when disabled, or when
// the port cannot be bound and output.allow_missing is set (logged).
[[nodiscard]] std::expected<Streaming, std::string> startStreaming(
    const vemd::VemdConfig& config, const vemd::SourceDescription& source,
    std::vector<std::unique_ptr<vemd::Sink>>& sinks);

}  // namespace vem::stream
