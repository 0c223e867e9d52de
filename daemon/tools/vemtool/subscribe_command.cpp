// `vemtool subscribe ws://HOST:PORT` or `mqtt://[USER@]HOST[:PORT]/PREFIX/CAMERA`: receives a vemd
// stream, straight or through an MQTT broker (client/stream_client.h), and prints each light frame
// as one JSON line (the `vemtool lights` light objects), each cube map as one line, and the
// reception statistics as a final JSON line on stderr. The lines come from the decoded values, so
// they are the same for the same frames whichever the transport.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <mutex>
#include <set>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "client/mqtt_url.h"
#include "client/mqtt_cli_options.h"
#include "client/stream_client.h"
#include "commands.h"
#include "proto/stream_protocol.h"
#include "util/cli_value_names.h"
#include "vemd/sinks/light_json.h"

namespace vem::tool {
namespace {

using namespace std::chrono_literals;

struct SubscribeOptions {
  std::string url;
  std::string token;
  std::string tokenFile;
  std::set<std::string> what{"lights"};
  double cubemapRateHz = 1.0;
  std::uint32_t cubemapFacePx = 64;
  std::uint32_t cubemapLevels = 1;
  std::uint64_t frames = 0;  // 0: until interrupted or the duration
  double timeoutS = 10.0;    // to connect and receive the first frame; 0: wait for ever
  double durationS = 0.0;    // 0: none
  client::MqttCliOptions mqtt;       // --ca-file (wss, mqtts), and the MQTT-only options
};

std::atomic<bool> interrupted{false};

double roundedMs(double ms) { return std::round(ms * 1000.0) / 1000.0; }

nlohmann::ordered_json lightFrameJson(const client::Received<client::LightFrame>& received) {
  const client::LightFrame& frame = received.frame;
  nlohmann::ordered_json lights = vemd::frameJson(frame.lights, frame.seq);
  return {{"seq", frame.seq},
          {"lights_seq", frame.lightsSeq},
          {"capture_ts_ns", frame.captureTsNs},
          {"latency_ms", roundedMs(double(received.receivedUnixNs - frame.publishUnixNs) * 1e-6)},
          {"count", lights["count"]},
          {"lights", std::move(lights["lights"])}};
}

nlohmann::ordered_json cubemapJson(const client::EnvironmentFrame& frame) {
  return {{"cubemap",
           {{"seq", frame.seq},
            {"face_px", frame.cube.levels.empty() ? 0 : frame.cube.levels[0].facePx},
            {"levels", frame.cube.levels.size()},
            {"bytes", frame.compressedBytes}}}};
}

nlohmann::ordered_json statsJson(const client::ClientStats& stats) {
  return {{"received", stats.received},
          {"skipped", stats.skipped},
          {"cubemaps", stats.environmentFrames},
          {"decode_errors", stats.decodeErrors},
          {"reconnects", stats.reconnects},
          {"latency_median_ms", roundedMs(stats.latency.medianMs)},
          {"latency_p99_ms", roundedMs(stats.latency.p99Ms)}};
}

// The token from --token or the first line of --token-file (surrounding blanks dropped).
bool readToken(SubscribeOptions& o) {
  if (o.tokenFile.empty()) return true;
  std::ifstream in(o.tokenFile);
  std::getline(in, o.token);
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!o.token.empty() && blank(o.token.back())) o.token.pop_back();
  while (!o.token.empty() && blank(o.token.front())) o.token.erase(0, 1);
  if (!in.bad() && !o.token.empty()) return true;
  spdlog::error("{}: cannot read a token from its first line", o.tokenFile);
  return false;
}

// Prints the frames as they arrive (on the client's I/O thread) and counts them.
class FramePrinter {
 public:
  explicit FramePrinter(std::uint64_t wanted, bool countCubemaps)
      : wanted_(wanted), countCubemaps_(countCubemaps) {}

  void light(const client::Received<client::LightFrame>& received) {
    print(lightFrameJson(received), !countCubemaps_);
  }
  void cubemap(const client::EnvironmentFrame& frame) { print(cubemapJson(frame), countCubemaps_); }

  enum class Outcome { Done, Stopped, NoFirstFrame, DurationOver };

  // Waits for the wanted frames (Done), the client's refusal or an interrupt (Stopped), no frame at
  // all by firstDeadline (NoFirstFrame) or the end of the run (DurationOver).
  Outcome waitDone(const client::StreamClient& client,
                   std::chrono::steady_clock::time_point firstDeadline,
                   std::chrono::steady_clock::time_point deadline) {
    std::unique_lock lock(mutex_);
    while (!(wanted_ > 0 && printed_ >= wanted_)) {
      if (interrupted || client.state() == client::ConnectionState::Refused) return Outcome::Stopped;
      const auto now = std::chrono::steady_clock::now();
      if (lines_ == 0 && now >= firstDeadline) return Outcome::NoFirstFrame;
      if (now >= deadline) return Outcome::DurationOver;
      // Polled too: the client's state and a signal do not notify this condition.
      done_.wait_until(lock, std::min({now + 100ms, lines_ == 0 ? firstDeadline : deadline, deadline}));
    }
    return Outcome::Done;
  }
  std::uint64_t printed() const {
    std::lock_guard lock(mutex_);
    return printed_;
  }

