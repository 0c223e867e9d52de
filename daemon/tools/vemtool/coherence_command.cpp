// `vemtool coherence`: how still the lights hold from frame to frame (issue 19). Runs map sequences
// with a known truth (daemon/synth/map_sequences.h) over every map in a folder and the synthetic
// sky and fluorescent scenes, through both samplers and the temporal-filter presets, and prints
// markdown tables of the angular steps, the irradiance flicker and the accuracy
// (daemon/synth/coherence_study.h; docs/temporal-filter.md shows and explains them).
#include <algorithm>
#include <cstdlib>
#include <expected>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "commands.h"
#include "core/default_pattern.h"
#include "core/sampling_tables.h"
#include "core/sphere_points.h"
#include "core/temporal_filter.h"
#include "core/upper_hemisphere.h"
#include "mapio/map_file.h"
#include "synth/coherence_study.h"
#include "synth/jump_causes.h"
#include "synth/scene_factory.h"
#include "util/cli_value_names.h"
#include "util/svg_plot.h"

namespace vem::tool {
namespace {

constexpr int kNormalCount = 64;
constexpr int kSceneWidth = 512;  // the synthetic scenes' maps: 512 x 256 (sphere), 512 x 128

struct CoherenceOptions {
  std::string mapsDir;
  std::string plotPath;  // --plot: accuracy against flicker, SVG
  MapLayout layout = MapLayout::Hemisphere;
  std::size_t lightCount = 256;
  double importanceWeight = 1.0;  // --importance-ema (an experiment of issue 19)
  double importanceGate = 0.0;    // --importance-gate (with it)
  double liftFraction = 0.0;      // --importance-lift (another)
  int liftRadiusPx = 8;           // --importance-lift-radius
  int frames = 30;
  bool noScenes = false;
  bool explainJumps = false;  // --explain-jumps: where the steps above 5 degrees went, and over what
  std::vector<SamplerKind> samplers{SamplerKind::Havran, SamplerKind::Standard};
  std::vector<FilterPreset> filters{kAllPresets.begin(), kAllPresets.end()};
};

struct NamedMap {
  std::string name;
  EnvMap map;
};

// A scenario turns a map into a sequence (the seed varies the noise per map).
struct Scenario {
  std::string name;
  bool perMapTable = false;  // the targets' scenarios get a table per map and a plot
  std::function<std::vector<synth::SequenceFrame>(const EnvMap&, std::uint64_t seed)> make;
};

std::vector<Scenario> mapScenarios(int frames) {
  std::vector<Scenario> out;
  for (double percent : {0.5, 1.0, 3.0}) {
    out.push_back({fmt::format("rest, {:g} % noise", percent), percent == 1.0,
                   [=](const EnvMap& m, std::uint64_t seed) {
                     return synth::noisySequence(m, percent / 100.0, frames, seed);
                   }});
  }
  for (double deg : {0.1, 0.25, 1.0}) {
    out.push_back(
        {fmt::format("turning {:g} deg/frame", deg), deg == 0.25,
         [=](const EnvMap& m, std::uint64_t) { return synth::turningSequence(m, deg, frames); }});
  }
  const int switchFrames = std::max(frames, synth::kSwitchOffFrames + synth::kSwitchRampFrames + 1);
  out.push_back({"switching on (10 frames)", false, [=](const EnvMap& m, std::uint64_t) {
                   return synth::switchOnSequence(m, switchFrames);
                 }});
  return out;
}

// Maps in the folder (.exr, .hdr, .pfm), sorted by name, in the study's layout; or one sentence.
std::expected<std::vector<NamedMap>, std::string> loadMaps(const CoherenceOptions& o) {
  std::vector<std::filesystem::path> paths;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(o.mapsDir, ec)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".exr" || ext == ".hdr" || ext == ".pfm") paths.push_back(entry.path());
  }
  if (ec)
    return std::unexpected(fmt::format("{}: cannot list the folder: {}.", o.mapsDir, ec.message()));
  if (paths.empty())
    return std::unexpected(fmt::format("{}: holds no map file (.exr, .hdr or .pfm).", o.mapsDir));
  std::sort(paths.begin(), paths.end());
  std::vector<NamedMap> maps;
  for (const auto& path : paths) {
    auto map = mapio::loadMap(path, MapLayout::Sphere);
    if (!map) return std::unexpected(map.error().message);
    if (o.layout == MapLayout::Hemisphere) {
      if (map->height % 2 != 0) {
        return std::unexpected(fmt::format(
            "{}: its height {} is odd, so it has no upper half to use as a polar map; expected "
            "an equirectangular map of even height.",
            path.string(), map->height));
      }
      maps.push_back({path.stem().string(), upperHemisphere(*map)});
    } else {
      maps.push_back({path.stem().string(), std::move(*map)});
    }
  }
  return maps;
}

