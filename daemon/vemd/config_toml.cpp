#include "vemd/config_toml.h"

#include <sstream>

namespace vem::vemd {
namespace {

// A uint64 count that the loader caps at int64's largest.
std::int64_t whole(std::uint64_t value) { return std::int64_t(value); }

toml::table sourceTable(const SourceConfig& s) {
  toml::table t{{"spec", s.spec}};
  if (s.rate.mode == SourceRate::Mode::Fixed) {
    t.insert("rate", s.rate.hz);
  } else {
    t.insert("rate", formatSourceRate(s.rate));
  }
  t.insert("loop", s.loop);
  t.insert("frames", whole(s.frames));
  t.insert("queue_depth", std::int64_t(s.queueDepth));
  t.insert("retry_initial_ms", s.retryInitialMs);
  t.insert("retry_max_ms", s.retryMaxMs);
  t.insert("camera", s.camera);
  t.insert("noise_code", s.noiseCode);
  t.insert("seed", whole(s.seed));
  return t;
}

toml::table cameraTable(const CameraConfig& c) {
  return toml::table{
      {"pixel_format", c.pixelFormat}, {"width_px", c.widthPx},    {"height_px", c.heightPx},
      {"exposure_us", c.exposureUs},   {"gain", c.gain},           {"frame_rate_hz", c.frameRateHz},
      {"buffers", c.buffers},          {"timeout_ms", c.timeoutMs}};
}

toml::table bracketingTable(const BracketingConfig& b) {
  return toml::table{{"count", b.count},
                     {"stops", b.stops},
                     {"base_exposure_us", b.baseExposureUs},
                     {"match_tolerance", b.matchTolerance}};
}

toml::table outputTable(const OutputConfig& o) {
  return toml::table{{"dir", o.dir},
                     {"jsonl", o.jsonl},
                     {"record", o.record},
                     {"record_sync_every", o.recordSyncEvery},
                     {"preview_every", o.previewEvery},
                     {"preview_numbered", o.previewNumbered},
                     {"preview_scale", o.previewScale},
                     {"allow_missing", o.allowMissing}};
}

toml::table streamTable(const StreamConfig& s) {
  return toml::table{{"enabled", s.enabled},
                     {"listen", s.listen},
                     {"token_file", s.tokenFile},
                     {"tls_cert", s.tlsCert},
                     {"tls_key", s.tlsKey},
                     {"max_clients", s.maxClients},
                     {"handshake_timeout_ms", s.handshakeTimeoutMs},
                     {"max_handshakes", s.maxHandshakes},
                     {"max_handshakes_per_address", s.maxHandshakesPerAddress},
                     {"send_timeout_ms", s.sendTimeoutMs},
                     {"max_client_lag_ms", s.maxClientLagMs},
                     {"send_buffer_bytes", s.sendBufferBytes},
                     {"cubemap_max_face_px", s.cubemapMaxFacePx},
                     {"cubemap_max_rate_hz", s.cubemapMaxRateHz},
                     {"cubemap_zstd_level", s.cubemapZstdLevel},
                     {"record_dir", s.recordDir}};
}

toml::table mqttTable(const stream::MqttSettings& m) {
  return toml::table{{"url", m.url},
                     {"prefix", m.prefix},
                     {"camera_id", m.cameraId},
                     {"credentials_file", m.credentialsFile},
                     {"tls_ca", m.tlsCa},
                     {"tls_cert", m.tlsCert},
                     {"tls_key", m.tlsKey},
                     {"keep_alive_s", m.keepAliveS},
                     {"queue_messages", m.queueMessages},
                     {"max_in_flight", m.maxInFlight},
                     {"cubemap_rate_hz", m.cubemapRateHz},
                     {"cubemap_face_px", m.cubemapFacePx},
                     {"cubemap_levels", m.cubemapLevels}};
}

}  // namespace

toml::table configTable(const VemdConfig& c) {
  const ProcessingOptions& p = c.processing;
  toml::table t{{"version", 1}};
  t.insert("source", sourceTable(c.source));
  t.insert("camera", cameraTable(c.camera));
  t.insert("bracketing", bracketingTable(c.bracketing));
  t.insert("processing",
           toml::table{{"map_width", p.mapWidth},
                       {"map_height", p.mapHeight},
                       {"lights", std::int64_t(p.lightCount)},
                       {"sampler", p.sampler == SamplerKind::Havran ? "havran" : "standard"}});
  t.insert("filter", toml::table{{"preset", presetName(p.filter)}});
  t.insert("clustering", toml::table{{"enabled", p.clustering},
                                     {"budget", p.clusterBudget},
                                     {"correction_factor", p.clusterCorrectionFactor}});
  t.insert("output", outputTable(c.output));
  t.insert("stats", toml::table{{"every_s", c.stats.everyS}});
  t.insert("log", toml::table{{"level", c.log.level}, {"format", c.log.format}});
  t.insert("stream", streamTable(c.stream));
  t.insert("mqtt", mqttTable(c.mqtt));
  return t;
}

std::string formatConfigToml(const VemdConfig& config) {
  std::ostringstream out;
  out << "# vemd's configuration in force (vemd --print-config): defaults, file and flags "
         "merged.\n";
  if (!config.stream.token.empty()) {
    out << "# stream.token is set and not shown (a secret).\n";
  }
  out << configTable(config) << "\n";
  return out.str();
}

}  // namespace vem::vemd