 private:
  void print(const nlohmann::ordered_json& line, bool counts) {
    std::lock_guard lock(mutex_);
    if (wanted_ > 0 && printed_ >= wanted_) return;  // exactly N lines of what was counted
    std::cout << line.dump() << '\n' << std::flush;
    if (++lines_ == 1) done_.notify_all();
    if (counts && ++printed_ == wanted_) done_.notify_all();
  }

  std::uint64_t wanted_;
  bool countCubemaps_;
  mutable std::mutex mutex_;
  std::condition_variable done_;
  std::uint64_t printed_ = 0;  // of what --frames counts
  std::uint64_t lines_ = 0;    // light frames and cube maps
};

// Seconds from now as a deadline; 0 (none) as the farthest time point.
std::chrono::steady_clock::time_point deadlineIn(double seconds) {
  if (!(seconds > 0.0)) return std::chrono::steady_clock::time_point::max();
  return std::chrono::steady_clock::now() +
         std::chrono::duration_cast<std::chrono::steady_clock::duration>(
             std::chrono::duration<double>(seconds));
}

// The sentence for no frame within --timeout: what did not happen, at which address.
std::string noFirstFrameSentence(const SubscribeOptions& o, client::ConnectionState state,
                                 const std::string& reason, bool lights) {
  const std::string last = reason.empty() ? "" : " (last attempt: " + reason + ")";
  if (state == client::ConnectionState::Connected) {
    return fmt::format("connected to {} but no {} arrived within {:g} s (--timeout)", o.url,
                       lights ? "light frame" : "cube map", o.timeoutS);
  }
  return fmt::format("could not connect to {} within {:g} s (--timeout){}", o.url, o.timeoutS,
                     last);
}

// The options of the other transport are a usage error (exit 2, the conventions' error line).
void refuseOtherTransportsOptions(const SubscribeOptions& o) {
  if (client::isMqttUrl(o.url) && (!o.token.empty() || !o.tokenFile.empty())) {
    throw CLI::ValidationError(
        "--token and --token-file are for ws:// and wss:// addresses (over MQTT the broker's ACL "
        "decides)");
  }
  if (!client::isMqttUrl(o.url) && client::anyMqttOnlyOption(o.mqtt)) {
    throw CLI::ValidationError(
        "--username, --password-file, --cert and --key are for mqtt:// and mqtts:// addresses");
  }
}

int runSubscribe(SubscribeOptions o) {
  refuseOtherTransportsOptions(o);
  if (!readToken(o)) return EXIT_FAILURE;
  const auto security = client::readMqttSecurity(o.mqtt);
  if (!security) {
    spdlog::error("{}", security.error());
    return EXIT_FAILURE;
  }
  const bool lights = o.what.contains("lights");
  const bool cubemaps = o.what.contains("cubemap");
  FramePrinter printer(o.frames, cubemaps && !lights);
  client::StreamClientOptions options;
  options.url = o.url;
  options.token = o.token;
  options.caFile = security->caFile;
  options.username = security->username;
  options.password = security->password;
  options.certFile = security->certFile;
  options.keyFile = security->keyFile;
  options.subscription.lights = lights;
  options.subscription.cubemapRateHz = cubemaps ? o.cubemapRateHz : 0.0;
  options.subscription.cubemapFacePx = o.cubemapFacePx;
  options.subscription.cubemapLevels = o.cubemapLevels;
  if (lights) options.onLightFrame = [&printer](const auto& r) { printer.light(r); };
  if (cubemaps)
    options.onEnvironmentFrame = [&printer](const auto& r) { printer.cubemap(r.frame); };
  auto client = client::StreamClient::start(std::move(options));
  if (!client) {
    spdlog::error("{}", client.error());
    return EXIT_FAILURE;
  }
  std::signal(SIGINT, [](int) { interrupted = true; });
  std::signal(SIGTERM, [](int) { interrupted = true; });
  using Outcome = FramePrinter::Outcome;
  const Outcome outcome =
      printer.waitDone(**client, deadlineIn(o.timeoutS), deadlineIn(o.durationS));
  const client::ConnectionState state = (*client)->state();
  const std::string reason = (*client)->stateReason();
  (*client)->stop();
  std::cerr << statsJson((*client)->stats()).dump() << '\n';
  if (outcome == Outcome::Done || interrupted) return EXIT_SUCCESS;
  if (state == client::ConnectionState::Refused) return EXIT_FAILURE;  // the client logged why
  if (outcome == Outcome::NoFirstFrame) {
    spdlog::error("{}", noFirstFrameSentence(o, state, reason, lights));
    return EXIT_FAILURE;
  }
  if (o.frames == 0) return EXIT_SUCCESS;  // --duration alone: ran for that long
  spdlog::error("stopped after {:g} s (--duration) with {} of {} {} from {}{}", o.durationS,
                printer.printed(), o.frames, lights ? "light frames" : "cube maps", o.url,
                reason.empty() ? "" : " (last: " + reason + ")");
  return EXIT_FAILURE;
}

}  // namespace

void addSubscribeCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<SubscribeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "subscribe",
      "Receive a vemd stream, straight or through an MQTT broker, and print its frames as JSON "
      "lines (client/)");
  cmd->footer(
      "Examples:\n  vemtool subscribe ws://127.0.0.1:8490 --frames 10\n"
      "  vemtool subscribe mqtt://viewer@broker/vemcast/cam-1 --password-file ~/.vemcast-pw\n"
      "  vemtool subscribe mqtts://broker/vemcast/cam-1 --ca-file ca.crt --cert me.crt --key me.key\n"
      "Prints one line per light frame:\n"
      "  {\"seq\":S,\"lights_seq\":L,\"capture_ts_ns\":T,\"latency_ms\":M,\"count\":N,"
      "\"lights\":[{\"id\":K,\"dir\":[x,y,z],\"rgb\":[r,g,b]},...]}\n"
      "one line per cube map, {\"cubemap\":{\"seq\":S,\"face_px\":F,\"levels\":L,\"bytes\":B}},\n"
      "and on exit the statistics on stderr: {\"received\":..,\"skipped\":..,...}.\n"
      "Exits 0 after N frames (light frames, or cube maps with --what cubemap) or at the end of\n"
      "--duration without --frames; 1 when no frame arrived within --timeout (no daemon at the\n"
      "address: the client retries until then), when --duration ends before N frames, or when\n"
      "the daemon or the broker refuses the client. Over MQTT the camera's vemd publishes cube maps\n"
      "at its own rate and size: --cubemap-rate, --cubemap-face and --cubemap-levels do not apply.");
  cmd->add_option("url", options->url,
                  "ws://HOST:PORT[/PATH], wss://..., mqtt://[USER@]HOST[:PORT]/PREFIX/CAMERA or "
                  "mqtts://...")
      ->required();
  auto* token = cmd->add_option("--token", options->token, "ws: the daemon's bearer token");
  cmd->add_option("--token-file", options->tokenFile, "ws: a file whose first line is the token")
      ->type_name("FILE")
      ->check(help::quiet(CLI::ExistingFile))
      ->excludes(token);
  cmd->add_option("--what", options->what, "lights, cubemap or lights,cubemap (default: lights)")
      ->delimiter(',')
      ->check(CLI::IsMember({"lights", "cubemap"}));
  cmd->add_option("--cubemap-rate", options->cubemapRateHz, "Cube maps per second (default 1)")
      ->type_name(help::rangeName(0.01, stream::kMaxCubemapRateHz))
      ->check(help::quiet(CLI::Range(0.01, stream::kMaxCubemapRateHz)));
  cmd->add_option("--cubemap-face", options->cubemapFacePx,
                  "Cube face size in texels (default 64; without the token at most the daemon's "
                  "[stream] cubemap_max_face_px)")
      ->type_name(help::rangeName(stream::kMinCubeFacePx, stream::kMaxCubeFacePx))
      ->check(help::quiet(CLI::Range(stream::kMinCubeFacePx, stream::kMaxCubeFacePx)));
  cmd->add_option("--cubemap-levels", options->cubemapLevels,
                  "Cube-map levels: 1 (default) for none below the face size, up to 8")
      ->type_name(help::rangeName(1, stream::kMaxCubeLevels))
      ->check(help::quiet(CLI::Range(1, stream::kMaxCubeLevels)));
  cmd->add_option("--frames", options->frames, "Exit after N frames (default: never)");
  cmd->add_option("--timeout", options->timeoutS,
                  "Seconds to connect and receive the first frame, then exit 1 (0: wait for ever)")
      ->option_text("SECONDS (default: 10)")
      ->check(help::quiet(CLI::NonNegativeNumber));
  cmd->add_option("--duration", options->durationS,
                  "Stop after S seconds (exit 1 when --frames were not all received)")
      ->option_text("SECONDS")
      ->check(help::quiet(CLI::PositiveNumber));
  client::addMqttCliOptions(*cmd, options->mqtt,
                    "wss, mqtts: trust the CA certificates of this PEM file instead of the system's");
  cmd->callback([options, &exitCode] { exitCode = runSubscribe(*options); });
}

}  // namespace vem::tool