// One scenario's tallies per (sampler, filter), summed over its sequences.
using TallyKey = std::pair<SamplerKind, FilterPreset>;
struct ScenarioTallies {
  std::string name;
  bool perMapTable = false;
  std::map<TallyKey, synth::CoherenceTally> total;
  // Per map, for the per-map table: the unfiltered tally per sampler.
  std::vector<std::pair<std::string, std::map<SamplerKind, synth::CoherenceTally>>> perMap;
  // With --explain-jumps: the unfiltered steps above kLargeStepDeg, per sampler.
  std::map<SamplerKind, std::vector<synth::LargeJump>> jumps;
  std::map<SamplerKind, std::vector<double>> rowPeakShares;  // of every light, for the base rate
  std::map<SamplerKind, std::vector<double>> rowsDisagreement;  // of every light, likewise
};

void measureInto(const std::vector<synth::SequenceFrame>& frames, const std::string& mapName,
                 const CoherenceOptions& o, const std::vector<glm::dvec3>& normals,
                 ScenarioTallies& into) {
  const auto exact = synth::exactIrradiance(frames, normals);
  std::map<SamplerKind, synth::CoherenceTally> unfiltered;
  for (SamplerKind sampler : o.samplers) {
    const auto sets = synth::sampleSequence(frames, sampler, o.lightCount, o.importanceWeight,
                                            o.importanceGate, o.liftFraction, o.liftRadiusPx);
    if (o.explainJumps) {
      for (std::size_t k = 1; k < frames.size(); ++k) {
        const SamplingTables tables = buildSamplingTables(frames[k].map);
        synth::appendLargeJumps(tables, sets[k - 1], sets[k], frames[k].motionFromPrevious,
                                into.jumps[sampler]);
        synth::appendRowPeakShares(tables, sets[k], into.rowPeakShares[sampler]);
        synth::appendNeighbourRowsDisagreement(tables, sets[k], into.rowsDisagreement[sampler]);
      }
    }
    for (FilterPreset preset : o.filters) {
      const auto filtered = synth::filterSequence(sets, preset);
      synth::CoherenceTally t = synth::tallySequence(frames, filtered, exact, normals);
      if (preset == FilterPreset::None) unfiltered[sampler] = t;
      into.total[{sampler, preset}].add(t);
    }
  }
  into.perMap.push_back({mapName, std::move(unfiltered)});
}

void printScenarioRows(const ScenarioTallies& s, const CoherenceOptions& o) {
  for (SamplerKind sampler : o.samplers) {
    for (FilterPreset preset : o.filters) {
      const auto it = s.total.find({sampler, preset});
      if (it == s.total.end()) continue;
      const synth::CoherenceFigures f = synth::summarise(it->second);
      std::cout << fmt::format(
          "| {} | {} | {} | {:.3f} | {:.2f} | {:.1f} | {:.2f} % | {:.4f} | {:.4f} | {:.4f} | "
          "{:.4f} | {:.2f} |\n",
          s.name, samplerName(sampler), presetName(preset), f.steps.medianDeg, f.steps.p99Deg,
          f.steps.maxDeg, 100.0 * f.steps.fractionLarge, f.lightsFlicker, f.exactFlicker,
          f.excessFlicker, f.meanError, TemporalFilter(presetTaps(preset)).delayFrames());
    }
  }
}

