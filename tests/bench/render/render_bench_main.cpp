// vem_render_bench: what accuracy costs in time (issue 7): the default scene under a few real
// HDRIs, rendered by the OpenGL and the Embree renderers over sweeps of the light count, the
// shadowed lights, the shadow-map resolution, angular regions and clustering (study_sweeps.h),
// each frame timed and compared with the Embree Monte Carlo reference (cached in the build folder).
//
//   vem_render_bench [--maps sky,studio,city,park] [--list-maps] [--table docs/render-accuracy.md]
//                    [--plot docs/render-accuracy-vs-time.png] [--section build/render.md]
//                    [--cache DIR] [--reference-error 0.01] [--no-gl]
//   vem_render_bench --materials [--material "GGX 0.1,..."] [--dump DIR] ...  (material_study.h)
#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "bench/machine_info.h"
#include "bench/markdown_output.h"
#include "bench/render/composite_study.h"
#include "bench/render/material_study.h"
#include "bench/render/render_report.h"
#include "bench/render/study_run.h"
#include "client/render/shading_lights.h"
#include "mapio/map_file.h"

namespace {

using namespace vem::bench;

struct BenchOptions {
  // One sound map per kind of light (--list-maps): an outdoor sun (58 % of the power in 0.1 % of
  // the sphere), studio's bright source (66 %, at a peak 18 times lower than sky's: larger and
  // softer), broad indoor light (0.7 %); and park, a damaged map (knownDamage: a blue-only sun),
  // kept as a hard case. park was the "few bright sources" map until issue 17 found its sun.
  std::vector<std::string> maps{"sky", "studio", "city", "park"};
  std::string hdriDir = std::string(VEM_SHARED_DATA_DIR) + "/hdri";
  StudyImageSize size;
  double referenceError = 0.01;
  int referenceMaxSamples = 8192;
  std::string cacheDir = "render-bench-cache";
  int glFrames = 5;
  int embreeFrames = 3;
  bool noGl = false;
  bool listMaps = false;
  bool materials = false;  // the material study (material_study.h) instead of the sweeps
  bool composite = false;  // the mixed-reality study (composite_study.h) instead of the sweeps
  std::vector<std::string> materialNames;
  std::vector<std::size_t> counts;  // --materials: the light counts N (empty: the study's)
  std::size_t glShadowMaps = 256;   // --materials: OpenGL's shadow maps S = min(N, this)
  int cubeFacePx = 0;  // --materials: the cube maps' level 0 (0: as vemview's plan)
  int shadowMapPx = 0;  // --composite: OpenGL's shadow-map size (0: the study's)
  bool softShadows = false;           // --materials: by ratio with soft shadows
  std::string dumpDir;
  std::string sweeps = "abcde";
  std::string table;
  std::string plot;
  std::string section;
};

double loadAverage() {
  std::ifstream loadavg("/proc/loadavg");
  double load = 0.0;
  loadavg >> load;
  return load;
}

// The arguments with the project folder left out of paths, for the report.
std::string commandLine(int argc, char** argv) {
  const std::string project = std::string(VEM_PROJECT_DIR) + "/";
  std::string out = "vem_render_bench";
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.rfind(project, 0) == 0) arg = arg.substr(project.size());
    out += fmt::format(" {}", arg);
  }
  return out;
}

int fail(const std::string& message) {
  std::cerr << "vem_render_bench: " << message << "\n";
  return 1;
}

