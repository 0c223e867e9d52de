// VemdConfig: everything vemd can be told, from config/vemd.toml (every key documented there with
// its default) and the command line, which overrides the file.
//
// File: TOML, sections [source], [camera], [bracketing], [processing], [filter], [clustering],
// [output], [stats], [log], [stream], [mqtt]; every
// key is optional (the built-in default applies), a key or section that is not listed is refused,
// and so is a value of the wrong type or out of range, in one sentence:
//   "vemd.toml: processing.lights: expected a whole number from 1 to 65536, found 0".
// Flags: --config FILE, --source SPEC, --frames N, --rate recorded|max|HZ, --loop, --lights N,
// --cluster Q (0: off), --out DIR, --record FILE, --jsonl FILE, --preview-every N (0: off),
// --stats-every S, --camera FILE, --list-devices, --stream-listen ADDR, --mqtt URL, --allow-missing-outputs,
// --log-level L, --quiet, --log-format F, --print-config (prints the merged configuration as
// TOML and exits 0: config_toml.h); a bad flag value is refused
// the same way ("--lights: expected ...").
//
// Units are in the key names: ..._ms milliseconds, ..._s seconds, rate in frames per second.
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stream/mqtt_settings.h"
#include "stream/stream_settings.h"
#include "vemd/pipeline.h"
#include "vemd/source_rate.h"

namespace vem::vemd {

struct SourceConfig {
  std::string spec;  // "replay:FILE" or "synthetic:SCENE"; required (here or --source)
  SourceRate rate;   // "recorded" | "max" | Hz
  bool loop = false;
  std::uint64_t frames = 0;  // stop after this many frames; 0: no limit
  std::size_t queueDepth = 4;
  std::int64_t retryInitialMs = 100;
  std::int64_t retryMaxMs = 5000;
  std::string camera;  // the camera file: synthetic (its truth; "": the built-in example camera)
                       // and live cameras (their calibration; required)
  double noiseCode = 0.0;  // synthetic: Gaussian read noise, in codes
  std::uint64_t seed = 1;  // synthetic: the noise, and the clouds scene's field
  friend bool operator==(const SourceConfig&, const SourceConfig&) = default;
};

struct OutputConfig {
  std::string dir;     // where the preview goes and relative jsonl/record paths lead; "": "."
  std::string jsonl;   // JSON-lines light file; "": none
  std::string record;  // a .vem file or a folder for new ones; "": none
  std::int64_t recordSyncEvery = 30;  // fdatasync the recording every N frames; 0: at close only
  std::int64_t previewEvery = 0;      // write preview.png every N frames; 0: no preview
  bool previewNumbered = false;       // also keep preview-SEQ.png files
  std::int64_t previewScale = 2;      // preview pixels per polar-map pixel
  // A configured output (these files, the stream server) that cannot open: false stops vemd
  // (exit 1), true lets it run without that output, with a warning.
  bool allowMissing = false;
  friend bool operator==(const OutputConfig&, const OutputConfig&) = default;
};

// [camera]: what vemd asks of a live camera (aravis:, v4l2:, libcamera:; docs/cameras.md).
// 0 or "" leaves the camera's own value.
struct CameraConfig {
  std::string pixelFormat;  // "Mono8" ... "RGB16" (calib's names); "": the deepest offered
  std::int64_t widthPx = 0;
  std::int64_t heightPx = 0;
  double exposureUs = 0.0;   // manual exposure, microseconds; 0: the camera's (auto) exposure
  double gain = 0.0;         // linear (1 = unity); 0: the camera's
  double frameRateHz = 0.0;  // 0: the camera's
  std::int64_t buffers = 4;
  std::int64_t timeoutMs = 1000;
  friend bool operator==(const CameraConfig&, const CameraConfig&) = default;
};

// [bracketing]: exposure bracketing for cameras without an HDR sensor (docs/cameras.md).
struct BracketingConfig {
  std::int64_t count = 0;          // exposures per group; 0: off, else 2 to 9
  double stops = 2.0;              // between neighbouring exposures
  double baseExposureUs = 1000.0;  // the shortest exposure
  double matchTolerance = 0.05;    // a frame's reported exposure vs the bracket's, relative
  friend bool operator==(const BracketingConfig&, const BracketingConfig&) = default;
};

// [log]: what vemd logs and how (util/log_setup.h).
struct LogConfig {
  std::string level = "info";   // trace|debug|info|warn|error|off (--log-level; --quiet: warn)
  std::string format = "text";  // text|json (--log-format)
  friend bool operator==(const LogConfig&, const LogConfig&) = default;
};

struct StatsConfig {
  double everyS = 5.0;  // a report line every this many seconds; 0: only at exit
  friend bool operator==(const StatsConfig&, const StatsConfig&) = default;
};

// [stream]: the stream server's settings and what vemd accepts as a token and an address
// (stream/stream_settings.h); vemd's configuration holds them.
using StreamConfig = stream::StreamSettings;
using stream::kMaxStreamTokenBytes;
using stream::kMinStreamTokenBytes;
using stream::ListenAddress;
using stream::parseListenAddress;
using stream::streamTokenExpected;
using stream::streamTokenProblem;

struct VemdConfig {
  SourceConfig source;
  CameraConfig camera;
  BracketingConfig bracketing;
  ProcessingOptions processing;  // [processing], [filter] and [clustering]
  OutputConfig output;
  StatsConfig stats;
  LogConfig log;
  StreamConfig stream;
  stream::MqttSettings mqtt;  // [mqtt] (--mqtt URL): the stream through a broker
  bool listDevices = false;  // --list-devices (command line only): list the cameras and exit
  friend bool operator==(const VemdConfig&, const VemdConfig&) = default;
};

// Every key the loader knows, by section ("" for the top level), in the order config/vemd.toml
// documents them.
struct ConfigSection {
  std::string name;
  std::vector<std::string> keys;
};
[[nodiscard]] const std::vector<ConfigSection>& configSchema();

// Loads a configuration file on top of the built-in defaults.
[[nodiscard]] std::expected<VemdConfig, std::string> loadConfigFile(
    const std::filesystem::path& path);
// The same from TOML text; `sourceName` names it in messages.
[[nodiscard]] std::expected<VemdConfig, std::string> parseConfig(const std::string& text,
                                                                 const std::string& sourceName);

// What the command line asks for: a configuration to run, or an exit (help, version, a bad flag)
// with the text to print.
struct CommandLineExit {
  int exitCode = 0;
  std::string out;  // for stdout (help, version)
  std::string err;  // for stderr (the problem)
};

// argv[0] is the program's name. Reads --config FILE first (when given), then applies the other
// flags over it.
[[nodiscard]] std::expected<VemdConfig, CommandLineExit> parseCommandLine(
    const std::vector<std::string>& args);

}  // namespace vem::vemd
