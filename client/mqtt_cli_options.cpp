#include "client/mqtt_cli_options.h"

#include <fmt/format.h>

#include "util/cli_value_names.h"
#include "util/owner_only_file.h"

namespace vem::client {

void addMqttCliOptions(CLI::App& command, MqttCliOptions& o, const std::string& caFileHelp) {
  command
      .add_option("--username", o.username,
                  "mqtt: the broker's user name (or USER@ in the address)")
      ->type_name("USER");
  command
      .add_option("--password-file", o.passwordFile,
                  "mqtt: a file readable by its owner only whose first line is the password")
      ->type_name("FILE")
      ->check(help::quiet(CLI::ExistingFile));
  command.add_option("--ca-file", o.caFile, caFileHelp)
      ->type_name("FILE")
      ->check(help::quiet(CLI::ExistingFile));
  auto* cert = command.add_option("--cert", o.certFile, "mqtts: a client certificate (PEM)")
                   ->type_name("FILE")
                   ->check(help::quiet(CLI::ExistingFile));
  auto* key = command.add_option("--key", o.keyFile, "mqtts: the client certificate's key (PEM)")
                  ->type_name("FILE")
                  ->check(help::quiet(CLI::ExistingFile));
  cert->needs(key);
  key->needs(cert);
}

bool anyMqttOnlyOption(const MqttCliOptions& o) {
  return !o.username.empty() || !o.passwordFile.empty() || !o.certFile.empty() ||
         !o.keyFile.empty();
}

std::expected<util::MqttSecurity, std::string> readMqttSecurity(const MqttCliOptions& o) {
  util::MqttSecurity security{o.username, "", o.caFile, o.certFile, o.keyFile};
  if (o.passwordFile.empty()) return security;
  const auto text = util::readOwnerOnlyFile(o.passwordFile, "--password-file");
  if (!text) return std::unexpected(text.error());
  security.password = text->substr(0, text->find('\n'));
  while (!security.password.empty() &&
         (security.password.back() == '\r' || security.password.back() == ' ' ||
          security.password.back() == '\t')) {
    security.password.pop_back();
  }
  if (security.password.empty()) {
    return std::unexpected(
        fmt::format("--password-file: {} holds no password on its first line", o.passwordFile));
  }
  return security;
}

}  // namespace vem::client
