// Streaming setup: from the [stream] settings (stream_settings.h) to the options of a listening
// StreamServer. vemd's setup (vemd/stream_wiring.h) starts the server with them and adds the
// StreamSink, the RecordingSwitch and the StreamControl.
//
// Refused at start, in one sentence: a token file that cannot be read, is empty, is readable by
// group or others, or holds a token vemd does not accept (streamTokenProblem: too short,
// white space or control bytes inside; the token itself is never quoted); a listen address
// beyond loopback without a token.
#pragma once

#include <expected>
#include <filesystem>
#include <string>

#include "frames/frame_source.h"
#include "stream/stream_server.h"
#include "stream/stream_settings.h"

namespace vem::stream {

// The token in `path` (surrounding white space removed), or why it cannot be used.
[[nodiscard]] std::expected<std::string, std::string> readTokenFile(
    const std::filesystem::path& path);

// The token clients present: stream.token, or the one in stream.token_file (read now); "" for
// none. vemd asks for it before its long start-up steps, so a bad token file stops it at once.
[[nodiscard]] std::expected<std::string, std::string> streamToken(const StreamSettings& config);

// "MODEL SERIAL #hash" of the source's camera file (FNV-1a 64 of its text), "none" without one.
[[nodiscard]] std::string calibrationId(const SourceDescription& source);

// What vemd says of itself on every connection (and on MQTT's retained hello): its version, the
// source, the calibration, the largest light count; the rest is the connection's.
[[nodiscard]] Hello helloFor(const SourceDescription& source);

[[nodiscard]] std::expected<StreamServerOptions, std::string> serverOptions(
    const StreamSettings& config, const SourceDescription& source);

}  // namespace vem::stream
