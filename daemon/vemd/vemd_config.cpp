#include "vemd/vemd_config.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>
#include <CLI/CLI.hpp>

#include "util/cli_conventions.h"
#include "util/mqtt_url.h"
#include "util/toml_reader.h"

#include "core/default_pattern.h"
#include "frames/raw_frame.h"
#include "vemd/config_toml.h"

namespace vem::vemd {

namespace {

// Ranges shared by the file and the flags.
constexpr std::int64_t kMaxFrames = std::numeric_limits<std::int64_t>::max();
// Each queued frame is a whole sensor image (and as many recycled spares wait beside the queue):
// docs/vemd.md, "Limits"; daemon_setup.h checks the bytes once the frame size is known.
constexpr std::int64_t kMaxQueueDepth = 64;
constexpr const char* kQueueDepthWhy = "every queued frame holds a whole sensor image";
constexpr double kMaxNoiseCode = 4096.0;
constexpr const char* kMapSizeWhy = "start-up time and memory grow with map_width x map_height";
constexpr std::int64_t kMaxClusterBudget = std::int64_t(kMaxLights);
constexpr double kMinCorrectionFactor = 0.1;
constexpr double kMaxCorrectionFactor = 10.0;
constexpr std::int64_t kMaxEvery = 1'000'000;
constexpr std::int64_t kMaxPreviewScale = 16;
// The preview image is map_width x preview_scale by map_height x preview_scale pixels, drawn and
// compressed on the processing thread (about 0.1 us per pixel, and up to 20 us per light drawn):
// docs/vemd.md, "Limits".
constexpr std::int64_t kMaxPreviewSidePx = 4096;
constexpr double kMaxStatsEveryS = 86400.0;
constexpr std::int64_t kMaxSensorSide = 65536;
constexpr double kMaxExposureUs = 60e6;  // a minute
constexpr double kMaxGain = 1e6;
constexpr const char* kRateExpected =
    "\"recorded\", \"max\" or a number of frames per second above 0 and at most 10000";

// The keys of each section, in the order config/vemd.toml documents them.
constexpr std::string_view kTopKeys[] = {"version",    "source", "camera",     "bracketing",
                                         "processing", "filter", "clustering", "output",
                                         "stats",      "log",    "stream",
                                         "mqtt"};
constexpr std::string_view kSourceKeys[] = {
    "spec",         "rate",   "loop",       "frames", "queue_depth", "retry_initial_ms",
    "retry_max_ms", "camera", "noise_code", "seed"};
constexpr std::string_view kCameraKeys[] = {"pixel_format", "width_px",  "height_px",
                                            "exposure_us",  "gain",      "frame_rate_hz",
                                            "buffers",      "timeout_ms"};
constexpr std::string_view kBracketingKeys[] = {"count", "stops", "base_exposure_us",
                                                "match_tolerance"};
constexpr std::string_view kProcessingKeys[] = {"map_width", "map_height", "lights", "sampler"};
constexpr std::string_view kFilterKeys[] = {"preset"};
constexpr std::string_view kClusteringKeys[] = {"enabled", "budget", "correction_factor"};
constexpr std::string_view kOutputKeys[] = {"dir",           "jsonl",
                                            "record",        "record_sync_every",
                                            "preview_every", "preview_numbered",
                                            "preview_scale", "allow_missing"};
constexpr std::string_view kStatsKeys[] = {"every_s"};
constexpr std::string_view kLogKeys[] = {"level", "format"};
const std::vector<std::string_view> kLogLevelNames{"trace", "debug", "info",
                                                   "warn",  "error", "off"};
const std::vector<std::string_view> kLogFormatNames{"text", "json"};
constexpr std::string_view kStreamKeys[] = {"enabled",
                                            "listen",
                                            "token",
                                            "token_file",
                                            "tls_cert",
                                            "tls_key",
                                            "max_clients",
                                            "send_timeout_ms",
                                            "cubemap_zstd_level",
                                            "record_dir",
                                            "handshake_timeout_ms",
                                            "max_handshakes",
                                            "max_handshakes_per_address",
                                            "max_client_lag_ms",
                                            "send_buffer_bytes",
                                            "cubemap_max_face_px",
                                            "cubemap_max_rate_hz"};
constexpr std::string_view kMqttKeys[] = {
    "url",     "prefix",     "camera_id",      "credentials_file", "tls_ca",
    "tls_cert", "tls_key",   "keep_alive_s",   "queue_messages",   "max_in_flight",
    "cubemap_rate_hz", "cubemap_face_px", "cubemap_levels"};
constexpr const char* kListenExpected =
    "\"IPV4:PORT\" or \"[IPV6]:PORT\" (an IP address, port 0 to 65535), or \"\" (no server)";

const std::vector<std::string_view> kSamplerNames{"havran", "standard"};
constexpr SamplerKind kSamplers[] = {SamplerKind::Havran, SamplerKind::Standard};

std::vector<std::string_view> presetNames() {
  std::vector<std::string_view> names;
  for (FilterPreset p : kAllPresets) names.emplace_back(presetName(p));
  return names;
}

void readSource(util::TomlReader r, SourceConfig& s) {
  r.onlyKeys(kSourceKeys, util::UnknownKeyWords::KeyOrSection);
  r.optionalText("spec", s.spec);
  r.optionalParsed("rate", kRateExpected, parseSourceRate, s.rate);
  r.optionalBoolean("loop", s.loop);
  r.optionalWholeNumber("frames", 0, kMaxFrames, s.frames);
  r.optionalWholeNumber("queue_depth", 1, kMaxQueueDepth, s.queueDepth, kQueueDepthWhy);
  r.optionalWholeNumber("retry_initial_ms", 1, 60'000, s.retryInitialMs);
  r.optionalWholeNumber("retry_max_ms", 1, 600'000, s.retryMaxMs);
  r.optionalText("camera", s.camera);
  r.optionalNumber("noise_code", 0.0, kMaxNoiseCode, s.noiseCode);
  r.optionalWholeNumber("seed", 0, kMaxFrames, s.seed);
  if (s.retryMaxMs < s.retryInitialMs) {
    r.failExpected("retry_max_ms",
                   fmt::format("at least source.retry_initial_ms ({})", s.retryInitialMs),
                   std::to_string(s.retryMaxMs));
  }
}

void readCamera(util::TomlReader r, CameraConfig& c) {
  r.onlyKeys(kCameraKeys, util::UnknownKeyWords::KeyOrSection);
  r.optionalText("pixel_format", c.pixelFormat);
  if (!c.pixelFormat.empty() && !parsePixelFormat(c.pixelFormat)) {
    r.failExpected("pixel_format",
                   "\"\", \"Mono8\", \"Mono10\", \"Mono12\", \"Mono16\", \"RGB8\" ... \"RGB16\"",
                   "the string \"" + c.pixelFormat + "\"");
  }
  r.optionalWholeNumber("width_px", 0, kMaxSensorSide, c.widthPx);
  r.optionalWholeNumber("height_px", 0, kMaxSensorSide, c.heightPx);
  r.optionalNumber("exposure_us", 0.0, kMaxExposureUs, c.exposureUs);
  r.optionalNumber("gain", 0.0, kMaxGain, c.gain);
  r.optionalNumber("frame_rate_hz", 0.0, 10000.0, c.frameRateHz);
  r.optionalWholeNumber("buffers", 2, 64, c.buffers);
  r.optionalWholeNumber("timeout_ms", 1, 600'000, c.timeoutMs);
}

void readBracketing(util::TomlReader r, BracketingConfig& b) {
  r.onlyKeys(kBracketingKeys, util::UnknownKeyWords::KeyOrSection);
  r.optionalWholeNumber("count", 0, 9, b.count);
  if (b.count == 1) r.failExpected("count", "0 (off) or 2 to 9", "1");
  r.optionalNumber("stops", 0.5, 8.0, b.stops);
  r.optionalNumber("base_exposure_us", 1.0, 1e7, b.baseExposureUs);
  r.optionalNumber("match_tolerance", 0.001, 0.5, b.matchTolerance);
}

void readProcessing(util::TomlReader r, ProcessingOptions& p) {
  r.onlyKeys(kProcessingKeys, util::UnknownKeyWords::KeyOrSection);
  r.optionalWholeNumber("map_width", kMinMapSide, kMaxMapWidth, p.mapWidth, kMapSizeWhy);
  r.optionalWholeNumber("map_height", kMinMapSide, kMaxMapHeight, p.mapHeight, kMapSizeWhy);
  r.optionalWholeNumber("lights", 1, std::int64_t(kMaxLights), p.lightCount);
  std::size_t sampler = p.sampler == SamplerKind::Havran ? 0 : 1;
  r.optionalChoice("sampler", kSamplerNames, sampler);
  p.sampler = kSamplers[sampler];
}

void readFilter(util::TomlReader r, ProcessingOptions& p) {
  r.onlyKeys(kFilterKeys, util::UnknownKeyWords::KeyOrSection);
  std::size_t preset = 0;
  while (kAllPresets[preset] != p.filter) ++preset;
  r.optionalChoice("preset", presetNames(), preset);
  p.filter = kAllPresets[preset];
}

void readClustering(util::TomlReader r, ProcessingOptions& p) {
  r.onlyKeys(kClusteringKeys, util::UnknownKeyWords::KeyOrSection);
  r.optionalBoolean("enabled", p.clustering);
  r.optionalWholeNumber("budget", 1, kMaxClusterBudget, p.clusterBudget);
  r.optionalNumber("correction_factor", kMinCorrectionFactor, kMaxCorrectionFactor,
                   p.clusterCorrectionFactor);
}

// The largest preview_scale for `mapWidth` x `mapHeight` maps (at least 1: maps are at most
// kMaxPreviewSidePx wide).
std::int64_t maxPreviewScale(int mapWidth, int mapHeight) {
  const std::int64_t longerSide = std::max(mapWidth, mapHeight);
  return std::clamp<std::int64_t>(kMaxPreviewSidePx / longerSide, 1, kMaxPreviewScale);
}

// Why the preview would be too large, as "expected ..." (for the file) or nullopt; checked only
// while the preview is on, so the shipped preview_scale = 2 stands beside any map without one.
std::optional<std::string> previewScaleExpected(const OutputConfig& o, const ProcessingOptions& p) {
  const std::int64_t most = maxPreviewScale(p.mapWidth, p.mapHeight);
  if (o.previewEvery == 0 || o.previewScale <= most) return std::nullopt;
  return fmt::format(
      "a whole number from 1 to {} while output.preview_every is on (the preview is the {} x {} "
      "map times preview_scale, at most {} pixels on a side)",
      most, p.mapWidth, p.mapHeight, kMaxPreviewSidePx);
}

void readOutput(util::TomlReader r, OutputConfig& o, const ProcessingOptions& p) {
  r.onlyKeys(kOutputKeys, util::UnknownKeyWords::KeyOrSection);
  r.optionalText("dir", o.dir);
  r.optionalText("jsonl", o.jsonl);
  r.optionalText("record", o.record);
  r.optionalWholeNumber("record_sync_every", 0, kMaxEvery, o.recordSyncEvery);
  r.optionalWholeNumber("preview_every", 0, kMaxEvery, o.previewEvery);
  r.optionalBoolean("preview_numbered", o.previewNumbered);
  r.optionalWholeNumber("preview_scale", 1, kMaxPreviewScale, o.previewScale);
  r.optionalBoolean("allow_missing", o.allowMissing);
  if (auto expected = previewScaleExpected(o, p)) {
    r.failExpected("preview_scale", *expected, std::to_string(o.previewScale));
  }
}

void readStats(util::TomlReader r, StatsConfig& s) {
  r.onlyKeys(kStatsKeys, util::UnknownKeyWords::KeyOrSection);
  r.optionalNumber("every_s", 0.0, kMaxStatsEveryS, s.everyS);
}

// A string of `names` into `out`.
void readName(util::TomlReader& r, std::string_view key, const std::vector<std::string_view>& names,
              std::string& out) {
  std::size_t index = 0;
  while (index < names.size() && names[index] != out) ++index;
  r.optionalChoice(key, names, index);
  if (index < names.size()) out = std::string(names[index]);
}

void readLog(util::TomlReader r, LogConfig& l) {
  r.onlyKeys(kLogKeys, util::UnknownKeyWords::KeyOrSection);
  readName(r, "level", kLogLevelNames, l.level);
  readName(r, "format", kLogFormatNames, l.format);
}

void readStream(util::TomlReader r, StreamConfig& s) {
  r.onlyKeys(kStreamKeys, util::UnknownKeyWords::KeyOrSection);
  r.optionalBoolean("enabled", s.enabled);
  r.optionalText("listen", s.listen);
  if (!s.listen.empty() && !parseListenAddress(s.listen)) {
    r.failExpected("listen", kListenExpected, "the string \"" + s.listen + "\"");
  }
  r.optionalText("token", s.token);
  if (!s.token.empty()) {
    if (auto problem = streamTokenProblem(s.token)) {
      r.failExpected("token", streamTokenExpected(), *problem);
    }
  }
  r.optionalText("token_file", s.tokenFile);
  r.optionalText("tls_cert", s.tlsCert);
  r.optionalText("tls_key", s.tlsKey);
  if (s.tlsCert.empty() != s.tlsKey.empty()) {
    r.failExpected(s.tlsCert.empty() ? "tls_cert" : "tls_key",
                   "both stream.tls_cert and stream.tls_key (PEM files), or neither", "only one");
  }
  r.optionalWholeNumber("max_clients", 1, 4096, s.maxClients);
  r.optionalWholeNumber("send_timeout_ms", 100, 600'000, s.sendTimeoutMs);
  r.optionalWholeNumber("cubemap_zstd_level", 1, 19, s.cubemapZstdLevel);
  r.optionalText("record_dir", s.recordDir);
  r.optionalWholeNumber("handshake_timeout_ms", 100, 60'000, s.handshakeTimeoutMs);
  r.optionalWholeNumber("max_handshakes", 1, 4096, s.maxHandshakes);
  r.optionalWholeNumber("max_handshakes_per_address", 1, 4096, s.maxHandshakesPerAddress);
  r.optionalWholeNumber("max_client_lag_ms", 100, 600'000, s.maxClientLagMs);
  r.optionalWholeNumber("send_buffer_bytes", 4096, 16 * 1024 * 1024, s.sendBufferBytes);
  r.optionalWholeNumber("cubemap_max_face_px", 64, 512, s.cubemapMaxFacePx);
  r.optionalNumber("cubemap_max_rate_hz", 0.0, 60.0, s.cubemapMaxRateHz);
  if (!s.token.empty() && !s.tokenFile.empty()) {
    r.failExpected("token_file", "stream.token or stream.token_file, not both", "both");
  }
  const auto address = parseListenAddress(s.listen);
  if (s.enabled && address && !address->loopback && s.token.empty() && s.tokenFile.empty()) {
    r.failExpected(
        "listen",
        "a loopback address (127.0.0.1, [::1]) unless stream.token or stream.token_file is "
        "set: listening beyond loopback needs a token",
        "the string \"" + s.listen + "\"");
  }
}

void readMqtt(util::TomlReader r, stream::MqttSettings& m) {
  r.onlyKeys(kMqttKeys, util::UnknownKeyWords::KeyOrSection);
  r.optionalText("url", m.url);
  if (!m.url.empty()) {
    if (auto url = util::parseMqttUrl(m.url); !url) {
      r.failExpected("url", "mqtt://[USER@]HOST[:PORT][/PREFIX[/CAMERA]], mqtts://..., or \"\"",
                     url.error());
    }
  }
  r.optionalText("prefix", m.prefix);
  if (std::string p = util::topicLevelProblem(m.prefix); !p.empty()) {
    r.failExpected("prefix", "one topic level", p);
  }
  r.optionalText("camera_id", m.cameraId);
  if (std::string p = util::topicLevelProblem(m.cameraId); !m.cameraId.empty() && !p.empty()) {
    r.failExpected("camera_id", "one topic level, or \"\" (the host name)", p);
  }
  r.optionalText("credentials_file", m.credentialsFile);
  r.optionalText("tls_ca", m.tlsCa);
  r.optionalText("tls_cert", m.tlsCert);
  r.optionalText("tls_key", m.tlsKey);
  if (m.tlsCert.empty() != m.tlsKey.empty()) {
    r.failExpected(m.tlsCert.empty() ? "tls_cert" : "tls_key",
                   "both mqtt.tls_cert and mqtt.tls_key (PEM files), or neither", "only one");
  }
  r.optionalWholeNumber("keep_alive_s", 5, 3600, m.keepAliveS);
  r.optionalWholeNumber("queue_messages", 1, 4096, m.queueMessages);
  r.optionalWholeNumber("max_in_flight", 1, 1024, m.maxInFlight);
  r.optionalNumber("cubemap_rate_hz", 0.0, 60.0, m.cubemapRateHz);
  r.optionalWholeNumber("cubemap_face_px", 8, 512, m.cubemapFacePx);
  r.optionalWholeNumber("cubemap_levels", 1, 8, m.cubemapLevels);
}

// The section `name` of the document, or an empty table when it is absent; a failure when it is
// not a table.
const toml::table& section(const toml::table& document, std::string_view name,
                           util::TomlReader& top) {
  static const toml::table empty;
  const toml::node* node = document.get(name);
  if (node == nullptr) return empty;
  if (!node->is_table()) {
    top.failExpected(name, fmt::format("a table ([{}])", name), util::describeTomlNode(*node));
    return empty;
  }
  return *node->as_table();
}

// ---- command line ----

std::string wholeNumberProblem(const std::string& text, std::int64_t min, std::int64_t max) {
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc() && end == text.data() + text.size() && value >= min && value <= max) {
    return {};
  }
  return fmt::format("expected a whole number from {} to {}, found {}", min, max, text);
}

CLI::Validator wholeNumberCheck(std::int64_t min, std::int64_t max) {
  return CLI::Validator(
      [min, max](std::string& text) { return wholeNumberProblem(text, min, max); }, "");
}

CLI::Validator numberCheck(double min, double max) {
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        double value = 0.0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec == std::errc() && end == text.data() + text.size() && std::isfinite(value) &&
            value >= min && value <= max) {
          return {};
        }
        return fmt::format("expected a number from {} to {}, found {}", min, max, text);
      },
      "");
}

// One of `names`.
CLI::Validator nameCheck(const std::vector<std::string_view>& names) {
  return CLI::Validator(
      [&names](std::string& text) -> std::string {
        if (std::find(names.begin(), names.end(), text) != names.end()) return {};
        return fmt::format("expected one of {}, found {}", fmt::join(names, "|"), text);
      },
      "");
}

CLI::Validator rateCheck() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (parseSourceRate(text)) return {};
        return fmt::format("expected {}, found {}", kRateExpected, text);
      },
      "");
}

struct Flags {
  std::optional<std::string> config, source, rate, out, record, jsonl, camera, streamListen, mqtt;
  std::optional<std::string> logLevel, logFormat;
  std::optional<std::uint64_t> frames;
  std::optional<std::size_t> lights;
  std::optional<int> cluster;
  std::optional<std::int64_t> previewEvery;
  std::optional<double> statsEvery;
  bool loop = false;
  bool previewNumbered = false;
  bool listDevices = false;
  bool allowMissingOutputs = false;
  bool quiet = false;
  bool printConfig = false;
};

void addFlags(CLI::App& app, Flags& f) {
  app.add_option("--config", f.config, "Configuration file (TOML; see config/vemd.toml)")
      ->type_name("FILE");
  app.add_option("--source", f.source,
                 "replay:FILE.vem | synthetic:SCENE | aravis:ID | v4l2:DEVICE | libcamera:ID")
      ->type_name("SPEC");
  app.add_option("--camera", f.camera,
                 "The camera file (calibration; for synthetic scenes the simulated camera)")
      ->type_name("FILE");
  app.add_flag("--list-devices", f.listDevices, "List the cameras every backend sees, and exit");
  app.add_option("--frames", f.frames, "Stop after N frames from the source (0: no limit)")
      ->type_name("N")
      ->default_str("0")
      ->check(wholeNumberCheck(0, kMaxFrames));
  app.add_option("--rate", f.rate, "The pace of the source: recorded, max or frames per second")
      ->type_name("recorded|max|HZ")
      ->default_str("recorded")
      ->check(rateCheck());
  app.add_flag("--loop", f.loop, "Replay the recording again and again");
  app.add_option("--lights", f.lights, "Lights per frame, 1 to 65536")
      ->type_name("N")
      ->default_str("1024")
      ->check(wholeNumberCheck(1, std::int64_t(kMaxLights)));
  app.add_option("--cluster", f.cluster, "Cluster toward about Q lights (0: no clustering)")
      ->type_name("Q")
      ->default_str("72")
      ->check(wholeNumberCheck(0, kMaxClusterBudget));
  app.add_option("--out", f.out, "Folder for the preview and relative --jsonl/--record paths")
      ->type_name("DIR");
  app.add_option("--record", f.record, "Record frames and lights into a new .vem (or a folder)")
      ->type_name("FILE");
  app.add_option("--jsonl", f.jsonl, "Append each frame's lights to a JSON-lines file")
      ->type_name("FILE");
  app.add_option("--preview-every", f.previewEvery, "Write preview.png every N frames (0: off)")
      ->type_name("N")
      ->default_str("0")
      ->check(wholeNumberCheck(0, kMaxEvery));
  app.add_option("--mqtt", f.mqtt,
                 "Publish through an MQTT broker too: mqtt://[USER@]HOST[:PORT][/PREFIX[/CAMERA]] "
                 "or mqtts://... (\"\": none; [mqtt] sets the rest)")
      ->type_name("URL")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            if (text.empty()) return {};
            auto url = util::parseMqttUrl(text);
            return url ? std::string() : url.error();
          },
          ""));
  app.add_option("--stream-listen", f.streamListen,
                 "Stream to render clients on IP:PORT (\"\": no server; port 0: any)")
      ->type_name("ADDR")
      ->default_str("127.0.0.1:8765")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            if (text.empty() || parseListenAddress(text)) return {};
            return fmt::format("expected {}, found {}", kListenExpected, text);
          },
          ""));
  app.add_flag("--preview-numbered", f.previewNumbered,
               "Also keep every preview as preview-SEQ.png");
  app.add_flag("--allow-missing-outputs", f.allowMissingOutputs,
               "Run on when a configured output (file, recording, preview, stream port) cannot "
               "open, with a warning; without it vemd stops (exit 1)");
  auto* logLevel =
      app.add_option("--log-level", f.logLevel, "Log messages of this level and above (off: none)")
          ->check(nameCheck(kLogLevelNames))
          ->type_name("trace|debug|info|warn|error|off")
          ->default_str("info");
  app.add_flag("--quiet", f.quiet, "Log warnings and errors only (--log-level warn)")
      ->excludes(logLevel);
  app.add_option("--log-format", f.logFormat,
                 "Log lines as text, or as one JSON object each (time, level, logger, message)")
      ->check(nameCheck(kLogFormatNames))
      ->type_name("text|json")
      ->default_str("text");
  app.add_flag("--print-config", f.printConfig,
               "Print the configuration in force (file, defaults and flags merged) as TOML, "
               "and exit");
  app.add_option("--stats-every", f.statsEvery, "A statistics line every S seconds (0: at exit)")
      ->type_name("S")
      ->default_str("5")
      ->check(numberCheck(0.0, kMaxStatsEveryS));
}