void printPerMap(const ScenarioTallies& s, const CoherenceOptions& o) {
  std::cout << fmt::format("\n### Per map: {}, no filter\n\n| map |", s.name);
  for (SamplerKind sampler : o.samplers)
    std::cout << fmt::format(" {0} p99 (deg) | {0} max (deg) | {0} error |", samplerName(sampler));
  std::cout << "\n|---|";
  for (std::size_t i = 0; i < o.samplers.size(); ++i) std::cout << "---:|---:|---:|";
  std::cout << '\n';
  for (const auto& [name, bySampler] : s.perMap) {
    std::cout << "| " << name << " |";
    for (SamplerKind sampler : o.samplers) {
      const auto it = bySampler.find(sampler);
      if (it == bySampler.end()) {
        std::cout << " | | |";
        continue;
      }
      const synth::CoherenceFigures f = synth::summarise(it->second);
      std::cout << fmt::format(" {:.2f} | {:.1f} | {:.4f} |", f.steps.p99Deg, f.steps.maxDeg,
                               f.meanError);
    }
    std::cout << '\n';
  }
}

void printJumpCauses(const std::vector<ScenarioTallies>& results, const CoherenceOptions& o) {
  std::cout << "\n### Why the largest steps happen (--explain-jumps), no filter\n\n"
               "Every step above 5 degrees, placed in the newer frame's tables (synth/jump_causes.h): "
               "across rows when its row coordinate moved by a row or more, else along its row; and "
               "the mean importance of what it passed over (the pixels of the row between its two "
               "columns, or the rows between its two rows) over the mean; and how many land in a "
               "row whose brightest 16-pixel block holds more than half of the row's importance (a "
               "sun's row), against the share of all lights in such rows; how many sit where the "
               "conditional CDFs of the two rows around them differ by more than 0.1 (a fraction of "
               "the row), against all lights; and how many changed row.\n\n"
               "| sequence | sampler | steps > 5 deg | across rows | along a row | over a gap below 1 % "
               "of the mean | below 10 % | median gap / mean | in a sun's row | all lights in a "
               "sun's row | rows differ | all lights where rows differ | row changed |\n"
               "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const ScenarioTallies& s : results) {
    for (SamplerKind sampler : o.samplers) {
      const auto it = s.jumps.find(sampler);
      if (it == s.jumps.end()) continue;
      const synth::JumpCauses c = synth::summariseJumps(it->second);
      const auto& shares = s.rowPeakShares.at(sampler);
      auto fractionAbove = [](const std::vector<double>& v, double limit) {
        return v.empty() ? 0.0
                         : double(std::count_if(v.begin(), v.end(),
                                                [&](double x) { return x > limit; })) /
                               double(v.size());
      };
      const double base = fractionAbove(shares, synth::kPeakyRowShare);
      const double baseDisagree =
          fractionAbove(s.rowsDisagreement.at(sampler), synth::kRowsDisagree);
      std::cout << fmt::format(
          "| {} | {} | {} | {:.0f} % | {:.0f} % | {:.0f} % | {:.0f} % | {:.3g} | {:.0f} % | {:.1f} % "
          "| {:.0f} % | {:.1f} % | {:.0f} % |\n",
          s.name, samplerName(sampler), c.count, 100.0 * c.fractionAcrossRows,
          100.0 * (c.count > 0 ? 1.0 - c.fractionAcrossRows : 0.0), 100.0 * c.fractionGapBelowPercent,
          100.0 * c.fractionGapBelowTenPercent, c.medianGapRatio, 100.0 * c.fractionPeakyRow,
          100.0 * base, 100.0 * c.fractionRowsDisagree, 100.0 * baseDisagree,
          100.0 * c.fractionRowIndexChanged);
    }
  }
}

