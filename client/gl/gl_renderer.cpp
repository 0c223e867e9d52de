#include "client/gl/gl_renderer.h"

#include <chrono>

#include <spdlog/spdlog.h>

#include "client/gl/environment_cube.h"
#include "client/gl/environment_lighting_textures.h"
#include "client/gl/gl_mesh.h"
#include "client/gl/gl_program.h"
#include "client/gl/light_clip.h"
#include "client/gl/light_textures.h"
#include "client/gl/mirror_occlusion.h"
#include "client/gl/overlay_pass.h"
#include "client/gl/shadow_atlas.h"
#include "client/gl/texture_buffer.h"
#include "client/gl/tone_map_pass.h"

namespace vem::gl {
namespace {

constexpr GLenum kShadowUnit = kFirstLightUnit + kLightUnitCount;  // 12
constexpr GLenum kEnvironmentUnit = kShadowUnit + 1;               // 13
constexpr GLenum kCasterUnit = kEnvironmentUnit + 1;               // 14
constexpr GLenum kIrradianceUnit = kCasterUnit + 1;                // 15
constexpr GLenum kPrefilteredUnit = kIrradianceUnit + 1;           // 16
constexpr GLenum kMirrorUnit = kPrefilteredUnit + 1;              // 17
constexpr GLenum kDrawWeightUnit = kMirrorUnit + 1;               // 18
constexpr GLint kFragmentUnitsNeeded = GLint(kDrawWeightUnit) + 1;

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// The float lighting buffer: RGBA32F colour (alpha = covered) and a 24-bit depth renderbuffer.
struct LightingTarget {
  GlTexture colour;
  GlRenderbuffer depth;
  GlFramebuffer framebuffer;
};

std::expected<LightingTarget, std::string> makeLightingTarget(int widthPx, int heightPx) {
  LightingTarget target{GlTexture::create(), GlRenderbuffer::create(), GlFramebuffer::create()};
  glBindTexture(GL_TEXTURE_2D, target.colour.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, widthPx, heightPx, 0, GL_RGBA, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindRenderbuffer(GL_RENDERBUFFER, target.depth.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, widthPx, heightPx);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.colour.id(),
                         0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                            target.depth.id());
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    return std::unexpected("the lighting framebuffer (" + std::to_string(widthPx) + "x" +
                           std::to_string(heightPx) + " RGBA32F + depth) is incomplete (status " +
                           std::to_string(status) + ")");
  }
  return target;
}

// By slot, (weight rgb, draws): render/shadow_draws.h's weights, and each soft light's number of
// draws at its first slot; one zero texel when the frame has no draws (a buffer is never empty).
std::vector<float> drawWeightTexels(const render::ShadingLights& lights) {
  if (lights.shadowDrawsOfDiffuse.empty()) return {0.0F, 0.0F, 0.0F, 0.0F};
  std::vector<float> out;
  out.reserve(4 * lights.shadowDrawWeights.size());
  for (const glm::vec3& w : lights.shadowDrawWeights) out.insert(out.end(), {w.x, w.y, w.z, 0.0F});
  for (std::size_t i = 0; i < lights.shadowDrawsOfDiffuse.size(); ++i) {
    const std::uint32_t draws = lights.shadowDrawsOfDiffuse[i];
    const std::int32_t slot = lights.shadowSlotOfDiffuse[i];
    if (draws > 0 && slot >= 0 && 4 * std::size_t(slot) + 3 < out.size()) {
      out[4 * std::size_t(slot) + 3] = float(draws);
    }
  }
  return out;
}

}  // namespace

struct GlRenderer::Impl {
  GlRendererOptions options;
  scene::Bounds bounds;  // the shadow casters' (scene::shadowCasterBounds): the maps' view
  std::vector<scene::Material> materials;
  std::vector<GlMesh> meshes;
  GlProgram lighting;
  GlProgram background;
  GlProgram depth;
  LightTextures lights;
  ShadowAtlas atlas;
  EnvironmentCube environment;
  EnvironmentLightingTextures environmentLighting;  // shading by ratio
  ToneMapPass toneMap;
  LightingTarget target;
  GlVertexArray emptyVertexArray = GlVertexArray::create();
  std::optional<std::uint64_t> shadowKey;  // lightsKey of the maps in the atlas
  // Each slot's caster direction (RGBA32F, xyz): a light shadowed through another light's map
  // looks it up in that caster's view, not its own.
  TextureBuffer casterDirs;
  // Soft shadows in the maps (render/shadow_draws.h), by slot (RGBA32F): the draw's weight (rgb)
  // and, at a soft light's first slot, its number of draws (a, 0 elsewhere). Uploaded every
  // frame: the weights follow the cube map even when the directions do not.
  TextureBuffer drawWeights;
  std::size_t shadowCount = 0;
  std::optional<OverlayPass> overlay;  // windows only (presentToWindow)
  MirrorOcclusion mirrors;             // what the mirror-like meshes' reflections hit