void applyFlags(const Flags& f, VemdConfig& c) {
  if (f.source) c.source.spec = *f.source;
  if (f.camera) c.source.camera = *f.camera;
  if (f.listDevices) c.listDevices = true;
  if (f.frames) c.source.frames = *f.frames;
  if (f.rate) c.source.rate = *parseSourceRate(*f.rate);
  if (f.loop) c.source.loop = true;
  if (f.lights) c.processing.lightCount = *f.lights;
  if (f.cluster) {
    c.processing.clustering = *f.cluster > 0;
    if (*f.cluster > 0) c.processing.clusterBudget = *f.cluster;
  }
  if (f.out) c.output.dir = *f.out;
  if (f.record) c.output.record = *f.record;
  if (f.jsonl) c.output.jsonl = *f.jsonl;
  if (f.previewEvery) c.output.previewEvery = *f.previewEvery;
  if (f.previewNumbered) c.output.previewNumbered = true;
  if (f.statsEvery) c.stats.everyS = *f.statsEvery;
  if (f.streamListen) c.stream.listen = *f.streamListen;
  if (f.mqtt) c.mqtt.url = *f.mqtt;
  if (f.allowMissingOutputs) c.output.allowMissing = true;
  if (f.logLevel) c.log.level = *f.logLevel;
  if (f.quiet) c.log.level = "warn";
  if (f.logFormat) c.log.format = *f.logFormat;
}

