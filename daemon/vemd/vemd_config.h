// VemdConfig: everything vemd can be told, from config/vemd.toml (every key documented there with
// its default) and the command line, which overrides the file.
//
// File: TOML, sections [source], [processing], [filter], [clustering], [output], [stats]; every
// key is optional (the built-in default applies), a key or section that is not listed is refused,
// and so is a value of the wrong type or out of range, in one sentence:
//   "vemd.toml: processing.lights: expected a whole number from 1 to 65536, found 0".
// Flags: --config FILE, --source SPEC, --frames N, --rate recorded|max|HZ, --loop, --lights N,
// --cluster Q (0: off), --out DIR, --record FILE, --jsonl FILE, --preview-every N (0: off),
// --stats-every S; a bad flag value is refused the same way ("--lights: expected ...").
//
// Units are in the key names: ..._ms milliseconds, ..._s seconds, rate in frames per second.
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <string>
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
  std::string camera;      // synthetic: the camera file; "": the built-in example camera
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
  friend bool operator==(const OutputConfig&, const OutputConfig&) = default;
};

struct StatsConfig {
  double everyS = 5.0;  // a report line every this many seconds; 0: only at exit
  friend bool operator==(const StatsConfig&, const StatsConfig&) = default;
};

struct VemdConfig {
  SourceConfig source;
  ProcessingOptions processing;  // [processing], [filter] and [clustering]
  OutputConfig output;
  StatsConfig stats;
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