  std::size_t shadowPass(const render::ShadingLights& frame, GlFrameStats& stats);
  void backgroundPass(const scene::ViewCamera& camera) const;
  void geometryPass(const scene::ViewCamera& camera, const render::ShadingLights& frame,
                    std::size_t shadowMaps, const RatioShading& ratio) const;
  void setMaterial(const scene::Material& material, bool glossyPass) const;
};

std::expected<std::unique_ptr<GlRenderer>, std::string> GlRenderer::create(
    const scene::Scene& scene, const GlRendererOptions& options) {
  if (std::string violation = scene::firstContractViolation(scene); !violation.empty()) {
    return std::unexpected("the scene cannot be drawn: " + violation);
  }
  auto lighting = GlProgram::build(
      "lighting", {"lighting.vert.glsl"},
      {"shading_model.glsl", "light_view.glsl", "shadow_lookup.glsl", "lighting.frag.glsl"});
  if (!lighting) return std::unexpected(lighting.error());
  auto background =
      GlProgram::build("background", {"fullscreen.vert.glsl"}, {"background.frag.glsl"});
  if (!background) return std::unexpected(background.error());
  auto depth =
      GlProgram::build("shadow depth", {"shadow_depth.vert.glsl"}, {"shadow_depth.frag.glsl"});
  if (!depth) return std::unexpected(depth.error());
  auto atlas = ShadowAtlas::create(options.shadowMapPx, options.maxShadowMaps);
  if (!atlas) return std::unexpected(atlas.error());
  auto toneMap = ToneMapPass::create(options.widthPx, options.heightPx);
  if (!toneMap) return std::unexpected(toneMap.error());
  GLint fragmentUnits = 0;
  glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &fragmentUnits);
  if (fragmentUnits < kFragmentUnitsNeeded) {
    return std::unexpected("the lighting shader reads " + std::to_string(kFragmentUnitsNeeded) +
                           " textures, and this OpenGL driver offers " +
                           std::to_string(fragmentUnits) + " (GL_MAX_TEXTURE_IMAGE_UNITS)");
  }
  auto target = makeLightingTarget(options.widthPx, options.heightPx);
  if (!target) return std::unexpected(target.error());
  const render::LightingGeometry ownGeometry =
      options.geometry == nullptr ? render::makeLightingGeometry() : render::LightingGeometry{};
  const render::LightingGeometry& geometry =
      options.geometry == nullptr ? ownGeometry : *options.geometry;

  auto impl = std::unique_ptr<Impl>(new Impl{options,
                                             options.shadowCasterBounds.value_or(
                                                 scene::shadowCasterBounds(scene)),
                                             scene.materials,
                                             {},
                                             std::move(*lighting),
                                             std::move(*background),
                                             std::move(*depth),
                                             LightTextures(geometry),
                                             std::move(*atlas),
                                             EnvironmentCube(),
                                             EnvironmentLightingTextures(),
                                             std::move(*toneMap),
                                             std::move(*target),
                                             GlVertexArray::create(),
                                             std::nullopt,
                                             TextureBuffer(GL_RGBA32F),
                                             TextureBuffer(GL_RGBA32F),
                                             0,
                                             std::nullopt,
                                             MirrorOcclusion{}});
  if (options.presentToWindow) {
    auto overlay = OverlayPass::create();
    if (!overlay) return std::unexpected(overlay.error());
    impl->overlay.emplace(std::move(*overlay));
  }
  impl->meshes.reserve(scene.meshes.size());
  for (const scene::Mesh& mesh : scene.meshes) impl->meshes.emplace_back(mesh);
  auto mirrors = MirrorOcclusion::create(scene, impl->meshes);
  if (!mirrors) return std::unexpected(mirrors.error());
  impl->mirrors = std::move(*mirrors);
  if (impl->atlas.capacity() < options.maxShadowMaps) {
    spdlog::warn("shadow atlas holds {} maps of {} px (GL_MAX_TEXTURE_SIZE), not {}",
                 impl->atlas.capacity(), impl->atlas.tilePx(), options.maxShadowMaps);
  }
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    return std::unexpected("OpenGL error " + std::to_string(error) +
                           " while creating the renderer");
  }
  return std::unique_ptr<GlRenderer>(new GlRenderer(std::move(impl)));
}

