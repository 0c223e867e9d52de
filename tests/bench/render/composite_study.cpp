#include "bench/render/composite_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "bench/render/reference_cache.h"
#include "bench/render/study_setup.h"
#include "client/embree/light_renderer.h"
#include "client/embree/surface_classes.h"
#include "client/gl/gl_context.h"
#include "client/gl/gl_renderer.h"
#include "client/render/environment_lighting.h"
#include "client/render/image_files.h"
#include "client/render/image_metrics.h"
#include "client/render/shadow_draws.h"
#include "client/render/soft_shadows.h"
#include "client/render/tone_mapping.h"
#include "client/scene/local_scene.h"
#include "client/scene/mixed_reality_world.h"
#include "client/vemview/plate_source.h"

namespace vem::bench {
namespace {

constexpr double kShadowDarkening = 0.05;  // the shadow region: truth darker than the plate by this
constexpr std::size_t kDumpCount = 256;

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

float luminanceOf(const render::LinearImage& image, std::size_t i) {
  return 0.2126F * image.rgb[3 * i] + 0.7152F * image.rgb[3 * i + 1] +
         0.0722F * image.rgb[3 * i + 2];
}

// `image` covered only where `mask` is set.
render::LinearImage restricted(render::LinearImage image, const std::vector<std::uint8_t>& mask) {
  for (std::size_t i = 0; i < image.pixelCount(); ++i) image.covered[i] = mask[i];
  return image;
}

render::LinearImage coveredEverywhere(render::LinearImage image) {
  std::ranges::fill(image.covered, std::uint8_t{1});
  return image;
}

struct Errors {
  double whole = 0.0;         // relative RMS
  double wholeMeanAbs = 0.0;  // mean |dY| / mean Y: less ruled by a few bright pixels
  double shadow = 0.0;
};

Errors errorsOf(const render::LinearImage& composite, const render::LinearImage& truth,
                const std::vector<std::uint8_t>& shadowRegion) {
  const std::vector<std::uint8_t> all(truth.pixelCount(), 1);
  const render::ImageError whole =
      render::compareImages(restricted(composite, all), restricted(truth, all));
  return {
      whole.relativeRms, whole.meanAbsoluteRelative,
      render::compareImages(restricted(composite, shadowRegion), restricted(truth, shadowRegion))
          .relativeRms};
}

scene::Scene rotatedAboutY(scene::Scene s, float angleRad) {
  const glm::mat3 r(glm::rotate(glm::mat4(1.0F), angleRad, glm::vec3(0.0F, 1.0F, 0.0F)));
  for (scene::Mesh& mesh : s.meshes) {
    for (glm::vec3& p : mesh.positions) p = r * p;
    for (glm::vec3& n : mesh.normals) n = r * n;
  }
  return s;
}

// The plate camera turned by `angleRad` about its own horizontal axis (a tilt error).
scene::ViewCamera tilted(scene::ViewCamera camera, float angleRad) {
  camera.viewFromWorld =
      glm::rotate(glm::mat4(1.0F), angleRad, glm::vec3(1.0F, 0.0F, 0.0F)) * camera.viewFromWorld;
  return camera;
}

// The same view of geometry turned by `angleRad` about +Y: the lights seem turned the other way.
scene::ViewCamera followingYaw(scene::ViewCamera camera, float angleRad) {
  camera.viewFromWorld =
      camera.viewFromWorld * glm::rotate(glm::mat4(1.0F), -angleRad, glm::vec3(0.0F, 1.0F, 0.0F));
  camera.eyeWorld = glm::vec3(glm::rotate(glm::mat4(1.0F), angleRad, glm::vec3(0, 1, 0)) *
                              glm::vec4(camera.eyeWorld, 1.0F));
  return camera;
}

// The composition's two scenes as Embree builds them.
struct LayerScenes {
  embree::EmbreeScene withObjects;
  embree::EmbreeScene localOnly;
  std::vector<bool> objectMeshes;
};

std::expected<LayerScenes, std::string> layerScenesOf(const scene::LocalComposition& c) {
  auto withObjects = embree::EmbreeScene::build(c.withObjects);
  auto localOnly = embree::EmbreeScene::build(c.localOnly);
  if (!withObjects) return std::unexpected(withObjects.error());
  if (!localOnly) return std::unexpected(localOnly.error());
  return LayerScenes{std::move(*withObjects), std::move(*localOnly), c.objectMeshes};
}

struct Composited {
  render::LinearImage differential;
  render::LinearImage pasted;
  double withMs = 0.0;     // the render with the objects and the surface classes
  double withoutMs = 0.0;  // the render without them (skipped while the lights are unchanged)
  double compositeMs = 0.0;
};

// The composite of `layers` into `plate` (a first frame: the albedo from this plate alone), timed,
// and the objects pasted over it for comparison.
void compositeInto(Composited& out, const render::LinearImage& plate,
                   const render::DifferentialLayers& layers) {
  const auto start = std::chrono::steady_clock::now();
  render::AlbedoEstimate albedo;
  const render::PlateColour colour;
  albedo.update(plate, layers.withoutObjects, colour);
  out.differential = render::compositeDifferential(plate, layers, albedo, colour);
  out.compositeMs = msSince(start);
  out.pasted = render::compositePasted(plate, layers, colour);
}

Composited compositeOnce(const LayerScenes& scenes, const scene::ViewCamera& camera,
                         const StudyImageSize& size, const render::ShadingLights& lights,
                         const render::LightingGeometry& geometry, const StudyMap& map,
                         const embree::LightRenderOptions& lightOptions,
                         const render::LinearImage& plate) {
  Composited out;
  render::DifferentialLayers layers;
  auto start = std::chrono::steady_clock::now();
  layers.withObjects =
      embree::renderWithLights(scenes.withObjects, camera, size.widthPx, size.heightPx, lights,
                               geometry, &map.cube, lightOptions);
  layers.classes = embree::surfaceClasses(scenes.withObjects, scenes.objectMeshes, camera,
                                          size.widthPx, size.heightPx, lightOptions.threadCount);
  out.withMs = msSince(start);
  start = std::chrono::steady_clock::now();
  layers.withoutObjects =
      embree::renderWithLights(scenes.localOnly, camera, size.widthPx, size.heightPx, lights,
                               geometry, &map.cube, lightOptions);
  out.withoutMs = msSince(start);
  compositeInto(out, plate, layers);
  return out;
}

// The OpenGL layers: the two scenes' renderers in one headless context, as vemview's composite.
struct GlLayers {
  std::unique_ptr<gl::GlContext> context;
  std::unique_ptr<gl::GlRenderer> withObjects;
  std::unique_ptr<gl::GlRenderer> localOnly;
  std::string name;
};

std::expected<GlLayers, std::string> glLayersOf(const scene::LocalComposition& c,
                                                const StudyImageSize& size,
                                                const render::LightingGeometry& geometry,
                                                std::size_t maxShadowMaps, int shadowMapPx) {
  GlLayers out;
  auto context = gl::GlContext::headless(size.widthPx, size.heightPx);
  if (!context) return std::unexpected(context.error());
  out.context = std::move(*context);
  out.name =
      fmt::format("OpenGL {} on {}", out.context->versionString(), out.context->timingLabel());
  gl::GlRendererOptions options;
  options.widthPx = size.widthPx;
  options.heightPx = size.heightPx;
  options.maxShadowMaps = maxShadowMaps;
  options.shadowMapPx = shadowMapPx;
  options.geometry = &geometry;
  scene::Scene objects;  // the maps look at the objects alone, as vemview's composite
  for (std::size_t i = 0; i < c.withObjects.meshes.size(); ++i) {
    if (c.objectMeshes[i]) objects.meshes.push_back(c.withObjects.meshes[i]);
  }
  options.shadowCasterBounds = scene::sceneBounds(objects);
  auto with = gl::GlRenderer::create(c.withObjects, options);
  if (!with) return std::unexpected(with.error());
  auto without = gl::GlRenderer::create(c.localOnly, options);
  if (!without) return std::unexpected(without.error());
  out.withObjects = std::move(*with);
  out.localOnly = std::move(*without);
  return out;
}

// vemview's OpenGL composite: the lights with the maps beyond N spent on the strata (soft
// shadows), both layers drawn with them, the classes from the primary rays.
Composited compositeOnceGl(GlLayers& layers, const LayerScenes& scenes,
                           const scene::ViewCamera& camera, const StudyImageSize& size,
                           const render::ShadingLights& lights, std::size_t maxShadowMaps,
                           const StudyMap& map, const render::EnvironmentLighting& environment,
                           std::uint64_t version, const render::LinearImage& plate) {
  Composited out;
  render::ShadingLights soft = lights;
  (void)render::spendShadowMapsOnStrata(
      soft, render::buildShadowStrata(lights.diffuse.lights, map.cube), maxShadowMaps);
  soft.lightsKey = version;  // every timed frame draws its maps
  const gl::RatioShading ratio{&environment, version};
  render::DifferentialLayers rendered;
  auto start = std::chrono::steady_clock::now();
  (void)layers.withObjects->render(camera, soft, &map.cube, version, ratio);
  rendered.withObjects = layers.withObjects->readLinear();
  rendered.classes = embree::surfaceClasses(scenes.withObjects, scenes.objectMeshes, camera,
                                            size.widthPx, size.heightPx, 2);
  out.withMs = msSince(start);
  start = std::chrono::steady_clock::now();
  (void)layers.localOnly->render(camera, soft, &map.cube, version, ratio);
  rendered.withoutObjects = layers.localOnly->readLinear();
  out.withoutMs = msSince(start);
  compositeInto(out, plate, rendered);
  return out;
}

void dumpRow(const std::string& path, std::initializer_list<const render::LinearImage*> images,
             const render::ToneParams& params) {
  const render::LinearImage& first = **images.begin();
  const int w = first.widthPx;
  const int h = first.heightPx;
  const int n = int(images.size());
  std::vector<std::uint8_t> out(std::size_t(3 * w * n * h));
  int k = 0;
  for (const render::LinearImage* image : images) {
    const std::vector<std::uint8_t> one = render::toneMappedSrgb8(*image, params);
    for (int y = 0; y < h; ++y) {
      std::copy_n(one.begin() + std::ptrdiff_t(3 * y * w), 3 * w,
                  out.begin() + std::ptrdiff_t(3 * (y * n * w + k * w)));
    }
    ++k;
  }
  (void)render::saveSrgbPng(out, n * w, h, path);
}

// |composite - truth| as grey, scaled so that 10 % of the truth's mean luminance is white.
render::LinearImage differenceImage(const render::LinearImage& a, const render::LinearImage& b,
                                    float meanLuminance) {
  render::LinearImage out = render::LinearImage::black(a.widthPx, a.heightPx);
  for (std::size_t i = 0; i < a.pixelCount(); ++i) {
    const float d = std::abs(luminanceOf(a, i) - luminanceOf(b, i)) / (0.1F * meanLuminance);
    for (int c = 0; c < 3; ++c) out.rgb[3 * i + std::size_t(c)] = std::min(d, 1.0F);
    out.covered[i] = 1;
  }
  return out;
}

std::string pct(double x) { return fmt::format("{:.1f} %", 100.0 * x); }

double percentileOf(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::ranges::sort(values);
  return values[std::min(values.size() - 1, std::size_t(p * double(values.size())))];
}

// vemview's plate decoding (an MPEG-4 video through OpenCV and FFmpeg, then sRGB to linear) per
// picture, at three sizes: videos of `frames` pictures of the plate scaled up, written here.
std::expected<std::string, std::string> plateDecodeRows(const render::LinearImage& plate,
                                                        const std::filesystem::path& folder,
                                                        int frames) {
  std::filesystem::create_directories(folder);
  render::LinearImage exposed = plate;  // the camera's exposure: the mean at 0.35 of its white
  double meanY = 0.0;
  for (std::size_t i = 0; i < plate.pixelCount(); ++i) meanY += double(luminanceOf(plate, i));
  meanY /= double(std::max<std::size_t>(plate.pixelCount(), 1));
  for (float& v : exposed.rgb) v = float(double(v) * 0.35 / std::max(meanY, 1e-12));
  const std::vector<std::uint8_t> srgb = render::displaySrgb8(exposed);
  const cv::Mat small(plate.heightPx, plate.widthPx, CV_8UC3,
                      const_cast<std::uint8_t*>(srgb.data()));
  std::string rows;
  for (const auto& [w, h] : {std::pair{640, 480}, std::pair{1280, 720}, std::pair{1920, 1080}}) {
    const std::string path = (folder / fmt::format("plate-{}x{}.mp4", w, h)).string();
    {
      cv::VideoWriter writer(path, cv::CAP_FFMPEG, cv::VideoWriter::fourcc('m', 'p', '4', 'v'),
                             30.0, cv::Size(w, h));
      if (!writer.isOpened()) return std::unexpected("cannot write " + path);
      cv::Mat big;
      cv::resize(small, big, cv::Size(w, h), 0, 0, cv::INTER_LINEAR);
      for (int i = 0; i < frames; ++i) {
        cv::Mat frame = big.clone();
        cv::randn(frame, cv::Scalar::all(0), cv::Scalar::all(4));  // sensor noise: real bits
        cv::add(frame, big, frame);
        writer.write(frame);
      }
    }
    auto source = view::openPlateSource(path);
    if (!source) return std::unexpected(source.error());
    std::vector<double> ms;
    for (;;) {
      const auto start = std::chrono::steady_clock::now();
      const std::optional<view::PlateFrame> picture = (*source)->next();
      if (!picture) break;
      ms.push_back(msSince(start));
    }
    rows += fmt::format("| {} x {} | {} | {:.1f} | {:.1f} |\n", w, h, ms.size(), medianOf(ms),
                        percentileOf(ms, 0.99));
  }
  return rows;
}

}  // namespace

std::expected<std::string, std::string> runCompositeStudy(const CompositeStudyOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const scene::MixedRealityWorld world = scene::mixedRealityWorld();
  const scene::ViewCamera camera = scene::plateViewCamera(world);
  const render::LightingGeometry geometry = render::makeLightingGeometry();
  auto realScene = studySceneSeenBy(world.realSurfaces, camera);
  auto truthScene = studySceneSeenBy(world.realWithObjects, camera);
  if (!realScene) return std::unexpected(realScene.error());
  if (!truthScene) return std::unexpected(truthScene.error());
  auto realEmbree = embree::EmbreeScene::build(realScene->scene);
  auto truthEmbree = embree::EmbreeScene::build(truthScene->scene);
  if (!realEmbree) return std::unexpected(realEmbree.error());
  if (!truthEmbree) return std::unexpected(truthEmbree.error());

  scene::Scene local = scene::floorOnly();
  for (const scene::Mesh& mesh : world.proxies.meshes) local.meshes.push_back(mesh);
  const scene::LocalComposition composition = scene::composeWithLocal(world.objects, local);
  auto renderer = layerScenesOf(composition);
  if (!renderer) return std::unexpected(renderer.error());
  const scene::LocalComposition floorOnlyComposition =
      scene::composeWithLocal(world.objects, scene::floorOnly());
  auto floorRenderer = layerScenesOf(floorOnlyComposition);
  if (!floorRenderer) return std::unexpected(floorRenderer.error());
  const float yawErrorRad = 2.0F * 3.14159265F / 180.0F;
  const scene::LocalComposition yawed = scene::composeWithLocal(
      rotatedAboutY(world.objects, yawErrorRad), rotatedAboutY(local, yawErrorRad));
  auto yawRenderer = layerScenesOf(yawed);
  if (!yawRenderer) return std::unexpected(yawRenderer.error());
  std::optional<GlLayers> glLayers;
  if (options.gl) {
    auto made = glLayersOf(composition, options.size, geometry, options.glShadowMaps,
                           options.glShadowMapPx);
    if (!made) return std::unexpected("OpenGL: " + made.error());
    glLayers = std::move(*made);
  }
  auto withScene = studySceneSeenBy(composition.withObjects, camera);
  if (!withScene) return std::unexpected(withScene.error());

  render::LinearImage lastPlate;
  std::string errorRows;
  std::string timeRows;
  std::string registrationRows;
  std::string referenceRows;
  for (const std::string& name : options.maps) {
    auto map = loadStudyMap(std::filesystem::path(options.hdriDir) / (name + ".exr"));
    if (!map) return std::unexpected(map.error());
    embree::ReferenceOptions referenceOptions;
    referenceOptions.targetRelativeError = options.referenceError;
    referenceOptions.maxSamples = options.referenceMaxSamples;
    auto plateRef = cachedReference(*realEmbree, *realScene, *map, options.size.widthPx,
                                    options.size.heightPx, referenceOptions, options.cacheDir);
    if (!plateRef) return std::unexpected(plateRef.error());
    auto truthRef = cachedReference(*truthEmbree, *truthScene, *map, options.size.widthPx,
                                    options.size.heightPx, referenceOptions, options.cacheDir);
    if (!truthRef) return std::unexpected(truthRef.error());
    const render::LinearImage plate = coveredEverywhere(plateRef->image);
    lastPlate = plate;
    const render::LinearImage truth = coveredEverywhere(truthRef->image);
    referenceRows += fmt::format("| {} | {} / {} | {} / {} | {:.0f} s / {:.0f} s |\n", name,
                                 plateRef->samplesPerPixel, truthRef->samplesPerPixel,
                                 pct(plateRef->relativeError), pct(truthRef->relativeError),
                                 plateRef->renderSeconds, truthRef->renderSeconds);

    // The shadow region: real surfaces the objects darken, from the two references.
    const std::vector<render::SurfaceClass> classes =
        embree::surfaceClasses(renderer->withObjects, composition.objectMeshes, camera,
                               options.size.widthPx, options.size.heightPx, 2);
    std::vector<std::uint8_t> shadowRegion(plate.pixelCount(), 0);
    std::size_t shadowPixels = 0;
    for (std::size_t i = 0; i < plate.pixelCount(); ++i) {
      const bool darker =
          luminanceOf(truth, i) < float(1.0 - kShadowDarkening) * luminanceOf(plate, i);
      shadowRegion[i] = classes[i] == render::SurfaceClass::Local && darker ? 1 : 0;
      shadowPixels += shadowRegion[i];
    }

    std::map<double, render::EnvironmentLighting> environments;
    for (const std::size_t n : options.counts) {
      render::EnvironmentLightingOptions environmentOptions;
      environmentOptions.peakFactor = render::peakFactorFor(n);
      auto [at, made] = environments.try_emplace(environmentOptions.peakFactor);
      if (made) {
        at->second = render::makeEnvironmentLighting(map->cube, composition.withObjects.materials,
                                                     environmentOptions);
      }
      render::LightingOptions lighting;
      lighting.lightCount = n;
      lighting.shadowedCount = 0;
      render::ShadingLights lights = studyLights(*map, *withScene, geometry, lighting);
      lights.glossy.reset();
      embree::LightRenderOptions lightOptions;
      lightOptions.environment = &at->second;
      lightOptions.softShadows = true;
      lightOptions.cubeCoverage = map->map.layout;

      // Timed: a frame whose lights changed (both renders), a frame whose lights did not (the
      // render without the objects kept), and the plain render of objects and local scene.
      std::vector<double> fullMs;
      std::vector<double> reuseMs;
      std::vector<double> plainMs;
      Composited result;
      for (int frame = 0; frame < options.frames; ++frame) {
        result = compositeOnce(*renderer, camera, options.size, lights, geometry, *map,
                               lightOptions, plate);
        fullMs.push_back(result.withMs + result.withoutMs + result.compositeMs);
        reuseMs.push_back(result.withMs + result.compositeMs);
        const auto start = std::chrono::steady_clock::now();
        (void)embree::renderWithLights(renderer->withObjects, camera, options.size.widthPx,
                                       options.size.heightPx, lights, geometry, &map->cube,
                                       lightOptions);
        plainMs.push_back(msSince(start));
      }
      std::string glErrors = "| | ";
      std::optional<render::LinearImage> glComposite;
      std::string glTimes = "| | ";
      if (glLayers) {
        std::vector<double> glFullMs;
        std::vector<double> glReuseMs;
        Composited glResult;
        // OpenGL draws a map per light up to S (Embree's lights have none: it traces rays).
        render::LightingOptions glLighting = lighting;
        glLighting.shadowedCount = std::min(n, options.glShadowMaps);
        render::ShadingLights glLights = studyLights(*map, *withScene, geometry, glLighting);
        glLights.glossy.reset();
        for (int frame = 0; frame < options.frames + 1; ++frame) {  // the first warms up
          glResult = compositeOnceGl(*glLayers, *renderer, camera, options.size, glLights,
                                     options.glShadowMaps, *map, at->second,
                                     std::uint64_t(1000 * n + std::size_t(frame)), plate);
          if (frame == 0) continue;
          glFullMs.push_back(glResult.withMs + glResult.withoutMs + glResult.compositeMs);
          glReuseMs.push_back(glResult.withMs + glResult.compositeMs);
        }
        const Errors e = errorsOf(glResult.differential, truth, shadowRegion);
        glComposite = glResult.differential;
        glErrors = fmt::format("| {} | {} ", pct(e.whole), pct(e.shadow));
        glTimes = fmt::format("| {:.1f} | {:.1f} ", medianOf(glFullMs), medianOf(glReuseMs));
      }
      const Errors differential = errorsOf(result.differential, truth, shadowRegion);
      const Errors pasted = errorsOf(result.pasted, truth, shadowRegion);
      const Composited floorOnlyResult = compositeOnce(*floorRenderer, camera, options.size, lights,
                                                       geometry, *map, lightOptions, plate);
      const Errors floorOnlyErrors = errorsOf(floorOnlyResult.differential, truth, shadowRegion);
      errorRows += fmt::format(
          "| {} | {} | {} | {} {}| {} | {} | {} | {} |\n", name, n, pct(differential.whole),
          pct(differential.shadow), glErrors, pct(pasted.whole), pct(pasted.shadow),
          fmt::format("{:.1f}x", pasted.shadow / differential.shadow), pct(floorOnlyErrors.shadow));
      timeRows += fmt::format("| {} | {} | {:.1f} | {:.1f} | {:.1f} | {:.2f} {}|\n", name, n,
                              medianOf(plainMs), medianOf(fullMs), medianOf(reuseMs),
                              result.compositeMs, glTimes);
      if (n == kDumpCount) {
        for (const float degrees : {0.5F, 1.0F}) {
          const Composited off =
              compositeOnce(*renderer, tilted(camera, degrees * 3.14159265F / 180.0F), options.size,
                            lights, geometry, *map, lightOptions, plate);
          const Errors e = errorsOf(off.differential, truth, shadowRegion);
          registrationRows +=
              fmt::format("| {} | plate camera tilted by {} degree | {} | {} | {} |\n", name,
                          degrees, pct(e.whole), pct(e.wholeMeanAbs), pct(e.shadow));
        }
        const Composited yawOff =
            compositeOnce(*yawRenderer, followingYaw(camera, yawErrorRad), options.size, lights,
                          geometry, *map, lightOptions, plate);
        const Errors e = errorsOf(yawOff.differential, truth, shadowRegion);
        registrationRows += fmt::format("| {} | probe yaw off by 2 degrees | {} | {} | {} |\n",
                                        name, pct(e.whole), pct(e.wholeMeanAbs), pct(e.shadow));
        registrationRows += fmt::format("| {} | none (calibrated) | {} | {} | {} |\n", name,
                                        pct(differential.whole), pct(differential.wholeMeanAbs),
                                        pct(differential.shadow));
        if (!options.dumpDir.empty()) {
          std::filesystem::create_directories(options.dumpDir);
          render::ToneSmoother smoother;
          const render::ToneParams params = smoother.update(render::measureLuminance(truth), 0.0);
          double meanY = 0.0;
          for (std::size_t i = 0; i < truth.pixelCount(); ++i)
            meanY += double(luminanceOf(truth, i));
          meanY /= double(truth.pixelCount());
          const render::LinearImage diff =
              differenceImage(result.differential, truth, float(meanY));
          const render::LinearImage pastedDiff =
              differenceImage(result.pasted, truth, float(meanY));
          dumpRow(fmt::format("{}/composite-{}.png", options.dumpDir, name),
                  {&plate, &result.differential, &truth, &diff, &pastedDiff}, params);
          if (glComposite) {
            const render::LinearImage glDiff = differenceImage(*glComposite, truth, float(meanY));
            dumpRow(fmt::format("{}/composite-{}-gl.png", options.dumpDir, name),
                    {&*glComposite, &truth, &glDiff}, params);
          }
        }
      }
    }
    errorRows += fmt::format("| {} | shadow region | {} pixels of {} | | | | | | | |\n", name,
                             shadowPixels, plate.pixelCount());
  }
  std::string decodeRows;
  if (!options.cacheDir.empty()) {
    auto decoded =
        plateDecodeRows(lastPlate, std::filesystem::path(options.cacheDir) / "plates", 60);
    if (!decoded) return std::unexpected(decoded.error());
    decodeRows = *decoded;
  }
  std::string out = fmt::format(
      "Scene: `{}` filmed by its plate camera at {} x {} px; the synthetic objects: {}. Local "
      "scene: the floor plane and the proxies (box, wall). Lights: the map's first N Havran "
      "lights, shading by ratio with soft shadows (Embree: a draw per light and pixel; {}: S = {} "
      "shadow maps of {} px, those beyond N along the strata, the surface classes from Embree's "
      "primary rays). References: embree::renderReference to {} relative error.\n\n",
      world.realSurfaces.name, options.size.widthPx, options.size.heightPx, world.objects.name,
      glLayers ? glLayers->name : std::string("OpenGL (not run)"), options.glShadowMaps,
      options.glShadowMapPx, pct(options.referenceError));
  out += "### Error against the truth (relative RMS)\n\n";
  out +=
      "| map | N | Embree, whole | Embree, shadow region | OpenGL, whole | OpenGL, shadow "
      "region | pasted, whole | pasted, shadow region | pasted / Embree in the shadows | "
      "Embree with the floor plane only, shadow region |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n" +
      errorRows;
  out += "\n### Time per frame (ms, median)\n\n";
  out +=
      "| map | N | Embree: plain render (objects and local scene) | Embree: composite, lights "
      "changed | Embree: composite, lights unchanged (\"without\" reused) | of which the "
      "composite itself | OpenGL: composite, lights changed | OpenGL: lights unchanged "
      "|\n|---|---|---|---|---|---|---|---|\n" +
      timeRows;
  out +=
      "\n### What a registration error costs (N = 256)\n\n| map | error | whole, relative RMS "
      "| whole, mean absolute | shadow region, relative RMS |\n|---|---|---|---|---|\n" +
      registrationRows;
  if (!decodeRows.empty()) {
    out +=
        "\n### Plate decoding (vemview's video plate: OpenCV's VideoCapture through FFmpeg, "
        "MPEG-4 part 2, then sRGB to linear), ms per picture\n\n| size | pictures | median | "
        "p99 |\n|---|---|---|---|\n" +
        decodeRows;
  }
  out +=
      "\n### The references\n\n| map | samples per pixel, plate / truth | relative error | "
      "render time |\n|---|---|---|---|\n" +
      referenceRows;
  out += fmt::format(
      "\nStudy time: {:.0f} s.\n",
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  return out;
}

}  // namespace vem::bench
