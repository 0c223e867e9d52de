// VemdConfig: everything vemd can be told, from config/vemd.toml (every key documented there with
// its default) and the command line, which overrides the file.
//
// File: TOML, sections [source], [camera], [bracketing], [processing], [filter], [clustering],
// [output], [stats], [log], [stream]; every
// key is optional (the built-in default applies), a key or section that is not listed is refused,
// and so is a value of the wrong type or out of range, in one sentence:
//   "vemd.toml: processing.lights: expected a whole number from 1 to 65536, found 0".
// Flags: --config FILE, --source SPEC, --frames N, --rate recorded|max|HZ, --loop, --lights N,
// --cluster Q (0: off), --out DIR, --record FILE, --jsonl FILE, --preview-every N (0: off),
// --stats-every S, --camera FILE, --list-devices, --stream-listen ADDR, --allow-missing-outputs,
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

// [stream]: the WebSocket server for render clients (daemon/stream/stream_server.h,
// docs/protocol.md). Listening beyond loopback needs a token (checked when the file is read), and a
// token given here must pass streamTokenProblem (below).
struct StreamConfig {
  bool enabled = true;
  std::string listen = "127.0.0.1:8765";  // "IPV4:PORT" or "[IPV6]:PORT"; port 0: any; "": off
  std::string token;                      // the bearer token; "": none (or token_file)
  std::string tokenFile;  // a file holding the token; must not be readable by group or others
  std::string tlsCert;    // PEM certificate chain: wss:// (with tls_key)
  std::string tlsKey;     // PEM private key
  std::int64_t maxClients = 64;
  std::int64_t sendTimeoutMs = 10'000;  // a send pending longer closes that client
  std::int64_t cubemapZstdLevel = 3;
  std::int64_t handshakeTimeoutMs = 3'000;    // TLS + upgrade request must end within
  std::int64_t maxHandshakes = 128;           // connections in their handshake at most
  std::int64_t maxHandshakesPerAddress = 32;  // of those from one address (more: 503)
  std::int64_t maxClientLagMs = 5'000;        // a client further behind is closed
  std::int64_t sendBufferBytes = 256 * 1024;  // SO_SNDBUF of each client socket
  std::int64_t cubemapMaxFacePx = 256;        // for clients without the token
  double cubemapMaxRateHz = 10.0;             // for clients without the token
  std::string recordDir;  // where control's start_recording writes; "": output.record's folder
                          // (when it is one), else output.dir
  friend bool operator==(const StreamConfig&, const StreamConfig&) = default;
};

// What vemd accepts as a stream token (stream.token, or the contents of stream.token_file), on
// every listener: on loopback too, where the token grants control (light count, filter,
// recordings) and any local user can connect. 16 visible ASCII characters are at least 64 bits
// even as hex, beyond guessing through WebSocket handshakes, and refuse typed words ("secret");
// `openssl rand -hex 32` makes a 64-character (256-bit) one. White space and control or non-ASCII
// bytes are refused: HTTP trims or mangles them, so no client could present such a token. At most
// 1024 bytes, so "Authorization: Bearer TOKEN" fits an HTTP request head.
inline constexpr std::size_t kMinStreamTokenBytes = 16;
inline constexpr std::size_t kMaxStreamTokenBytes = 1024;
// "a token of 16 to 1024 visible ASCII characters ...", for messages.
[[nodiscard]] std::string streamTokenExpected();
// What is wrong with `token` ("a token of 3 bytes", "white space at byte 5"), never quoting it (it
// is a secret); nullopt when vemd accepts it.
[[nodiscard]] std::optional<std::string> streamTokenProblem(std::string_view token);

// A parsed [stream] listen value.
struct ListenAddress {
  std::string host;  // the IP address without brackets
  std::uint16_t port = 0;
  bool loopback = false;  // 127.0.0.0/8 or ::1
};
// "127.0.0.1:8765", "[::1]:0", "0.0.0.0:8765"; nullopt when not of that form.
[[nodiscard]] std::optional<ListenAddress> parseListenAddress(const std::string& text);

struct VemdConfig {
  SourceConfig source;
  CameraConfig camera;
  BracketingConfig bracketing;
  ProcessingOptions processing;  // [processing], [filter] and [clustering]
  OutputConfig output;
  StatsConfig stats;
  LogConfig log;
  StreamConfig stream;
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