// --preview-every may turn on a preview too large for the file's map and scale.
std::optional<std::string> previewProblem(const VemdConfig& c) {
  if (!previewScaleExpected(c.output, c.processing)) return std::nullopt;
  return fmt::format(
      "--preview-every: the preview would be {} x {} pixels (the {} x {} map times "
      "output.preview_scale = {}), where at most {} on a side was expected; set "
      "output.preview_scale to {}",
      std::int64_t(c.processing.mapWidth) * c.output.previewScale,
      std::int64_t(c.processing.mapHeight) * c.output.previewScale, c.processing.mapWidth,
      c.processing.mapHeight, c.output.previewScale, kMaxPreviewSidePx,
      maxPreviewScale(c.processing.mapWidth, c.processing.mapHeight));
}

// The flags may move the listener beyond loopback: the file's rule again.
std::optional<std::string> streamProblem(const StreamConfig& s) {
  const auto address = parseListenAddress(s.listen);
  if (s.enabled && address && !address->loopback && s.token.empty() && s.tokenFile.empty()) {
    return fmt::format(
        "--stream-listen: {} is beyond loopback, which needs stream.token or stream.token_file "
        "in the configuration",
        s.listen);
  }
  return std::nullopt;
}

constexpr const char* kFooter =
    "Examples:\n"
    "  vemd --source replay:sky.vem --rate max --frames 300\n"
    "  vemd --config /etc/vemcast/vemd.toml\n"
    "  vemd --source synthetic:sky --jsonl lights.jsonl --record runs/\n"
    "  vemd --source v4l2:/dev/video0 --camera my-camera.toml --preview-every 30\n"
    "  vemd --list-devices\n"
    "Flags override the configuration file (defaults above are the built-in ones);\n"
    "config/vemd.toml documents every key. A configuration file that cannot be read or holds a\n"
    "bad key is a usage error (exit 2), like a bad flag. SIGINT and SIGTERM stop vemd cleanly\n"
    "(sinks closed, a recording indexed; exit 0).";

}  // namespace

