// `vemtool lights`: one environment-map file to N directional lights, printed as JSON.
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "core/default_pattern.h"
#include "core/light_generator.h"
#include "core/sampling_tables.h"
#include "mapio/map_file.h"
#include "util/cli_value_names.h"
#include "vemd/sinks/light_json.h"

namespace vem::tool {
namespace {

struct LightsOptions {
  std::string input;
  std::size_t count = 64;
  std::optional<MapLayout> layout;
  SamplerKind sampler = SamplerKind::Havran;
  std::optional<int> clusterQ;
  bool prettyJson = false;
};

int runLights(const LightsOptions& o) {
  auto map = mapio::loadMap(o.input, o.layout);
  if (!map) {
    spdlog::error("{}", map.error().message);
    return EXIT_FAILURE;
  }
  const SamplingTables tables = buildSamplingTables(*map);
  if (tables.badPixels > 0) {
    spdlog::warn("{}: {} pixels had NaN, infinite or negative values; they count as 0", o.input,
                 tables.badPixels);
  }
  if (tables.black) spdlog::warn("{}: the map is black; every light has rgb 0", o.input);
  const LightSet lights =
      generateLights(tables, defaultSamplingPattern(map->layout).first(o.count), o.sampler);
  const nlohmann::ordered_json frame =
      o.clusterQ ? vemd::clusteredFrameJson(lights, *o.clusterQ, map->layout, 0)
                 : vemd::frameJson(lights, 0);
  std::cout << (o.prettyJson ? frame.dump(2) : frame.dump()) << '\n';
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
}

}  // namespace

void addLightsCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<LightsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "lights", "Compute N directional lights from an environment map file (.exr, .hdr, .pfm)");
  cmd->footer(
      "Example:\n  vemtool lights --in ../shared/data/hdri/park.exr --count 16\n"
      "Prints "
      "{\"frame\":0,\"count\":N,\"lights\":[{\"id\":K,\"dir\":[x,y,z],\"rgb\":[r,g,b]},...]}:\n"
      "dir points from the scene toward the light (+Y up), rgb is its irradiance contribution\n"
      "(radiance x sr); the first k lights of an N-light set are the k-light set.");
  cmd->add_option("--in", options->input, "Map file: equirectangular (W = 2H) or polar (W = 4H)")
      ->required()
      ->type_name("FILE")
      ->check(help::quiet(CLI::ExistingFile));
  cmd->add_option("--count", options->count, "Number of lights N")
      ->type_name(help::rangeName(std::size_t(1), kMaxLights))
      ->check(help::quiet(CLI::Range(std::size_t(1), kMaxLights)));
  const std::map<std::string, MapLayout> layouts{{"sphere", MapLayout::Sphere},
                                                 {"hemisphere", MapLayout::Hemisphere}};
  cmd->add_option("--layout", options->layout,
                  "sphere | hemisphere (default: from the map's shape)")
      ->transform(CLI::CheckedTransformer(layouts, CLI::ignore_case));
  const std::map<std::string, SamplerKind> samplers{{"havran", SamplerKind::Havran},
                                                    {"standard", SamplerKind::Standard}};
  cmd->add_option("--sampler", options->sampler, "havran (default) | standard (the baseline)")
      ->transform(CLI::CheckedTransformer(samplers, CLI::ignore_case));
  cmd->add_option("--cluster", options->clusterQ,
                  "Cluster the lights toward about Q clusters over the map (paper 004, 4.3)")
      ->type_name(help::rangeName(1, int(kMaxLights)))
      ->check(help::quiet(CLI::Range(1, int(kMaxLights))));
  std::string format = "jsonl";
  cmd->add_option_function<std::string>(
         "--format", [options](const std::string& f) { options->prettyJson = f == "json"; },
         "jsonl (default: one line per frame) | json (indented)")
      ->check(CLI::IsMember({"jsonl", "json"}));
  cmd->callback([options, &exitCode] { exitCode = runLights(*options); });
}

}  // namespace vem::tool
