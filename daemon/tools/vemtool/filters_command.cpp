// `vemtool filters`: the temporal filter's presets and a Parks-McClellan design, measured at a
// capture rate: delay, phase, attenuation, jitter and step response, as a markdown table
// (docs/temporal-filter.md shows and explains it).
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "commands.h"
#include "util/cli_value_names.h"
#include "core/fir_design.h"

namespace vem::tool {
namespace {

// Linear phase has no group-delay spread; anything above rounding is reported as non-linear.
constexpr double kLinearPhaseSpreadFrames = 1e-6;

struct FiltersOptions {
  LowPassSpec spec{9, kPaperStatedEdges};
};

void printHeader(const BandEdgesHz& e) {
  std::cout << fmt::format(
      "| filter | taps | phase | delay (frames) | delay (ms) | delay spread 0-{0:g} Hz (frames) "
      "| -3 dB (Hz) | gain at {0:g} Hz | max gain {1:g}-{2:g} Hz | white-jitter RMS gain "
      "| step over / undershoot |\n",
      e.passHz, e.stopHz, 0.5 * e.rateHz);
  std::cout << "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
}

void printRow(const std::string& name, const FirTaps& taps, const BandEdgesHz& edges) {
  const FilterCharacteristics c = characteriseFilter(taps, edges);
  const bool linear = c.delaySpreadFrames < kLinearPhaseSpreadFrames;
  std::cout << fmt::format(
      "| {} | {} | {} | {:.2f} | {:.0f} | {:.2f} | {:.2f} | {:.3f} | {:.3f} | {:.3f} | "
      "{:.1f}% / {:.1f}% |\n",
      name, taps.size(), linear ? "linear" : "non-linear", c.delayFrames, c.delayMs,
      c.delaySpreadFrames, c.halfPowerHz, c.passGain, c.stopGainMax, c.jitterRmsGain,
      100.0 * c.stepOvershoot, 100.0 * c.stepUndershoot);
}

void printTaps(const std::string& name, const FirTaps& taps) {
  std::cout << "- " << name << ":";
  for (double w : taps.weights()) std::cout << fmt::format(" {:.5f}", w);
  std::cout << '\n';
}

int runFilters(const FiltersOptions& o) {
  if (const auto problem = describeInvalid(o.spec)) {
    spdlog::error("filters: {}; see --rate, --pass, --stop and --taps.", *problem);
    return EXIT_FAILURE;
  }
  const std::optional<FirTaps> designed = designLowPass(o.spec);
  if (!designed) {
    spdlog::error("filters: Parks-McClellan found no {}-tap low-pass for these edges.",
                  o.spec.tapCount);
    return EXIT_FAILURE;
  }
  const BandEdgesHz& e = o.spec.edges;
  const std::string designName =
      fmt::format("pm{} {:g}/{:g} Hz", o.spec.tapCount, e.passHz, e.stopHz);
  std::cout << fmt::format(
      "Temporal-filter presets at {:g} Hz capture (normalised taps, sum 1).\n\n", e.rateHz);
  printHeader(e);
  for (FilterPreset preset : kAllPresets) printRow(presetName(preset), presetTaps(preset), e);
  printRow(designName, *designed, e);
  std::cout << "\nTaps, newest frame first:\n\n";
  for (FilterPreset preset : kAllPresets) printTaps(presetName(preset), presetTaps(preset));
  printTaps(designName, *designed);
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
}

}  // namespace

void addFiltersCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<FiltersOptions>();
  CLI::App* cmd = app.add_subcommand(
      "filters",
      "Compare the temporal filter presets (delay, attenuation, jitter) at a capture rate");
  cmd->footer(
      "Example:\n  vemtool filters --rate 21\n"
      "Prints a markdown table: one row per preset (none, paper9, equiripple5, minphase9) and one\n"
      "for a Parks-McClellan design with --taps, --pass and --stop at --rate (paper 004, 3.3).\n"
      "The presets' taps are fixed in frames: their Hz figures scale with the rate.");
  LowPassSpec& spec = options->spec;
  cmd->add_option("--rate", spec.edges.rateHz, "Capture rate in Hz (default 21, the paper's)")
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--pass", spec.edges.passHz,
                  "Pass-band edge in Hz for the design and the gains (7)");
  cmd->add_option("--stop", spec.edges.stopHz, "Stop-band edge in Hz, below rate / 2 (9)");
  cmd->add_option("--taps", spec.tapCount, "Odd tap count of the design (9)");
  cmd->callback([options, &exitCode] { exitCode = runFilters(*options); });
}

}  // namespace vem::tool
