#include "vemd/source_factory.h"

#include <fmt/format.h>

#include "vemd/replay_source.h"
#include "vemd/synthetic_source.h"

namespace vem::vemd {

namespace {
constexpr const char* kExpectedSpec = "replay:FILE.vem or synthetic:SCENE";
}  // namespace

std::expected<SourceSpec, std::string> parseSourceSpec(std::string_view spec) {
  if (spec.empty()) {
    return std::unexpected(
        fmt::format("no source given: expected --source (or source.spec in the configuration) {}",
                    kExpectedSpec));
  }
  const std::size_t colon = spec.find(':');
  const std::string_view kind = spec.substr(0, colon);
  const std::string_view argument = colon == std::string_view::npos ? "" : spec.substr(colon + 1);
  SourceSpec parsed;
  if (kind == "replay") {
    parsed.kind = SourceSpec::Kind::Replay;
  } else if (kind == "synthetic") {
    parsed.kind = SourceSpec::Kind::Synthetic;
  } else {
    return std::unexpected(
        fmt::format("source \"{}\": unknown kind \"{}\" (expected {})", spec, kind, kExpectedSpec));
  }
  if (argument.empty()) {
    return std::unexpected(
        fmt::format("source \"{}\": expected {} after \"{}:\"", spec,
                    parsed.kind == SourceSpec::Kind::Replay ? "a file" : "a scene", kind));
  }
  parsed.argument = std::string(argument);
  return parsed;
}

std::expected<std::unique_ptr<FrameSource>, std::string> makeSource(const SourceConfig& config) {
  auto spec = parseSourceSpec(config.spec);
  if (!spec) return std::unexpected(spec.error());
  if (spec->kind == SourceSpec::Kind::Replay) {
    auto source = ReplaySource::open(spec->argument, {config.rate, config.loop});
    if (!source) return std::unexpected(source.error().message);
    return std::unique_ptr<FrameSource>(std::move(*source));
  }
  auto source = SyntheticSource::create(
      spec->argument, {config.rate, config.camera, config.noiseCode, config.seed});
  if (!source) return std::unexpected(source.error().message);
  return std::unique_ptr<FrameSource>(std::move(*source));
}

}  // namespace vem::vemd