GlRenderer::GlRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GlRenderer::~GlRenderer() = default;

std::size_t GlRenderer::Impl::shadowPass(const render::ShadingLights& frame, GlFrameStats& stats) {
  const std::size_t count = std::min(frame.shadowDirs.size(), atlas.capacity());
  if (count == 0) {
    shadowKey.reset();
    return 0;
  }
  if (shadowKey == frame.lightsKey && shadowCount == count) {
    stats.shadowMapsReused = count;
    return count;
  }
  const std::vector<glm::vec3> dirs(frame.shadowDirs.begin(),
                                    frame.shadowDirs.begin() + std::ptrdiff_t(count));
  atlas.render(dirs, bounds, depth, meshes);
  std::vector<float> texels;
  texels.reserve(4 * dirs.size());
  for (const glm::vec3& d : dirs) {
    texels.insert(texels.end(), {d.x, d.y, d.z, 0.0F});
  }
  casterDirs.upload(texels);
  shadowKey = frame.lightsKey;
  shadowCount = count;
  stats.shadowMapsRendered = count;
  return count;
}

void GlRenderer::Impl::backgroundPass(const scene::ViewCamera& camera) const {
  const float aspect = float(options.widthPx) / float(options.heightPx);
  const glm::mat4 clipFromWorld = camera.clipFromView(aspect) * camera.viewFromWorld;
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  background.use();
  environment.bind(kEnvironmentUnit);
  background.set("uEnvironment", int(kEnvironmentUnit));
  background.set("uWorldFromClip", glm::inverse(clipFromWorld));
  background.set("uEye", camera.eyeWorld);
  background.set("uViewportPx", glm::vec2(float(options.widthPx), float(options.heightPx)));
  background.set("uHemisphere", options.environmentCoverage == MapLayout::Hemisphere ? 1 : 0);
  glBindVertexArray(emptyVertexArray.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthMask(GL_TRUE);
}

void GlRenderer::Impl::setMaterial(const scene::Material& material, bool glossyPass) const {
  const bool glossy = material.glossy();
  const bool mirror = material.mirrorLike();
  lighting.set("uDiffuseAlbedo", material.diffuseAlbedo);
  lighting.set("uLobe", int(material.lobe));
  lighting.set("uSpecularAlbedo", material.specularAlbedo);
  lighting.set("uExponent", material.exponent);
  lighting.set("uRoughness", material.roughness);
  lighting.set("uSpecularFromDiffuse", glossy && !mirror && !glossyPass ? 1 : 0);
  lighting.set("uGlossyPass", glossy && !mirror && glossyPass ? 1 : 0);
  lighting.set("uMirror", mirror ? 1 : 0);
}

void GlRenderer::Impl::geometryPass(const scene::ViewCamera& camera,
                                    const render::ShadingLights& frame, std::size_t shadowMaps,
                                    const RatioShading& ratio) const {
  const float aspect = float(options.widthPx) / float(options.heightPx);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  lighting.use();
  lighting.set("uClipFromWorld", camera.clipFromView(aspect) * camera.viewFromWorld);
  lighting.set("uEye", camera.eyeWorld);
  lights.bind(lighting);
  atlas.bind(kShadowUnit);
  lighting.set("uShadowAtlas", int(kShadowUnit));
  lighting.set("uShadowGrid", atlas.grid());
  lighting.set("uShadowCapacity", int(shadowMaps));
  lighting.set("uShadowMapPx", float(atlas.tilePx()));
  lighting.set("uShadowAtlasPx", float(atlas.atlasPx()));
  casterDirs.bind(kCasterUnit);
  lighting.set("uShadowCasterDirs", int(kCasterUnit));
  drawWeights.bind(kDrawWeightUnit);
  lighting.set("uShadowDrawWeights", int(kDrawWeightUnit));
  lighting.set("uShadowDraws", frame.shadowDrawsOfDiffuse.empty() ? 0 : 1);
  lighting.set("uSceneCentre", bounds.centre());
  lighting.set("uShadowRadius", shadowFrameRadius(bounds));
  environment.bind(kEnvironmentUnit);
  lighting.set("uEnvironment", int(kEnvironmentUnit));
  lighting.set("uHasEnvironment", environment.present() ? 1 : 0);
  const bool byRatio = ratio.lighting != nullptr;
  lighting.set("uRatio", byRatio ? 1 : 0);
  // Every sampler on its own unit, even unread: two sampler types on one unit fail the draw.
  lighting.set("uIrradiance", int(kIrradianceUnit));
  lighting.set("uPrefiltered", int(kPrefilteredUnit));
  lighting.set("uMinEffectiveLights", float(ratio.minEffectiveLights));
  lighting.set("uMirrorDistance", int(kMirrorUnit));
  if (byRatio) glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  const bool glossyPass = frame.glossy.has_value() && !byRatio;
  for (std::size_t meshIndex = 0; meshIndex < meshes.size(); ++meshIndex) {
    const GlMesh& mesh = meshes[meshIndex];
    setMaterial(materials.at(mesh.material()), glossyPass);
    mirrors.bindMesh(lighting, meshIndex, kMirrorUnit);
    if (byRatio) {
      environmentLighting.bindMaterial(lighting, mesh.material(), kIrradianceUnit,
                                       kPrefilteredUnit);
    }
    mesh.draw();
  }
  glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
}

GlFrameStats GlRenderer::render(const scene::ViewCamera& camera,
                                const render::ShadingLights& lights, const CubeMap* background,
                                std::uint64_t backgroundVersion, const RatioShading& ratio) {
  Impl& s = *impl_;
  GlFrameStats stats;
  const auto start = std::chrono::steady_clock::now();
  const std::size_t shadowMaps = s.shadowPass(lights, stats);
  glFinish();
  stats.shadowPassMs = msSince(start);

  const auto lightingStart = std::chrono::steady_clock::now();
  std::vector<float> peakFractions;
  if (ratio.lighting != nullptr && background != nullptr) {
    peakFractions = render::peakFractionsOf(*ratio.lighting, *background, lights.diffuse.lights);
  }
  s.lights.upload(lights, peakFractions);
  s.drawWeights.upload(std::span<const float>(drawWeightTexels(lights)));
  stats.backgroundUploaded = s.environment.update(background, backgroundVersion);
  s.environmentLighting.update(ratio.lighting, ratio.version);
  glBindFramebuffer(GL_FRAMEBUFFER, s.target.framebuffer.id());
  glViewport(0, 0, s.options.widthPx, s.options.heightPx);
  glClearColor(0.0F, 0.0F, 0.0F, 0.0F);
  glClearDepth(1.0);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (s.environment.present()) s.backgroundPass(camera);
  s.geometryPass(camera, lights, shadowMaps, ratio);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glFinish();
  stats.lightingPassMs = msSince(lightingStart);
  stats.totalMs = msSince(start);
  return stats;
}

render::LinearImage GlRenderer::readLinear() const {
  const int w = impl_->options.widthPx;
  const int h = impl_->options.heightPx;
  std::vector<float> rgba(std::size_t(w) * std::size_t(h) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, impl_->target.framebuffer.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  render::LinearImage image = render::LinearImage::black(w, h);
  for (int y = 0; y < h; ++y) {
    const std::size_t glRow = std::size_t(h - 1 - y);
    for (int x = 0; x < w; ++x) {
      const float* p = &rgba[(glRow * std::size_t(w) + std::size_t(x)) * 4];
      image.set(x, y, glm::vec3(p[0], p[1], p[2]), p[3] > 0.5F);
    }
  }
  return image;
}

void GlRenderer::presentToneMapped(const render::ToneParams& params) {
  impl_->toneMap.run(impl_->target.colour.id(), params, impl_->options.presentToWindow);
}

std::vector<std::uint8_t> GlRenderer::readDisplaySrgb8() const {
  return impl_->toneMap.readSrgb8(impl_->options.presentToWindow);
}

void GlRenderer::drawOverlay(std::string_view text) {
  if (!impl_->overlay) return;
  impl_->overlay->draw(0, {impl_->options.widthPx, impl_->options.heightPx}, text);
}

int GlRenderer::widthPx() const { return impl_->options.widthPx; }
int GlRenderer::heightPx() const { return impl_->options.heightPx; }
std::size_t GlRenderer::shadowMapCapacity() const { return impl_->atlas.capacity(); }
int GlRenderer::shadowAtlasPx() const { return impl_->atlas.atlasPx(); }

}  // namespace vem::gl