// Error against the lights' flicker per sampler and scenario (those with a per-map table), one
// point per filter preset: what smoothing in time costs in accuracy.
bool writePlot(const std::vector<ScenarioTallies>& results, const CoherenceOptions& o) {
  std::vector<PlotSeries> series;
  int colour = 0;
  for (const ScenarioTallies& s : results) {
    if (!s.perMapTable) continue;
    for (SamplerKind sampler : o.samplers) {
      PlotSeries line;
      line.name = fmt::format("{}, {}", samplerName(sampler), s.name);
      line.colour = colour++;
      line.marker = sampler == SamplerKind::Havran ? PlotMarker::Circle : PlotMarker::Square;
      for (FilterPreset preset : o.filters) {
        const auto it = s.total.find({sampler, preset});
        if (it == s.total.end()) continue;
        const synth::CoherenceFigures f = synth::summarise(it->second);
        if (f.lightsFlicker <= 0.0 || f.meanError <= 0.0) continue;  // no point on a log axis
        line.points.emplace_back(f.lightsFlicker, f.meanError);
        line.labels.emplace_back(presetName(preset));
      }
      if (!line.points.empty()) series.push_back(std::move(line));
    }
  }
  return writeLogLogSvg(
      o.plotPath,
      {fmt::format("Irradiance error against flicker, {} lights, one point per filter preset",
                   o.lightCount),
       "flicker: frame-to-frame change of the lights' irradiance, relative RMS at 64 normals",
       "irradiance error, relative RMS at 64 normals (mean over frames)", true},
      series, PlotCanvas{820, 520});
}

int runCoherence(const CoherenceOptions& o) {
  auto maps = loadMaps(o);
  if (!maps) return fail(maps.error());
  const auto normals = fibonacciSphere(kNormalCount);
  std::vector<ScenarioTallies> results;
  std::uint64_t seed = 1;
  for (const Scenario& scenario : mapScenarios(o.frames)) {
    ScenarioTallies s{scenario.name, scenario.perMapTable, {}, {}, {}, {}, {}};
    for (const NamedMap& m : *maps) {
      spdlog::info("coherence: {}, {}", scenario.name, m.name);
      measureInto(scenario.make(m.map, seed++), m.name, o, normals, s);
    }
    results.push_back(std::move(s));
  }
  if (!o.noScenes) {
    const int height = o.layout == MapLayout::Sphere ? kSceneWidth / 2 : kSceneWidth / 4;
    for (const char* spec : {"sky", "fluorescent"}) {
      auto scene = synth::makeScene(spec, {});
      if (!scene) return fail(scene.error());
      spdlog::info("coherence: synthetic:{}", spec);
      ScenarioTallies s{fmt::format("synthetic:{}", spec), false, {}, {}, {}, {}, {}};
      const auto frames = synth::sceneSequence(**scene, o.layout, kSceneWidth, height,
                                               *synth::naturalRateHz(spec), o.frames);
      measureInto(frames, spec, o, normals, s);
      results.push_back(std::move(s));
    }
  }

  std::cout << fmt::format(
      "## Temporal coherence (vemtool coherence)\n\n"
      "`vemtool coherence --maps {} --layout {} --lights {} --frames {}{}`\n\n",
      o.mapsDir, layoutName(o.layout), o.lightCount, o.frames,
      (o.importanceWeight < 1.0 ? fmt::format(" --importance-ema {:g}", o.importanceWeight) : "") +
          (o.importanceGate > 0.0 ? fmt::format(" --importance-gate {:g}", o.importanceGate) : "") +
          (o.liftFraction > 0.0 ? fmt::format(" --importance-lift {:g} --importance-lift-radius {}",
                                              o.liftFraction, o.liftRadiusPx)
                                : "") +
          (o.explainJumps ? " --explain-jumps" : ""));
  std::cout << fmt::format(
      "Coherence: {} lights, {} layout, {} frames per sequence, {} maps from {}; steps in degrees "
      "between consecutive frames (beyond the true motion), flicker and error on irradiance at {} "
      "normals (daemon/synth/coherence_study.h).\n\n",
      o.lightCount, layoutName(o.layout), o.frames, maps->size(), o.mapsDir, kNormalCount);
  std::cout
      << "| sequence | sampler | filter | median step | p99 step | max step | steps > 5 deg "
         "| flicker (lights) | flicker (exact) | flicker (excess) | error | delay (frames) |\n"
         "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const ScenarioTallies& s : results) printScenarioRows(s, o);
  for (const ScenarioTallies& s : results) {
    if (s.perMapTable) printPerMap(s, o);
  }
  if (o.explainJumps) printJumpCauses(results, o);
  if (!o.plotPath.empty() && !writePlot(results, o))
    return fail(fmt::format("--plot {}: could not write the file.", o.plotPath));
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
}

}  // namespace

void addCoherenceCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<CoherenceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "coherence", "Measure how still the lights hold from frame to frame (steps, flicker, error)");
  cmd->footer(
      "Example:\n  vemtool coherence --maps ../shared/data/hdri --lights 256\n"
      "Per map in --maps: the map at rest with 0.5, 1 and 3 % sensor noise, turning at 0.1, 0.25\n"
      "and 1 degree per frame, and its brightest region switching on over 10 frames; then the\n"
      "synthetic sky and fluorescent scenes. Prints markdown tables per sampler and filter "
      "preset.");
  cmd->add_option("--maps", options->mapsDir, "Folder of equirectangular maps (.exr, .hdr, .pfm)")
      ->required()
      ->type_name("DIR")
      ->check(help::quiet(CLI::ExistingDirectory));
  const std::map<std::string, MapLayout> layouts{{"sphere", MapLayout::Sphere},
                                                 {"hemisphere", MapLayout::Hemisphere}};
  cmd->add_option("--layout", options->layout,
                  "hemisphere (default: each map's upper half, as vemd's camera) | sphere")
      ->transform(CLI::CheckedTransformer(layouts, CLI::ignore_case));
  cmd->add_option("--lights", options->lightCount, "Number of lights N (256)")
      ->type_name(help::rangeName(std::size_t(1), kMaxLights))
      ->check(help::quiet(CLI::Range(std::size_t(1), kMaxLights)));
  cmd->add_option("--frames", options->frames, "Frames per sequence (30)")
      ->type_name(help::rangeName(2, 10000))
      ->check(help::quiet(CLI::Range(2, 10000)));
  cmd->add_option_function<std::string>(
         "--sampler",
         [options](const std::string& name) {
           if (name != "both")
             options->samplers = {name == "havran" ? SamplerKind::Havran : SamplerKind::Standard};
         },
         "both (default) | havran | standard")
      ->check(CLI::IsMember({"both", "havran", "standard"}));
  cmd->add_option_function<std::string>(
         "--filter",
         [options](const std::string& name) { options->filters = {*presetFromName(name)}; },
         "One preset: none | paper9 | equiripple5 | minphase9 (default: all)")
      ->check(CLI::IsMember({"none", "paper9", "equiripple5", "minphase9"}));
  cmd->add_option("--importance-ema", options->importanceWeight,
                  "Experiment: tables from a moving average of the maps, this weight on the newest "
                  "(1: none)")
      ->type_name("0..1")
      ->check(help::quiet(CLI::Range(1e-3, 1.0)));
  cmd->add_option("--importance-gate", options->importanceGate,
                  "Experiment, with --importance-ema: a pixel whose luminance changed by more than "
                  "this fraction takes the newest value (0: no gate)")
      ->type_name("FRACTION")
      ->check(help::quiet(CLI::Range(0.0, 1.0)));
  cmd->add_option("--importance-lift", options->liftFraction,
                  "Experiment: each pixel's importance raised to this fraction of the mean luminance "
                  "around it (0: none)")
      ->type_name("FRACTION")
      ->check(help::quiet(CLI::Range(0.0, 1.0)));
  cmd->add_flag("--explain-jumps", options->explainJumps,
                "Also tabulate the steps above 5 degrees: across rows or along a row, and how dark "
                "what they passed over is");
  cmd->add_option("--importance-lift-radius", options->liftRadiusPx,
                  "With --importance-lift: the radius of the neighbourhood in pixels (8)")
      ->type_name("PX")
      ->check(help::quiet(CLI::Range(1, 256)));
  cmd->add_option("--plot", options->plotPath,
                  "Also write error against flicker per filter preset as an SVG plot")
      ->type_name("FILE.svg");
  cmd->add_flag("--no-scenes", options->noScenes,
                "Leave out the synthetic sky and fluorescent scenes");
  cmd->callback([options, &exitCode] { exitCode = runCoherence(*options); });
}

}  // namespace vem::tool
