// The options by which the tools reach an MQTT broker (vemtool subscribe and cameras, vemview
// --connect): --username, --password-file (the password is the file's first line; a file group or
// others may read is refused, util/owner_only_file.h), --ca-file, --cert and --key; and their
// reading into util::MqttSecurity. A shell-side helper (CLI11): library vem_client_cli.
#pragma once

#include <expected>
#include <string>

#include <CLI/CLI.hpp>

#include "util/mosquitto_client.h"

namespace vem::client {

struct MqttCliOptions {
  std::string username;
  std::string passwordFile;
  std::string caFile;
  std::string certFile;
  std::string keyFile;
};

// Adds --username, --password-file, --ca-file (described by `caFileHelp`), --cert and --key.
void addMqttCliOptions(CLI::App& command, MqttCliOptions& options, const std::string& caFileHelp);

// True when any of the MQTT-only options (not --ca-file) was given.
[[nodiscard]] bool anyMqttOnlyOption(const MqttCliOptions& options);

// The security settings, the password read from its file; one sentence naming the file when it
// cannot be used.
[[nodiscard]] std::expected<util::MqttSecurity, std::string> readMqttSecurity(
    const MqttCliOptions& options);

}  // namespace vem::client
