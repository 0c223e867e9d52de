// The configuration vemd runs with, back as TOML (`vemd --print-config`): every key of
// config/vemd.toml with the value in force after the built-in defaults, the file and the flags,
// in the file's sections. parseConfig() of the text gives the same VemdConfig (a round trip),
// except stream.token, a secret: it is left out and a comment says it is set.
#pragma once

#include <string>

#include <toml++/toml.h>

#include "vemd/vemd_config.h"

namespace vem::vemd {

// The configuration as a TOML table (without stream.token).
[[nodiscard]] toml::table configTable(const VemdConfig& config);
// The table as text, ending in a newline, with a comment first when stream.token is set.
[[nodiscard]] std::string formatConfigToml(const VemdConfig& config);

}  // namespace vem::vemd