int parse(int argc, char** argv, BenchOptions& o) {
  CLI::App app{"The render study: accuracy against time for the OpenGL and Embree renderers"};
  app.add_option("--maps", o.maps, "HDRIs of the shared data (names without .exr)")->delimiter(',');
  app.add_option("--hdri-dir", o.hdriDir, "the folder of the HDRIs");
  app.add_option("--width", o.size.widthPx)->check(CLI::Range(16, 4096));
  app.add_option("--height", o.size.heightPx)->check(CLI::Range(16, 4096));
  app.add_option("--reference-error", o.referenceError, "the reference's target error")
      ->check(CLI::Range(1e-4, 0.5));
  app.add_option("--reference-max-samples", o.referenceMaxSamples)->check(CLI::Range(16, 1 << 20));
  app.add_option("--cache", o.cacheDir, "the folder of cached references");
  app.add_option("--gl-frames", o.glFrames, "timed OpenGL frames per point")
      ->check(CLI::Range(1, 100));
  app.add_option("--embree-frames", o.embreeFrames)->check(CLI::Range(1, 100));
  app.add_flag("--no-gl", o.noGl, "Embree only (no OpenGL context)");
  app.add_flag("--materials", o.materials,
               "the material study of issue 20 (a sphere on a plane, one material at a time, "
               "shading by the lights and by ratio) instead of the sweeps; writes --table");
  app.add_option("--shadow-map-px", o.shadowMapPx,
                 "with --composite: OpenGL's shadow-map size (default 256)")
      ->check(CLI::Range(64, 4096));
  app.add_flag("--composite", o.composite,
               "the mixed-reality study: objects composited into a simulated plate, against the "
               "truth (composite_study.h)");
  app.add_option("--dump", o.dumpDir, "with --materials: side-by-side PNGs into this folder");
  app.add_option("--material", o.materialNames, "with --materials: only these materials")
      ->delimiter(',');
  app.add_option("--counts", o.counts, "with --materials or --composite: the light counts N, e.g. 16,256")
      ->delimiter(',');
  app.add_option("--gl-shadow-maps", o.glShadowMaps,
                 "with --materials: OpenGL's shadow maps, min(N, this), shared by group below N")
      ->check(CLI::Range(std::size_t(1), vem::render::kMaxShadowMaps));
  app.add_option("--cube-face-px", o.cubeFacePx,
                 "with --materials: the cube maps' face size, as vemview --cube-face-px "
                 "(default: as vemview's plan, 512 for the mirror, else 128)")
      ->check(CLI::Range(8, 512));
  app.add_flag("--soft-shadows", o.softShadows,
               "with --materials: by ratio, soft lights draw their shadows from their strata of "
               "the sky (render/soft_shadows.h): Embree a direction per pixel, OpenGL the spare "
               "maps when N < --gl-shadow-maps (render/shadow_draws.h)");
  app.add_flag("--list-maps", o.listMaps, "print how concentrated each HDRI's light is, and exit");
  app.add_option("--sweeps", o.sweeps, "the sweeps to run, e.g. ad (study_sweeps.h)");
  app.add_option("--table", o.table, "write the study (markdown) to this file");
  app.add_option("--plot", o.plot,
                 "write the error-against-time plot (PNG, and SVG beside it); with --materials, "
                 "the prefix of one SVG per material");
  app.add_option("--section", o.section, "write the docs/BENCHMARKS.md section to this file");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? -1 : 2;
  }
  return 0;
}

// Every HDRI of the folder with its character (what the choice of --maps rests on).
int listMaps(const BenchOptions& o) {
  std::vector<std::filesystem::path> paths;
  for (const auto& entry : std::filesystem::directory_iterator(o.hdriDir)) {
    if (entry.path().extension() == ".exr") paths.push_back(entry.path());
  }
  std::ranges::sort(paths);
  fmt::print(
      "| map | peak / mean luminance | power in the brightest 0.1 % | character |\n"
      "|---|---:|---:|---|\n");
  for (const auto& path : paths) {
    auto map = vem::mapio::loadMap(path);
    if (!map) return fail(map.error().message);
    const MapCharacter c = characterOf(*map);
    const auto damage = knownDamage(path.stem().string());
    fmt::print("| {} | {:.0f} | {} | {}{} |\n", path.stem().string(), c.peakToMean,
               percent(c.topShareOfPower), describeCharacter(c), damage ? "; " + *damage : "");
  }
  return 0;
}

// Links from the table's folder (docs/, where BENCHMARKS.md includes the section too).
std::string linkTo(const std::string& target, const std::string& table) {
  if (target.empty()) return "";
  if (table.empty()) return std::filesystem::path(target).filename().string();
  const std::filesystem::path base = std::filesystem::absolute(table).parent_path();
  return std::filesystem::absolute(target).lexically_relative(base).string();
}

int writeOutputs(const BenchOptions& o, const StudyContext& context,
                 const std::vector<Sweep>& sweeps, const std::vector<MapStudy>& studies) {
  const std::string plotLink = linkTo(o.plot, o.table);
  if (!o.plot.empty()) {
    if (auto written = writeAccuracyPlot(o.plot, sweeps, studies); !written) {
      return fail(written.error());
    }
  }
  if (!emitMarkdown("vem_render_bench", accuracyReport(context, sweeps, studies, plotLink),
                    o.table)) {
    return 1;
  }
  if (o.section.empty()) return 0;
  std::ofstream section(o.section);
  section << benchmarkSection(context, sweeps, studies, linkTo(o.table, o.table), plotLink);
  return section ? 0 : fail("cannot write " + o.section);
}

// The OpenGL renderer unless --no-gl; its labels go into the context.
std::expected<std::optional<GlStudyRenderer>, std::string> openGl(
    const BenchOptions& o, const StudyScene& scene, const vem::render::LightingGeometry& geometry,
    StudyContext& context) {
  if (o.noGl) return std::optional<GlStudyRenderer>{};
  auto made = makeGlStudyRenderer(scene, geometry, o.size, o.glFrames);
  if (!made) return std::unexpected(made.error() + " (--no-gl runs the Embree half alone)");
  context.glLabel = made->timingLabel;
  context.glRenderer = fmt::format("{}, {}", made->rendererName, made->version);
  context.glSoftware = made->software;
  return std::optional<GlStudyRenderer>(std::move(*made));
}

struct StudyInputs {
  const StudyScene& scene;
  const vem::embree::EmbreeScene& embreeScene;
  const vem::render::LightingGeometry& geometry;
  const std::vector<Sweep>& sweeps;
  StudyRenderers renderers;
};