const std::vector<ConfigSection>& configSchema() {
  static const std::vector<ConfigSection> schema = [] {
    const auto list = [](std::span<const std::string_view> keys) {
      return std::vector<std::string>(keys.begin(), keys.end());
    };
    return std::vector<ConfigSection>{{"", {"version"}},
                                      {"source", list(kSourceKeys)},
                                      {"camera", list(kCameraKeys)},
                                      {"bracketing", list(kBracketingKeys)},
                                      {"processing", list(kProcessingKeys)},
                                      {"filter", list(kFilterKeys)},
                                      {"clustering", list(kClusteringKeys)},
                                      {"output", list(kOutputKeys)},
                                      {"stats", list(kStatsKeys)},
                                      {"log", list(kLogKeys)},
                                      {"stream", list(kStreamKeys)},
                                      {"mqtt", list(kMqttKeys)}};
  }();
  return schema;
}

std::expected<VemdConfig, std::string> parseConfig(const std::string& text,
                                                   const std::string& sourceName) {
  const auto document = util::parseToml(text, sourceName);
  if (!document) return std::unexpected(document.error().message);
  util::TomlStatus status{sourceName, std::nullopt};
  VemdConfig config;
  util::TomlReader top(*document, "", status);
  top.onlyKeys(kTopKeys, util::UnknownKeyWords::KeyOrSection);
  std::int64_t version = 1;
  top.optionalWholeNumber("version", 1, 1, version);
  readSource({section(*document, "source", top), "source.", status}, config.source);
  readCamera({section(*document, "camera", top), "camera.", status}, config.camera);
  readBracketing({section(*document, "bracketing", top), "bracketing.", status}, config.bracketing);
  readProcessing({section(*document, "processing", top), "processing.", status}, config.processing);
  readFilter({section(*document, "filter", top), "filter.", status}, config.processing);
  readClustering({section(*document, "clustering", top), "clustering.", status}, config.processing);
  readOutput({section(*document, "output", top), "output.", status}, config.output,
             config.processing);
  readStats({section(*document, "stats", top), "stats.", status}, config.stats);
  readLog({section(*document, "log", top), "log.", status}, config.log);
  readStream({section(*document, "stream", top), "stream.", status}, config.stream);
  readMqtt({section(*document, "mqtt", top), "mqtt.", status}, config.mqtt);
  if (!status.ok()) return std::unexpected(status.failure->message);
  return config;
}

