// Streaming in vemd: from vemd's configuration ([stream], [mqtt], and [output] for recordings and
// allow_missing) to a listening StreamServer (stream/stream_setup.h), the StreamSink and the
// RecordingSwitch (which records through vemd's recorder, sinks/recorder_sink.h) that join
// vemd's sinks, and the StreamControl the loop calls between frames. vemd is the one place that
// wires the stream to the recorder and the loop; the stream folder knows neither.
//
// A port that cannot be bound (taken, say) stops vemd, its sentence naming the address and
// output.allow_missing; with output.allow_missing = true (--allow-missing-outputs) it is a warning
// and vemd runs without streaming. TLS files that do not load always stop it. Disabled ([stream]
// enabled = false or listen = ""): nothing is started.
#pragma once

#include <expected>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "frames/frame_source.h"
#include "frames/sink.h"
#include "recording/recording_writer.h"
#include "stream/mqtt_publisher.h"
#include "stream/publisher_fan_out.h"
#include "stream/recording_switch.h"
#include "stream/stream_control.h"
#include "stream/stream_server.h"
#include "vemd/sinks/recording_context.h"
#include "vemd/vemd_config.h"

namespace vem::vemd {

// Where control's start_recording writes (see vemd_config.h, StreamConfig::recordDir).
[[nodiscard]] std::filesystem::path controlRecordingFolder(const VemdConfig& config);

// How the RecordingSwitch opens a recording: vemd's recorder with this header context and these
// writer options; for an empty file name a new time-stamped file (recorder_sink.h,
// recordingPathFor).
[[nodiscard]] stream::OpenRecording recorderOpener(RecordingContext context,
                                                   recording::WriterOptions options);

// Members in the order they may be destroyed (last first): the control borrows the publishers.
struct Streaming {
  std::unique_ptr<stream::StreamServer> server;        // null: no WebSocket server
  std::unique_ptr<stream::MqttPublisher> mqtt;         // null: no broker
  std::unique_ptr<stream::PublisherFanOut> both;       // with the two: what the sink feeds
  std::unique_ptr<stream::StreamControl> control;      // null when neither runs
};

// Starts the server and the MQTT publisher and appends their sinks to `sinks`; an empty Streaming
// when both are off, or when the port cannot be bound and output.allow_missing is set (logged).
// A broker that cannot be reached is no error: the publisher keeps trying (mqtt_publisher.h).
[[nodiscard]] std::expected<Streaming, std::string> startStreaming(
    const VemdConfig& config, const SourceDescription& source,
    std::vector<std::unique_ptr<Sink>>& sinks);

}  // namespace vem::vemd
