// GlRenderer: vemview's OpenGL renderer (paper 004 section 5.2): per-pixel lighting of a scene
// from many directional lights into a float framebuffer, in two stages, shadow maps into one
// atlas (shadow_atlas.h, section 5.2.1), then one geometry pass with angular-region light lists
// (section 4.1), the glossy L/H sets (section 4.2) and the cube map for mirror-like materials and
// the background; a separate tone-mapping pass for display (tone_map_pass.h, section 5.1).
//
// Conventions: the scene's world frame (scene/scene.h); images widthPx x heightPx, row 0 at the
// top and pixel-aligned with the Embree renderer through scene::ViewCamera; radiance in the
// lights' units (core/light.h). Needs a current GlContext for its whole life.
//
// What a frame computes follows its ShadingLights: no shadowDirs, no shadow pass; the same
// lightsKey (and caster count) as the previous frame, the maps are reused; empty diffuseLists, every
// diffuse light is walked; no glossy sets, glossy materials take their specular lobe from the
// diffuse lights; mirror-like materials reflect the cube map (black without one), black where the
// scene blocks the reflected ray (mirror_occlusion.h: drawn once, at create()).
//
// With a RatioShading, shading by ratio instead (issue 20): the model and its sums are
// client/embree/light_renderer.h's, term for term, over the diffuse lights and with the shadow
// maps' visibility; the glossy L/H sets are not read. A soft light with draws
// (ShadingLights::shadowDrawsOfDiffuse, render/shadow_draws.h) sums its maps' draws instead of its
// one map. The environment's cubes (irradiance, the clipped environment or the split sum's
// prefiltered cubes) are read with GL_TEXTURE_CUBE_MAP_SEAMLESS (on for that pass only), as
// render::sampleCubeMapSeamless reads them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <expected>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "client/render/environment_lighting.h"
#include "client/render/linear_image.h"
#include "client/render/shading_lights.h"
#include "client/render/tone_mapping.h"
#include "client/scene/view_camera.h"
#include "client/scene/scene.h"
#include "core/cube_map.h"
#include "core/env_map.h"

namespace vem::gl {

struct GlRendererOptions {
  int widthPx = 320;
  int heightPx = 240;
  int shadowMapPx = 256;                              // one tile's side
  std::size_t maxShadowMaps = render::kMaxShadowMaps;  // atlas slots (grid = ceil(sqrt))
  bool presentToWindow = false;  // presentToneMapped also blits into framebuffer 0
  // What the cube maps cover: a Hemisphere one (made from vemd's polar map) holds nothing below
  // the horizon, and the background shows black there (render::sampleBackground).
  MapLayout environmentCoverage = MapLayout::Sphere;
  // The region tables the ShadingLights were built on (borrowed during create() only);
  // nullptr: render::makeLightingGeometry(), the defaults buildShadingLights callers use.
  const render::LightingGeometry* geometry = nullptr;
  // What the shadow maps look at; nothing: the scene's shadow casters (scene::shadowCasterBounds).
  // A composite's layers fit them to the synthetic objects alone: the plate holds the real
  // shadows, and the maps' texels go where the objects' shadows are.
  std::optional<scene::Bounds> shadowCasterBounds;
};

// Shading by ratio: the unshadowed light from `lighting` (built for this renderer's scene's
// materials from the frame's cube map, borrowed for the call), re-uploaded when (lighting,
// version) differs from the last frame's. The peaks' shares are taken from the frame's cube map.
struct RatioShading {
  const render::EnvironmentLighting* lighting = nullptr;
  std::uint64_t version = 0;
  double minEffectiveLights = render::kMinEffectiveLights;
};

struct GlFrameStats {
  double shadowPassMs = 0.0;    // shadow maps, to glFinish
  double lightingPassMs = 0.0;  // light upload, background and geometry pass, to glFinish
  double totalMs = 0.0;
  std::size_t shadowMapsRendered = 0;
  std::size_t shadowMapsReused = 0;
  bool backgroundUploaded = false;
};

class GlRenderer {
 public:
  [[nodiscard]] static std::expected<std::unique_ptr<GlRenderer>, std::string> create(
      const scene::Scene& scene, const GlRendererOptions& options);
  ~GlRenderer();
  GlRenderer(const GlRenderer&) = delete;
  GlRenderer& operator=(const GlRenderer&) = delete;

  // One frame into the float buffer. background: the cube map to show and reflect (nullptr:
  // black), re-uploaded only when (background, backgroundVersion) differs from the last frame's.
  // ratio: shading by ratio when ratio.lighting is set (above).
  GlFrameStats render(const scene::ViewCamera& camera, const render::ShadingLights& lights,
                      const CubeMap* background, std::uint64_t backgroundVersion = 0,
                      const RatioShading& ratio = {});
  // The last frame: linear radiance, covered = 1 where geometry was drawn.
  [[nodiscard]] render::LinearImage readLinear() const;
  // Tone-maps the last frame (render::toneMap + sRGB) into the display image (and the window).
  void presentToneMapped(const render::ToneParams& params);
  // The display image as RGB bytes, row 0 at the top (from the window's back buffer when
  // presentToWindow, so read it before swapBuffers, and before drawOverlay to leave the text out).
  [[nodiscard]] std::vector<std::uint8_t> readDisplaySrgb8() const;
  // Windows only (presentToWindow; a no-op headless): blends `text` (lines separated by '\n') over
  // the window's back buffer, top left (overlay_pass.h), after presentToneMapped. Never part of
  // readLinear(); part of readDisplaySrgb8() only when read after this call.
  void drawOverlay(std::string_view text);

  [[nodiscard]] int widthPx() const;
  [[nodiscard]] int heightPx() const;
  [[nodiscard]] std::size_t shadowMapCapacity() const;  // atlas slots actually available
  [[nodiscard]] int shadowAtlasPx() const;

 private:
  struct Impl;
  explicit GlRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace vem::gl
