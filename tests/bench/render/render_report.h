// The render study's outputs: docs/render-accuracy.md (the machine, the renderers, the references
// and one table per sweep with the maps as columns, closed by a few sentences computed from the
// numbers), the error-against-time plot (SVG, converted to PNG by rsvg-convert), and the short
// section docs/BENCHMARKS.md includes.
//
// Errors are fractions of the reference (shown as percentages); times are median wall-clock
// milliseconds per 320 x 240 frame (or the study's size).
#pragma once

#include <expected>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "bench/render/study_run.h"
#include "bench/render/study_sweeps.h"

namespace vem::bench {

struct StudyContext {
  std::string command;                     // how the study was run
  std::string machine;                     // CPU model and cores
  std::pair<double, double> loadAverages;  // 1-minute load average at the start and the end
  std::string glLabel;                     // empty without OpenGL
  std::string glRenderer;                  // GL_RENDERER and GL_VERSION
  bool glSoftware = true;
  std::string sceneDescription;
  int widthPx = 320;
  int heightPx = 240;
  double referenceTarget = 0.01;
  int glFrames = 5;
  int embreeFrames = 3;
  double studySeconds = 0.0;            // the whole run, references included
  std::vector<std::string> mapReasons;  // one per map: why it is in the study
};

[[nodiscard]] std::string accuracyReport(const StudyContext& context,
                                         const std::vector<Sweep>& sweeps,
                                         const std::vector<MapStudy>& studies,
                                         const std::string& plotName);

// The steps of the N and S sweeps where an error grows (beyond half the reference's target error),
// as a table, then riseNotes().
[[nodiscard]] std::string risesSection(const std::vector<Sweep>& sweeps,
                                       const std::vector<MapStudy>& studies,
                                       double referenceTarget);
// What issue 17's investigation measured about each rise (not computed by this run: the numbers
// there come from the investigation, render_rise_notes.cpp says how).
[[nodiscard]] std::string riseNotes();
// What vemview's and vemd's defaults take from the study (issue 17), hand-written like riseNotes.
[[nodiscard]] std::string defaultsNote();

// 3-5 sentences on what the numbers say, computed from them.
[[nodiscard]] std::string studyFindings(const std::vector<Sweep>& sweeps,
                                        const std::vector<MapStudy>& studies);

// The section for docs/BENCHMARKS.md: a summary table and links (relative to docs/).
[[nodiscard]] std::string benchmarkSection(const StudyContext& context,
                                           const std::vector<Sweep>& sweeps,
                                           const std::vector<MapStudy>& studies,
                                           const std::string& tableName,
                                           const std::string& plotName);

// Writes the SVG beside `pngPath` (same stem) and converts it with rsvg-convert.
[[nodiscard]] std::expected<void, std::string> writeAccuracyPlot(
    const std::filesystem::path& pngPath, const std::vector<Sweep>& sweeps,
    const std::vector<MapStudy>& studies);

// What the numbers say about a map's light, e.g. "a small, very bright source (a sun): ...".
[[nodiscard]] std::string describeCharacter(const MapCharacter& character);

// "software renderer (llvmpipe), not a GPU", the GPU's name, or "not measured".
[[nodiscard]] std::string glDescription(const StudyContext& context);

// Helpers shared by the report's parts.
[[nodiscard]] std::string percent(double fraction);  // "4.12 %"
[[nodiscard]] std::string milliseconds(double ms);   // "12.3"
// Geometric mean over the maps of an error, arithmetic mean of a time: over the sound maps (a
// damaged map, MapStudy::damaged, is shown but not averaged, unless every map is damaged).
[[nodiscard]] double meanError(const std::vector<MapStudy>& studies, const StudyConfig& config);
[[nodiscard]] double meanTimeMs(const std::vector<MapStudy>& studies, const StudyConfig& config);
// The maps the means are over, for the text: "sky, studio, city; not park, damaged".
[[nodiscard]] std::string meanedMaps(const std::vector<MapStudy>& studies);
// The render plot's caption: what its axes are, in which units, over which maps.
[[nodiscard]] std::string plotCaption(const std::vector<MapStudy>& studies);
// A map's column title: "park (damaged)" for a damaged map.
[[nodiscard]] std::string columnName(const MapStudy& study);

}  // namespace vem::bench
