#include "report_writer.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "accuracy_study.h"
#include "bench_fixtures.h"
#include "machine_info.h"
#include "util/svg_plot.h"
#include "vemd_benchmarks.h"

namespace vem::bench {
namespace {

// "median (fastest)" in microseconds.
std::string timeCell(const ReportInputs& in, const std::string& name) {
  const auto it = in.timesUs.find(name);
  if (it == in.timesUs.end()) return "-";
  const auto fastest = in.minTimesUs.find(name);
  return fastest == in.minTimesUs.end()
             ? fmt::format("{:.0f}", it->second)
             : fmt::format("{:.0f} ({:.0f})", it->second, fastest->second);
}

double timeOf(const ReportInputs& in, const std::string& name) {
  const auto it = in.timesUs.find(name);
  return it == in.timesUs.end() ? std::nan("") : it->second;
}

void stageTable(std::ostringstream& md, const ReportInputs& in) {
  const auto& configs = stageConfigs();
  md << "## Stage timings\n\nMicroseconds per frame, one thread: the median of 5 repetitions, and "
        "in "
        "brackets the fastest. This is a shared virtual machine: the same binary's timings drift "
        "by up "
        "to 30 % from one minute to the next, all stages together. Input: a procedural sky as the "
        "camera's polar (hemisphere) map.\n\n| stage |";
  for (const auto& c : configs) md << " " << c.label() << " |";
  md << " paper 004, section 6 (Pentium 4, 3 GHz; 360x90, 300 lights) |\n|---|";
  for (std::size_t i = 0; i < configs.size(); ++i) md << "---:|";
  md << "---|\n";
  const std::vector<std::tuple<std::string, std::string, std::string>> rows{
      {"tables", "importance and CDFs", "under 2000 (CDF and luminous power)"},
      {"lights_havran", "N lights, Havran sampler", "732 for 300 (410 samples/ms)"},
      {"lights_standard", "N lights, standard sampler (baseline)", "-"},
      {"fir", "FIR, paper's 9 taps", "1000 for 210 lights"},
      {"clustering", "clustering (Q = 72)", "about 1000 for 300 lights"},
      {"regions", "angular regions (200), light lists", "under 1000"},
      {"shadow_groups", "vemview: 64 shadow maps shared by group (k-means)", "-"},
      {"shadow_nearest", "vemview: 64 shadow maps, the nearest caster's (paper)", "-"},
      {"chain", "capture chain: tables, lights, FIR, clustering", "under 5000"},
      {"chain_regions", "whole chain: the capture chain plus angular regions", "-"}};
  for (const auto& [key, label, paper] : rows) {
    md << "| " << label << " |";
    for (std::size_t i = 0; i < configs.size(); ++i)
      md << " " << timeCell(in, fmt::format("stage/{}/{}", key, i)) << " |";
    md << " " << paper << " |\n";
  }
  md << "| samples per ms, Havran |";
  for (std::size_t i = 0; i < configs.size(); ++i)
    md << fmt::format(" {:.0f} |", 1e3 * double(configs[i].lights) /
                                       timeOf(in, fmt::format("stage/lights_havran/{}", i)));
  md << " 410 |\n\n";
  const double chain = timeOf(in, "stage/chain/1");
  const double whole = timeOf(in, "stage/chain_regions/1");
  const auto fastest = in.minTimesUs.find("stage/chain_regions/1");
  md << fmt::format(
      "Target: the whole chain at 1024x256 with 1024 lights under 1000 us on one core: "
      "median **{:.0f} us with the angular regions, {}** (fastest repetition {:.0f} us); "
      "{:.0f} us for the capture chain alone (what vemd computes per frame; the "
      "renderer builds the regions).\n\n",
      whole, whole < 1000 ? "met" : "NOT met",
      fastest == in.minTimesUs.end() ? whole : fastest->second, chain);
}

void calibrationTable(std::ostringstream& md, const ReportInputs& in) {
  md << "## Calibration applied per frame\n\nA 1280x1024 raw frame of the camera simulator "
        "(190-degree lens, log response) through the photometric table and the remap into a "
        "1024x256 polar map, one thread, microseconds: median (fastest). Baseline: the whole frame "
        "through the same table into a float image, then OpenCV's `cv::remap` (bilinear) with the "
        "same sensor positions. The table is rebuilt only when exposure or gain change, the remap "
        "only when the calibration changes.\n\n| format | apply (vemcast) | baseline (LUT + "
        "cv::remap) | code table rebuild |\n|---|---:|---:|---:|\n";
  for (const char* format : {"Mono16", "RGB16", "Mono12"}) {
    md << fmt::format("| {} | {} | {} | {} |\n", format,
                      timeCell(in, fmt::format("calib/apply_{}", format)),
                      timeCell(in, fmt::format("calib/baseline_{}", format)),
                      timeCell(in, fmt::format("calib/lut_{}", format)));
  }
  const double mono = timeOf(in, "calib/apply_Mono16");
  md << fmt::format("\nRemap table, built once per calibration: {} us.\n\nTarget: a 1280x1024 "
                    "16-bit frame into the 1024x256 polar map under 1000 us on one core: Mono16 "
                    "median **{:.0f} us, {}**.\n\n",
                    timeCell(in, "calib/build_remap"), mono, mono < 1000 ? "met" : "NOT met");
}

void recordingTable(std::ostringstream& md, const ReportInputs& in) {
  md << "## Recordings\n\nOne 1280x1024 Mono16 frame of the camera simulator per record, zstd level "
        "1 on split byte planes, CRC32C through ISA-L (docs/vem-format.md), one thread, "
        "microseconds: median (fastest). Reading includes the file read, the checksum, the "
        "metadata and the decompression; writing the compression, the checksum and the write (no "
        "fdatasync).\n\n| stage | time |\n|---|---:|\n";
  md << "| read + decompress | " << timeCell(in, "recording/read_decompress_Mono16") << " |\n";
  md << "| compress + write | " << timeCell(in, "recording/write_compress_Mono16") << " |\n\n";
  const double read = timeOf(in, "recording/read_decompress_Mono16");
  md << fmt::format("Replay budget: at 300 frames/s a frame has 3333 us; reading takes {:.0f} us of "
                    "it ({:.0f} frames/s for reading alone).\n\n",
                    read, 1e6 / read);
}

void accuracyVersusTime(std::ostringstream& md, const ReportInputs& in,
                        const std::vector<MapErrors>& sphere,
                        const std::filesystem::path& docsDir) {
  md << "## Accuracy against time\n\nThe 18 shared HDRIs (512x256, full sphere). Error: relative "
        "RMS "
        "of the irradiance from the lights at 64 Fibonacci normals against exact integration over "
        "the map, mean over the maps. Time: importance tables plus N lights, per frame.\n\n"
        "| N | Havran error | Havran time (us) | standard error | standard time (us) |\n"
        "|---:|---:|---:|---:|---:|\n";
  PlotSeries havran{"Havran", {}, {}}, standard{"standard", {}, {}};
  for (std::size_t k = 0; k < in.counts.size(); ++k) {
    double h = 0, s = 0;
    for (const auto& row : sphere) {
      h += row.havran[k] / double(sphere.size());
      s += row.standard[k] / double(sphere.size());
    }
    const double th = timeOf(in, fmt::format("accuracy/havran/{}", in.counts[k]));
    const double ts = timeOf(in, fmt::format("accuracy/standard/{}", in.counts[k]));
    md << fmt::format("| {} | {:.4f} | {:.1f} | {:.4f} | {:.1f} |\n", in.counts[k], h, th, s, ts);
    havran.points.push_back({th, h});
    standard.points.push_back({ts, s});
    havran.labels.push_back(fmt::format("N={}", in.counts[k]));
    standard.labels.push_back(fmt::format("N={}", in.counts[k]));
  }
  havran.marker = PlotMarker::Circle;
  standard.marker = PlotMarker::Square;
  standard.labelOffsetPx = {6.0, 14.0};
  if (!writeLogLogSvg(docsDir / "accuracy-vs-time.svg",
                      {"Irradiance error of the N lights (not a render) against time per frame",
                       "time per frame: importance tables plus N lights (us)",
                       "irradiance error, relative RMS at 64 normals", true},
                      {havran, standard}, PlotCanvas{760, 460})) {
    md << "\n(The plot could not be written to " << (docsDir / "accuracy-vs-time.svg").string()
       << ".)\n";
  }
  md << "\n![irradiance error of the lights against time per frame](accuracy-vs-time.svg)\n\n"
        "Irradiance error of the lights against time per frame, log-log: the relative RMS "
        "difference between the irradiance the N lights give at 64 Fibonacci normals and exact "
        "integration over the map, mean over the 18 HDRIs (per cent), against microseconds for "
        "the importance tables plus N lights. No rendering: for the error of rendered images see "
        "the rendering section's plot.\n\n";
}

void perMapTable(std::ostringstream& md, const std::vector<MapErrors>& rows,
                 const std::vector<std::size_t>& counts, const char* title) {
  md << "### " << title << "\n\n| map |";
  for (std::size_t n : counts) md << " Havran " << n << " | standard " << n << " |";
  md << "\n|---|";
  for (std::size_t k = 0; k < counts.size(); ++k) md << "---:|---:|";
  md << "\n";
  std::vector<int> wins(counts.size(), 0);
  std::vector<double> meanH(counts.size(), 0), meanS(counts.size(), 0);
  for (const auto& row : rows) {
    md << "| " << row.map << " |";
    for (std::size_t k = 0; k < counts.size(); ++k) {
      const bool win = row.havran[k] <= row.standard[k];
      wins[k] += win ? 1 : 0;
      meanH[k] += row.havran[k] / double(rows.size());
      meanS[k] += row.standard[k] / double(rows.size());
      md << fmt::format(" {}{:.4f}{} | {:.4f} |", win ? "**" : "", row.havran[k], win ? "**" : "",
                        row.standard[k]);
    }
    md << "\n";
  }
  md << "| mean |";
  for (std::size_t k = 0; k < counts.size(); ++k)
    md << fmt::format(" {:.4f} | {:.4f} |", meanH[k], meanS[k]);
  md << "\n| Havran at or below standard |";
  for (std::size_t k = 0; k < counts.size(); ++k)
    md << fmt::format(" {} of {} | |", wins[k], rows.size());
  md << "\n\n";
}

void patternTable(std::ostringstream& md, const std::vector<PatternErrors>& rows,
                  const std::vector<std::size_t>& counts) {
  md << "## Sampling pattern\n\nMean irradiance error over the 18 HDRIs (sphere) for three "
        "patterns "
        "fed to both samplers.\n\n| pattern |";
  for (std::size_t n : counts) md << " Havran " << n << " | standard " << n << " |";
  md << "\n|---|";
  for (std::size_t k = 0; k < counts.size(); ++k) md << "---:|---:|";
  md << "\n";
  for (const auto& row : rows) {
    md << "| " << row.pattern << " |";
    for (std::size_t k = 0; k < counts.size(); ++k)
      md << fmt::format(" {:.4f} | {:.4f} |", row.havranMean[k], row.standardMean[k]);
    md << "\n";
  }
  md << "\n";
}

}  // namespace

std::string writeReport(const ReportInputs& in, const std::filesystem::path& docsDir) {
  std::ostringstream md;
  md << "# Benchmarks\n\nGenerated by `cmake --build build --target bench`, which runs "
        "`build/tests/bench/vem_camera_bench --frames 300 --report build/camera-latency.md` "
        "inside its own network namespace, `build/tests/bench/vem_stream_bench --report "
        "build/stream.md`, `build/tests/bench/vem_mqtt_bench --report build/mqtt.md`, "
        "`build/tests/bench/vem_render_bench` (the render study, also alone "
        "as `--target render-bench`: docs/render-accuracy.md, its plot and build/render.md), "
        "`VEM_SOAK_SECONDS=60 VEM_SOAK_REPORT=build/soak.md build/tests/soak/vem_soak_tests`, "
        "`build/daemon/tools/vemtool/vemtool coherence --maps ../shared/data/hdri --plot "
        "docs/coherence-accuracy-vs-flicker.svg > build/coherence.md`, "
        "then `build/tests/bench/vem_bench --benchmark_min_time=0.2 "
        "--benchmark_repetitions=5 --include build/coherence.md --include build/camera-latency.md "
        "--include build/stream.md --include build/mqtt.md "
        "--include build/soak.md --include build/render.md --report docs/BENCHMARKS.md` (Release build, -O3; one thread except where a section says "
        "otherwise). Machine: "
     << machineDescription() << ". Do not edit by hand: rerun the command.\n\n";
  stageTable(md, in);
  calibrationTable(md, in);
  recordingTable(md, in);
  md << vemdReportSection();
  for (const std::string& section : in.includedSections) md << section << "\n";
  const auto sphere = perMapErrors(in.counts, MapLayout::Sphere);
  accuracyVersusTime(md, in, sphere, docsDir);
  const std::vector<std::size_t> tableCounts{64, 256, 1024};
  md << "## Accuracy per map\n\nRelative RMS irradiance error at 64 normals; bold where Havran's "
        "is at "
        "or below the standard sampler's. The hemisphere table uses each map's upper half as the "
        "camera's polar map.\n\n";
  perMapTable(md, perMapErrors(tableCounts, MapLayout::Sphere), tableCounts,
              "Full sphere (equirectangular)");
  perMapTable(md, perMapErrors(tableCounts, MapLayout::Hemisphere), tableCounts,
              "Upper hemisphere (polar)");
  patternTable(md, patternComparison(tableCounts), tableCounts);
  return md.str();
}

}  // namespace vem::bench