std::expected<VemdConfig, std::string> loadConfigFile(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    return std::unexpected(fmt::format("{}: no such file", path.string()));
  }
  if (std::filesystem::is_directory(path, error)) {
    return std::unexpected(fmt::format("{}: a folder, not a configuration file", path.string()));
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) {
    return std::unexpected(fmt::format("{}: cannot read the file", path.string()));
  }
  return parseConfig(text.str(), path.string());
}

std::expected<VemdConfig, CommandLineExit> parseCommandLine(const std::vector<std::string>& args) {
  CLI::App app{"vemd: turns an HDR fisheye camera's frames into directional lights"};
  app.footer(kFooter);
  app.set_version_flag("--version", "vemd " VEM_VERSION);
  Flags flags;
  addFlags(app, flags);
  cli::applyConventions(app, "vemd");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    app.parse(int(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    std::ostringstream out, err;
    const int code = cli::exitStatusFor(app, e, out, err);  // 0 for --help and --version, else 2
    return std::unexpected(CommandLineExit{code, out.str(), err.str()});
  }
  VemdConfig config;
  if (flags.config) {
    auto loaded = loadConfigFile(*flags.config);
    if (!loaded) {
      return std::unexpected(CommandLineExit{cli::kExitUsage, "", loaded.error() + "\n"});
    }
    config = std::move(*loaded);
  }
  applyFlags(flags, config);
  if (auto problem = streamProblem(config.stream)) {
    return std::unexpected(CommandLineExit{cli::kExitUsage, "", *problem + "\n"});
  }
  if (auto problem = previewProblem(config)) {
    return std::unexpected(CommandLineExit{cli::kExitUsage, "", *problem + "\n"});
  }
  if (flags.printConfig) return std::unexpected(CommandLineExit{0, formatConfigToml(config), ""});
  return config;
}

}  // namespace vem::vemd
