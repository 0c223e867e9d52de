// `vemtool cameras mqtt://HOST[:PORT][/PREFIX]`: the cameras an MQTT broker knows, from their
// retained statuses under PREFIX/+/status (client/camera_list.h), one line each: camera id,
// online or offline, source, state, frame rate, light count and the messages its publisher
// dropped; --json for JSON lines. It waits --wait-ms after subscribing (the broker sends the
// retained statuses at once, but how many there are it cannot know).
#include <cstdint>
#include <iostream>
#include <memory>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "client/camera_list.h"
#include "client/mqtt_cli_options.h"
#include "commands.h"
#include "util/cli_conventions.h"
#include "util/cli_value_names.h"

namespace vem::tool {
namespace {

struct CamerasOptions {
  std::string url;
  std::uint32_t waitMs = 1000;
  bool json = false;
  client::MqttCliOptions mqtt;
};

nlohmann::ordered_json cameraJson(const client::CameraStatus& c) {
  return {{"camera", c.camera},
          {"online", !c.status.offline},
          {"source", c.status.source},
          {"state", client::sourceStateName(c.status.state)},
          {"frame_rate_hz", c.status.frameRateHz},
          {"light_count", c.status.lightCount},
          {"publish_dropped", c.status.publishDropped}};
}

std::string cameraLine(const client::CameraStatus& c) {
  return fmt::format("{}  {}  {}  {}  {:.1f} Hz  {} lights  {} dropped", c.camera,
                     c.status.offline ? "offline" : "online",
                     c.status.source.empty() ? "-" : c.status.source,
                     client::sourceStateName(c.status.state), c.status.frameRateHz,
                     c.status.lightCount, c.status.publishDropped);
}

int runCameras(const CamerasOptions& o) {
  const auto security = client::readMqttSecurity(o.mqtt);
  if (!security) return fail(security.error());
  client::CameraListOptions options;
  options.url = o.url;
  options.security = *security;
  options.wait = std::chrono::milliseconds(o.waitMs);
  const auto list = client::listCameras(options);
  if (!list) return fail(list.error());
  for (const std::string& refused : list->refused) spdlog::warn("{}", refused);
  for (const client::CameraStatus& camera : list->cameras) {
    std::cout << (o.json ? cameraJson(camera).dump() : cameraLine(camera)) << '\n';
  }
  if (list->cameras.empty()) {
    spdlog::warn("no camera has a retained status at {} within {} ms", o.url, o.waitMs);
  }
  return cli::kExitSuccess;
}

}  // namespace

void addCamerasCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<CamerasOptions>();
  CLI::App* cmd = app.add_subcommand(
      "cameras", "List the cameras an MQTT broker knows, from their retained statuses (client/)");
  cmd->footer(
      "Examples:\n  vemtool cameras mqtt://broker\n"
      "  vemtool cameras mqtts://viewer@broker:8883/site-a --password-file ~/.vemcast-pw --json\n"
      "Prints one line per camera under PREFIX/+/status (PREFIX: vemcast by default):\n"
      "  CAMERA  online|offline  SOURCE  STATE  RATE Hz  N lights  D dropped\n"
      "or with --json {\"camera\":..,\"online\":..,\"source\":..,\"state\":..,"
      "\"frame_rate_hz\":..,\"light_count\":..,\"publish_dropped\":..}.\n"
      "Waits --wait-ms after subscribing: the broker sends the retained statuses at once, but how\n"
      "many there are it cannot know. Exits 0 with the list (empty: a warning on stderr), 1 when\n"
      "the broker cannot be reached or refuses the client.");
  cmd->add_option("url", options->url, "mqtt://[USER@]HOST[:PORT][/PREFIX] or mqtts://...")
      ->required();
  cmd->add_option("--wait-ms", options->waitMs,
                  "How long to collect statuses after subscribing (default: 1000)")
      ->type_name(help::rangeName(1, 60000))
      ->check(help::quiet(CLI::Range(1, 60000)));
  cmd->add_flag("--json", options->json, "One JSON object per line");
  client::addMqttCliOptions(*cmd, options->mqtt,
                    "mqtts: trust the CA certificates of this PEM file instead of the system's");
  cmd->callback([options, &exitCode] { exitCode = runCameras(*options); });
}

}  // namespace vem::tool