// One map: its reference (cached) and every sweep point.
std::expected<MapStudy, std::string> studyMap(const BenchOptions& o, const std::string& name,
                                              const StudyInputs& in, StudyContext& context) {
  auto map = loadStudyMap(std::filesystem::path(o.hdriDir) / (name + ".exr"));
  if (!map) return std::unexpected(map.error());
  vem::embree::ReferenceOptions referenceOptions;
  referenceOptions.targetRelativeError = o.referenceError;
  referenceOptions.maxSamples = o.referenceMaxSamples;
  auto reference = cachedReference(in.embreeScene, in.scene, *map, o.size.widthPx, o.size.heightPx,
                                   referenceOptions, o.cacheDir);
  if (!reference) return std::unexpected(reference.error());
  fmt::print(stderr, "{}: reference {} samples per pixel, error {:.4f}, {:.0f} s{}\n", name,
             reference->samplesPerPixel, reference->relativeError, reference->renderSeconds,
             reference->fromCache ? " (cached)" : "");
  context.mapReasons.push_back(
      map->damage ? fmt::format("**{}** ({})", *map->damage, describeCharacter(map->character))
                  : describeCharacter(map->character));
  return runMapStudy(*map, in.scene, in.geometry, *reference, in.sweeps, in.renderers);
}

// Renders the study and writes the outputs.
int run(const BenchOptions& o, StudyContext context) {
  const auto started = std::chrono::steady_clock::now();
  auto scene = studyScene();
  if (!scene) return fail(scene.error());
  context.sceneDescription = scene->description;
  auto embreeScene = vem::embree::EmbreeScene::build(scene->scene);
  if (!embreeScene) return fail(embreeScene.error());
  const vem::render::LightingGeometry geometry = vem::render::makeLightingGeometry();
  auto gl = openGl(o, *scene, geometry, context);
  if (!gl) return fail(gl.error());
  const auto embree =
      makeEmbreeStudyRenderer(*embreeScene, *scene, geometry, o.size, o.embreeFrames);
  std::vector<Sweep> sweeps = studySweeps(gl->has_value());
  std::erase_if(sweeps, [&](const Sweep& s) { return !o.sweeps.contains(s.id); });
  const StudyInputs inputs{*scene,
                           *embreeScene,
                           geometry,
                           sweeps,
                           {*gl ? (*gl)->renderer.get() : nullptr, embree.get()}};
  std::vector<MapStudy> studies;
  for (const std::string& name : o.maps) {
    auto study = studyMap(o, name, inputs, context);
    if (!study) return fail(study.error());
    studies.push_back(std::move(*study));
  }
  context.loadAverages = {context.loadAverages.first, loadAverage()};
  context.studySeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return writeOutputs(o, context, sweeps, studies);
}

}  // namespace

int main(int argc, char** argv) {
  BenchOptions options;
  if (const int parsed = parse(argc, argv, options); parsed != 0) return parsed < 0 ? 0 : parsed;
  if (options.listMaps) return listMaps(options);
  if (options.composite) {
    CompositeStudyOptions study;
    if (options.maps != BenchOptions{}.maps) study.maps = options.maps;
    study.hdriDir = options.hdriDir;
    study.size = options.size;
    study.referenceError = options.referenceError;
    study.cacheDir = options.cacheDir;
    study.dumpDir = options.dumpDir;
    study.frames = options.embreeFrames;
    study.gl = !options.noGl;
    study.glShadowMaps = options.glShadowMaps;
    if (options.shadowMapPx > 0) study.glShadowMapPx = options.shadowMapPx;
    if (!options.counts.empty()) study.counts = options.counts;
    auto report = runCompositeStudy(study);
    if (!report) return fail(report.error());
    const std::string withCommand =
        fmt::format("Command: `{}`\n\n{}", commandLine(argc, argv), *report);
    return emitMarkdown("vem_render_bench", withCommand, options.table) ? 0 : 1;
  }
  if (options.materials) {
    MaterialStudyOptions study;
    study.maps = options.maps;
    study.hdriDir = options.hdriDir;
    study.size = options.size;
    study.referenceError = options.referenceError;
    study.referenceMaxSamples = options.referenceMaxSamples;
    study.cacheDir = options.cacheDir;
    study.materials = options.materialNames;
    study.dumpDir = options.dumpDir;
    study.gl = !options.noGl;
    study.glFrames = options.glFrames;
    study.glShadowMaps = options.glShadowMaps;
    study.cubeFacePx = options.cubeFacePx;
    study.softShadows = options.softShadows;
    study.plotPrefix = options.plot;
    if (!options.counts.empty()) study.counts = options.counts;
    study.command = commandLine(argc, argv);
    auto report = runMaterialStudy(study);
    if (!report) return fail(report.error());
    return emitMarkdown("vem_render_bench", *report, options.table) ? 0 : 1;
  }
  StudyContext context;
  context.command = commandLine(argc, argv);
  context.machine = machineDescription();
  context.loadAverages = {loadAverage(), 0.0};
  context.widthPx = options.size.widthPx;
  context.heightPx = options.size.heightPx;
  context.referenceTarget = options.referenceError;
  context.glFrames = options.glFrames;
  context.embreeFrames = options.embreeFrames;
  return run(options, std::move(context));
}
