// RenderPlan: what vemview computes for a scene and an input, decided once at start and printed
// (the user's rule "simulate only the effects a scene calls for"), and the per-frame decisions that
// skip work that did not change.
//
// Once per run (planFor):
// - glossyPass: the L/H light sets and their regions (paper 004 section 4.2) only when some
//   material is glossy; otherwise every surface is shaded from the diffuse lights alone.
// - cubeMap: the environment cube map (subscribed from the stream, or made from the map file) only
//   when some material is glossy (reflections) or the user asked for it as the background; 512 px
//   a face with a mirror-like material, else 128 (--cube-face-px overrides).
// - shadowMaps: shadowedCount > 0 only when some surface can hide a light from another
//   (scene::canCastShadows); the atlas is not even allocated otherwise. Once the renderer exists,
//   shadowedCount is cut to what its atlas holds (withShadowMapCapacity).
// - shadingByRatio (--shading ratio, with a cube map in the input): the irradiance cube only with a
//   diffuse material, the clipped environment for the glossy lobes only with a glossy one, and no
//   L/H sets.
// - softShadows (--soft-shadows, by ratio, with shadow maps): each light that stands for a wide
//   part of the sky casts that part's soft shadow (render/soft_shadows.h). Embree draws a
//   direction per pixel; OpenGL spends the maps beyond N, up to S as asked (softShadowMaps), on
//   directions drawn per frame (render/shadow_draws.h), so with S <= N it changes nothing there.
// Per frame (decideFrame):
// - lights unchanged since the last drawn frame (same input seq): shadow maps are reused;
// - lights, camera and scene all unchanged: nothing is redrawn (the last image stands).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "client/render/cube_resolution.h"
#include "client/render/shading_lights.h"
#include "client/scene/scene.h"

namespace vem::view {

struct PlanRequest {
  std::size_t lightCount = 256;    // N asked for
  std::size_t shadowedCount = 64;  // S asked for
  int shadowMapPx = 256;
  int cubeFacePx = 0;  // the cube map's level 0 (--cube-face-px); 0: the plan's choice
  bool regions = true;
  int clusterBudget = 0;                // Q, 0: off
  bool backgroundWanted = false;        // --background
  std::optional<double> targetFrameMs;  // adaptive light count
  bool inputClustered = false;          // the input's lights are clusters already
  bool inputHasCubeMaps = true;         // a light file has none
  MapLayout inputLayout = MapLayout::Hemisphere;
  bool shadingByRatio = false;  // --shading ratio
  bool softShadows = false;     // --soft-shadows
};

// Mixed reality (--plate; composite_frame_renderer.h): whether the objects get the differential
// pass (their shadows on the local scene, Debevec 1998) or are only drawn over the plate, and why;
// what the plate and its camera are, for the plan line.
struct CompositePlan {
  bool differential = false;
  std::string reason;
  std::string plate;   // the plate source's description
  std::string camera;  // the plate camera's
  std::size_t proxyMeshes = 0;
  // OpenGL's shadow maps look at the objects alone (in the light probe's world): the plate holds
  // the real shadows, and the differential pass needs only the objects'.
  std::optional<scene::Bounds> objectBounds;
};

// The differential pass runs when something synthetic can shadow the local scene: an object with
// a vertex above the floor plane (y > 0 in the plate's world), or proxies it may shadow; none when
// the scene has no objects.
[[nodiscard]] CompositePlan compositePlanFor(const scene::Scene& objects, std::size_t proxyMeshes);

struct RenderPlan {
  bool glossyPass = false;
  bool cubeMap = false;
  bool shadowMaps = false;
  render::LightingOptions lighting;  // N, S (0 without shadow maps), regions, glossy, Q
  int shadowMapPx = 256;
  // render::cubeFacePxFor(scene) (512 px with a mirror-like material, else 128), or as asked.
  int cubeFacePx = render::kCubeFacePx;
  std::optional<double> targetFrameMs;
  std::string glossyReason;  // why, in a few words
  std::string cubeMapReason;
  std::string shadowReason;
  std::size_t shadowedAskedFor = 0;  // S asked for, when the renderer holds fewer maps; else 0
  // What the input's cube maps cover (vemd's stream: the upper hemisphere); the renderers show no
  // background below a hemisphere's horizon.
  MapLayout cubeMapCoverage = MapLayout::Sphere;
  // Shading by ratio: the prefiltered environment (render/environment_lighting.h), built when the
  // cube map changes, only for what the materials use: the irradiance cube when a material has a
  // diffuse albedo, the clipped environment with its chain when a material is glossy and not
  // mirror-like (filtered importance sampling, render/environment_lighting.h). No L/H pass.
  bool shadingByRatio = false;
  bool irradianceCube = false;
  bool glossyEnvironment = false;
  std::string ratioReason;
  bool softShadows = false;
  std::size_t softShadowMaps = 0;  // OpenGL's maps with soft shadows: S as asked (0 without)
  std::string softShadowReason;    // why not, when asked for and off
  std::optional<CompositePlan> composite;  // --plate

  [[nodiscard]] std::string describe() const;  // one line for the start and the status line
};

[[nodiscard]] RenderPlan planFor(const scene::Scene& scene, const PlanRequest& request);

// The plan for a renderer that holds at most `capacity` shadow maps (the OpenGL atlas is bounded
// by GL_MAX_TEXTURE_SIZE): S becomes min(S, capacity), so the lights without a map of their own
// take their nearest caster's, and what is reported as shadowed is what is shadowed; the soft
// shadows' maps are cut likewise.
[[nodiscard]] RenderPlan withShadowMapCapacity(RenderPlan plan, std::size_t capacity);

struct FrameState {
  std::uint64_t inputSeq = 0;
  std::uint64_t cameraVersion = 0;
  std::size_t lightCount = 0;
  std::uint64_t plateVersion = 0;  // --plate: the picture composited into (a new one: redraw)
};

struct FrameDecision {
  bool redraw = true;
  bool lightsChanged = true;  // the shading lights must be rebuilt (and shadow maps redrawn)
};

// `last` is the state of the last drawn frame (empty before the first).
[[nodiscard]] FrameDecision decideFrame(const std::optional<FrameState>& last,
                                        const FrameState& now);

}  // namespace vem::view
