#include "bench/render/material_study.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>

#include <fmt/format.h>

#include "bench/render/reference_cache.h"
#include "bench/render/study_setup.h"
#include "client/embree/light_renderer.h"
#include "client/embree/reference_renderer.h"
#include "client/render/cube_resolution.h"
#include "client/render/environment_lighting.h"
#include "client/render/shadow_draws.h"
#include "client/render/soft_shadows.h"
#include "client/render/image_files.h"
#include "client/render/image_metrics.h"
#include "client/render/tone_mapping.h"
#include "client/scene/default_scene.h"
#include "util/svg_plot.h"

namespace vem::bench {
namespace {

struct StudyMaterial {
  std::string name;
  scene::Material material;
  bool defaultScene = false;  // the default scene as it is (its own four materials)
};

scene::Material ggx(float alpha, glm::vec3 f0) {
  scene::Material m;
  m.lobe = scene::Lobe::Ggx;
  m.roughness = std::sqrt(alpha);  // scene.h: alpha = roughness^2
  m.specularAlbedo = f0;
  m.diffuseAlbedo = glm::vec3(0.0F);
  return m;
}

scene::Material phong(float exponent) {
  scene::Material m;
  m.lobe = scene::Lobe::Phong;
  m.exponent = exponent;
  m.specularAlbedo = glm::vec3(0.5F);
  m.diffuseAlbedo = glm::vec3(0.3F);
  return m;
}

std::vector<StudyMaterial> studyMaterials() {
  const glm::vec3 gold(0.9F, 0.7F, 0.35F);
  scene::Material diffuse;
  diffuse.diffuseAlbedo = glm::vec3(0.8F);
  return {{"diffuse", diffuse},
          {"GGX 0.1", ggx(0.1F, gold)},
          {"GGX 0.3", ggx(0.3F, gold)},
          {"GGX 0.6", ggx(0.6F, gold)},
          {"Phong 10", phong(10.0F)},
          {"Phong 100", phong(100.0F)},
          {"mirror", ggx(0.0004F, glm::vec3(0.9F))},
          {"default scene", scene::Material{}, true}};
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The reference's error against its samples per pixel: c in e = c / sqrt(spp), and its time per
// sample per pixel.
struct ReferenceCurve {
  std::vector<std::pair<int, double>> points;  // spp, relative RMS against the converged one
  std::vector<double> seconds;
  double c = 0.0;
  double secondsPerSample = 0.0;
  [[nodiscard]] double secondsToReach(double error) const {
    return error > 0.0 ? (c / error) * (c / error) * secondsPerSample : 0.0;
  }
};

ReferenceCurve referenceCurve(const embree::EmbreeScene& embreeScene, const StudyScene& scene,
                              const StudyMap& map, StudyImageSize size,
                              const render::LinearImage& converged) {
  ReferenceCurve curve;
  for (const int spp : {4, 16, 64}) {
    embree::ReferenceOptions o;
    o.seed = 0xc0ffeeULL;  // not the converged reference's: its first samples would correlate
    o.samplesPerPass = std::min(spp, 16);
    o.minSamples = spp;
    o.maxSamples = spp;
    o.targetRelativeError = 0.0;
    const auto start = std::chrono::steady_clock::now();
    const embree::ReferenceResult r =
        embree::renderReference(embreeScene, scene.camera, size.widthPx, size.heightPx, map.map, o);
    curve.seconds.push_back(secondsSince(start));
    curve.points.emplace_back(spp, render::compareImages(r.image, converged).relativeRms);
  }
  // c from the 16-spp point (the 64-spp one carries more of the converged reference's own noise),
  // the time per sample from the 64-spp render (the least fixed cost per sample).
  curve.c = curve.points[1].second * std::sqrt(16.0);
  curve.secondsPerSample = curve.seconds[2] / 64.0;
  return curve;
}

struct Row {
  std::string material;
  std::string map;
  std::size_t lights = 0;
  std::string renderer;
  std::string shading;
  double error = 0.0;
  double frameMs = 0.0;
  double referenceSeconds = 0.0;
};

// The reference's error after `seconds`, from its measured c / sqrt(spp) curve.
struct CurveOfMap {
  std::string material;
  double c = 0.0;
  double secondsPerSample = 0.0;
};

std::string slug(const std::string& name) {
  std::string out;
  for (const char ch : name) {
    if (std::isalnum(static_cast<unsigned char>(ch))) {
      out += char(std::tolower(static_cast<unsigned char>(ch)));
    } else if (!out.empty() && out.back() != '-') {
      out += '-';
    }
  }
  return out;
}

// One SVG per material: each renderer and shading over N (means over the maps), and the
// reference's curve over the same span of time.
bool writeMaterialPlots(const std::string& prefix, const std::vector<Row>& rows,
                        const std::vector<CurveOfMap>& curves) {
  std::vector<std::string> materials;
  for (const Row& r : rows) {
    if (std::ranges::find(materials, r.material) == materials.end())
      materials.push_back(r.material);
  }
  for (const std::string& material : materials) {
    std::vector<PlotSeries> series;
    double fastest = 1e30;
    double slowest = 0.0;
    int colour = 0;
    for (const std::string renderer : {"Embree", "OpenGL"}) {
      for (const std::string shading : {"lights", "ratio"}) {
        std::map<std::size_t, std::array<double, 3>> byN;  // error, seconds, maps
        for (const Row& r : rows) {
          if (r.material != material || r.renderer != renderer || r.shading != shading) continue;
          auto& sums = byN[r.lights];
          sums[0] += r.error;
          sums[1] += r.frameMs * 1e-3;
          sums[2] += 1.0;
        }
        if (byN.empty()) continue;
        PlotSeries s;
        s.name = fmt::format("{}, {}", renderer, shading == "ratio" ? "by ratio" : "by the lights");
        s.colour = colour++;
        s.marker = renderer == "Embree" ? PlotMarker::Circle : PlotMarker::Square;
        s.dashed = shading == "lights";
        for (const auto& [n, sums] : byN) {
          const double seconds = sums[1] / sums[2];
          s.points.emplace_back(seconds, sums[0] / sums[2]);
          s.labels.push_back(renderer == "Embree" && shading == "ratio" ? fmt::format("N={}", n)
                                                                        : std::string());
          fastest = std::min(fastest, seconds);
          slowest = std::max(slowest, seconds);
        }
        series.push_back(std::move(s));
      }
    }
    std::vector<const CurveOfMap*> mine;
    for (const CurveOfMap& c : curves) {
      if (c.material == material) mine.push_back(&c);
    }
    if (!mine.empty() && slowest > 0.0) {
      PlotSeries reference;
      reference.name = "Monte Carlo reference (path tracer)";
      reference.colour = colour++;
      reference.marker = PlotMarker::Diamond;
      const double from = fastest / 2.0;
      const double to = std::max(slowest * 4.0, 30.0);
      for (double t = from; t <= to * 1.0001; t *= std::sqrt(2.0)) {
        double error = 0.0;
        for (const CurveOfMap* c : mine) error += c->c / std::sqrt(t / c->secondsPerSample);
        reference.points.emplace_back(t, error / double(mine.size()));
        reference.labels.emplace_back();
      }
      series.push_back(std::move(reference));
    }
    PlotText text;
    text.title =
        fmt::format("{}: relative RMS error against frame time, mean over the maps", material);
    text.xLabel = "time, s";
    text.yLabel = "relative RMS error";
    text.yPercent = true;
    if (!writeLogLogSvg(prefix + "-" + slug(material) + ".svg", text, series)) return false;
  }
  return true;
}

std::string percent(double x) { return fmt::format("{:.2f} %", 100.0 * x); }

// reference | lights | ratio, left to right, each tone-mapped with the reference's parameters.
void dumpSideBySide(const std::string& path, const render::LinearImage& reference,
                    const render::LinearImage& lights, const render::LinearImage& ratio) {
  render::ToneSmoother smoother;
  const render::ToneParams params = smoother.update(render::measureLuminance(reference), 0.0);
  const int w = reference.widthPx;
  const int h = reference.heightPx;
  std::vector<std::uint8_t> out(std::size_t(3 * w * 3 * h));
  const render::LinearImage* images[] = {&reference, &lights, &ratio};
  for (int k = 0; k < 3; ++k) {
    const std::vector<std::uint8_t> one = render::toneMappedSrgb8(*images[k], params);
    for (int y = 0; y < h; ++y) {
      std::copy_n(one.begin() + std::ptrdiff_t(3 * y * w), 3 * w,
                  out.begin() + std::ptrdiff_t(3 * (y * 3 * w + k * w)));
    }
  }
  (void)render::saveSrgbPng(out, 3 * w, h, path);
}

}  // namespace

std::expected<std::string, std::string> runMaterialStudy(const MaterialStudyOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const render::LightingGeometry geometry = render::makeLightingGeometry();
  // The maps with each cube size the study's materials call for (render::cubeFacePxFor, as
  // vemview's plan), or the one asked for.
  std::map<int, std::vector<StudyMap>> mapsByFacePx;
  const auto mapsOf = [&](int facePx) -> std::expected<const std::vector<StudyMap>*, std::string> {
    std::vector<StudyMap>& maps = mapsByFacePx[facePx];
    if (maps.empty()) {
      for (const std::string& name : options.maps) {
        auto map = loadStudyMap(std::filesystem::path(options.hdriDir) / (name + ".exr"), facePx);
        if (!map) return std::unexpected(map.error());
        maps.push_back(std::move(*map));
      }
    }
    return &maps;
  };
  std::vector<Row> rows;
  std::string glLabel;
  std::string curves;
  std::vector<CurveOfMap> curvesOfMaps;
  std::string prefilter;
  for (const StudyMaterial& material : studyMaterials()) {
    if (!options.materials.empty() &&
        std::ranges::find(options.materials, material.name) == options.materials.end()) {
      continue;
    }
    auto scene = material.defaultScene ? studyScene() : [&] {
      scene::Scene sceneWithMaterial = *scene::builtinScene("spheres");
      sceneWithMaterial.materials[0] = material.material;
      sceneWithMaterial.materials[0].name = "sphere";
      sceneWithMaterial.name = "spheres, sphere " + material.name;
      return studySceneOf(std::move(sceneWithMaterial));
    }();
    if (!scene) return std::unexpected(scene.error());
    auto embreeScene = embree::EmbreeScene::build(scene->scene);
    if (!embreeScene) return std::unexpected(embreeScene.error());
    const std::unique_ptr<StudyRenderer> embreeRenderer =
        makeEmbreeStudyRenderer(*embreeScene, *scene, geometry, options.size, 1,
                                options.softShadows);
    GlStudyRenderer glRenderer;
    if (options.gl) {
      auto made = makeGlStudyRenderer(*scene, geometry, options.size, options.glFrames);
      if (!made) return std::unexpected(made.error());
      glRenderer = std::move(*made);
      glLabel = glRenderer.timingLabel;
    }
    const int facePx =
        options.cubeFacePx > 0 ? options.cubeFacePx : render::cubeFacePxFor(scene->scene);
    auto maps = mapsOf(facePx);
    if (!maps) return std::unexpected(maps.error());
    for (const StudyMap& map : **maps) {
      embree::ReferenceOptions referenceOptions;
      referenceOptions.targetRelativeError = options.referenceError;
      referenceOptions.maxSamples = options.referenceMaxSamples;
      auto reference = cachedReference(*embreeScene, *scene, map, options.size.widthPx,
                                       options.size.heightPx, referenceOptions, options.cacheDir);
      if (!reference) return std::unexpected(reference.error());
      const ReferenceCurve curve =
          referenceCurve(*embreeScene, *scene, map, options.size, reference->image);
      curvesOfMaps.push_back({material.name, curve.c, curve.secondsPerSample});
      curves += fmt::format("| {} | {} | {} spp, {:.1f} s{} | {} | {} | {} | {:.3f} |\n",
                            material.name, map.name, reference->samplesPerPixel,
                            reference->renderSeconds, reference->fromCache ? " (cached)" : "",
                            percent(reference->relativeError), percent(curve.points[0].second),
                            percent(curve.points[1].second), curve.seconds[2] / 64.0 * 1e3);
      // The prefiltered environment for each peak factor the counts call for (as vemview's,
      // render::peakFactorFor); the first one's build time is reported.
      std::map<double, render::EnvironmentLighting> environments;
      const auto environmentFor = [&](std::size_t n) -> const render::EnvironmentLighting& {
        render::EnvironmentLightingOptions environmentOptions;
        environmentOptions.peakFactor = render::peakFactorFor(n);
        auto [at, made] = environments.try_emplace(environmentOptions.peakFactor);
        if (made) {
          const auto prefilterStart = std::chrono::steady_clock::now();
          at->second = render::makeEnvironmentLighting(map.cube, scene->scene.materials,
                                                       environmentOptions);
          if (environments.size() == 1) {
            prefilter += fmt::format("| {} | {} | {:.1f} |\n", material.name, map.name,
                                     secondsSince(prefilterStart) * 1e3);
          }
        }
        return at->second;
      };
      for (const std::size_t n : options.counts) {
        const render::EnvironmentLighting& environment = environmentFor(n);
        for (const RendererKind kind : {RendererKind::Embree, RendererKind::Gl}) {
          StudyRenderer* renderer =
              kind == RendererKind::Embree ? embreeRenderer.get() : glRenderer.renderer.get();
          if (renderer == nullptr) continue;
          std::vector<render::LinearImage> images;  // by the lights, then by ratio
          for (const bool byRatio : {false, true}) {
            StudyConfig config;
            config.renderer = kind;
            config.lighting.lightCount = n;
            // Embree traces a ray per light; OpenGL draws a map per light up to glShadowMaps.
            config.lighting.shadowedCount =
                kind == RendererKind::Embree ? 0 : std::min(n, options.glShadowMaps);
            config.lighting.glossyPass = !byRatio && scene::anyGlossy(scene->scene);
            config.lighting.clusterLayout = map.map.layout;
            render::ShadingLights lights =
                render::buildShadingLights(map.lights, geometry, config.lighting);
            // OpenGL's soft shadows spend the spare maps on the soft lights' strata
            // (render/shadow_draws.h); building them counts in the frame, as in Embree's.
            double strataMs = 0.0;
            if (kind == RendererKind::Gl && byRatio && options.softShadows) {
              const auto strataStart = std::chrono::steady_clock::now();
              const render::ShadowStrata strata =
                  render::buildShadowStrata(lights.diffuse.lights, map.cube);
              if (render::spendShadowMapsOnStrata(lights, strata, options.glShadowMaps)) {
                config.lighting.shadowedCount = lights.shadowDirs.size();
              }
              strataMs = secondsSince(strataStart) * 1e3;
            }
            auto frame = renderer->render(config, map, lights, byRatio ? &environment : nullptr);
            if (!frame) return std::unexpected(frame.error());
            frame->medianMs += strataMs;
            Row row{material.name, map.name, n, rendererLabel(kind), byRatio ? "ratio" : "lights"};
            row.frameMs = frame->medianMs;
            row.error = render::compareImages(frame->image, reference->image).relativeRms;
            row.referenceSeconds = curve.secondsToReach(row.error);
            fmt::print(stderr, "{} / {} / N {} / {} / {}: {} in {:.0f} ms\n", material.name,
                       map.name, n, row.renderer, row.shading, percent(row.error), row.frameMs);
            rows.push_back(row);
            images.push_back(std::move(frame->image));
          }
          if (!options.dumpDir.empty()) {
            std::filesystem::create_directories(options.dumpDir);
            dumpSideBySide(fmt::format("{}/{}-{}-{}-{}.png", options.dumpDir, material.name,
                                       map.name, n, kind == RendererKind::Embree ? "embree" : "gl"),
                           reference->image, images[0], images[1]);
          }
        }
      }
    }
  }
  std::string out = fmt::format(
      "Generated by `{}` in {:.0f} s, {} x {} pixels, cube maps of {}. Embree: 2 threads, a ray "
      "per light{}, one frame per point. OpenGL{}: min(N, {}) shadow maps of 256 px (shared by "
      "group below N{}), every timed frame redraws them, the median of {} frames. Times drift "
      "by tens of per cent on this shared machine.\n\n",
      options.command, secondsSince(started), options.size.widthPx, options.size.heightPx,
      options.cubeFacePx > 0
          ? fmt::format("{} px", options.cubeFacePx)
          : fmt::format("{} px ({} px for the mirror, as vemview's plan)", render::kCubeFacePx,
                        render::kMirrorCubeFacePx),
      options.softShadows ? " (by ratio: soft shadows, filtered over 4 px)" : "",
      options.gl ? fmt::format(" ({})", glLabel) : " (not run: --no-gl)",
      options.glShadowMaps,
      options.softShadows ? "; by ratio with soft shadows, the spare maps above N hold draws "
                            "from the soft lights' strata, their build in the frame time"
                          : "",
      options.glFrames);
  out +=
      "| material | map | N | renderer | shading | error (relative RMS) | frame ms | reference's "
      "time to that error, s | x faster than the reference |\n"
      "|---|---|---:|---|---|---:|---:|---:|---:|\n";
  for (const Row& r : rows) {
    out += fmt::format("| {} | {} | {} | {} | {} | {} | {:.0f} | {:.2f} | {:.1f} |\n", r.material,
                       r.map, r.lights, r.renderer, r.shading, percent(r.error), r.frameMs,
                       r.referenceSeconds, r.referenceSeconds / (r.frameMs * 1e-3));
  }
  out +=
      "\nThe references and their own curves (error against the converged reference at 4 and 16 "
      "samples per pixel, another seed; time per sample per pixel):\n\n"
      "| material | map | converged reference | its noise | 4 spp | 16 spp | ms per spp |\n"
      "|---|---|---|---:|---:|---:|---:|\n" +
      curves;
  out +=
      "\nPrefiltering (once per cube map, not per frame), ms:\n\n| material | map | ms "
      "|\n|---|---|---:|\n" +
      prefilter;
  if (!options.plotPrefix.empty()) {
    if (!writeMaterialPlots(options.plotPrefix, rows, curvesOfMaps)) {
      return std::unexpected("cannot write the plots " + options.plotPrefix + "-*.svg");
    }
    out += fmt::format(
        "\nError against time per material (the mean over the maps; the reference's curve from "
        "its measured c / sqrt(spp)): {}-*.svg.\n",
        std::filesystem::path(options.plotPrefix).filename().string());
  }
  return out;
}

}  // namespace vem::bench
