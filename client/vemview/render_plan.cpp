#include "client/vemview/render_plan.h"

#include <algorithm>

#include <fmt/format.h>

namespace vem::view {

RenderPlan planFor(const scene::Scene& scene, const PlanRequest& request) {
  RenderPlan plan;
  plan.glossyPass = scene::anyGlossy(scene);
  plan.glossyReason = plan.glossyPass ? "a material is glossy" : "no glossy material";
  const bool mirror = scene::anyMirrorLike(scene);
  plan.shadingByRatio = request.shadingByRatio && request.inputHasCubeMaps;
  if (plan.shadingByRatio) {
    plan.irradianceCube = std::ranges::any_of(scene.meshes, [&](const scene::Mesh& mesh) {
      const glm::vec3 kd = scene.materials.at(mesh.material).diffuseAlbedo;
      return mesh.triangleCount() > 0 && std::max({kd.x, kd.y, kd.z}) > 0.0F;
    });
    plan.glossyEnvironment = std::ranges::any_of(scene.meshes, [&](const scene::Mesh& mesh) {
      const scene::Material& m = scene.materials.at(mesh.material);
      return mesh.triangleCount() > 0 && m.glossy() && !m.mirrorLike();
    });
    plan.glossyPass = false;
    plan.glossyReason = "shading by ratio";
  }
  plan.ratioReason = !request.shadingByRatio ? "" : !request.inputHasCubeMaps
                                                   ? "the input carries no cube map"
                                                   : "";
  const bool wanted = plan.glossyPass || request.backgroundWanted || plan.shadingByRatio;
  plan.cubeMap = wanted && request.inputHasCubeMaps;
  plan.cubeMapReason = !request.inputHasCubeMaps && wanted ? "the input carries none"
                       : plan.shadingByRatio ? "shading by ratio"
                       : plan.glossyPass
                           ? (mirror ? "mirror-like reflections" : "glossy reflections")
                       : request.backgroundWanted ? "background asked for"
                                                  : "no glossy material";
  const bool canShadow = scene::canCastShadows(scene);
  plan.shadowMaps = canShadow && request.shadowedCount > 0;
  plan.shadowReason = !canShadow                   ? "nothing can shadow anything"
                      : request.shadowedCount == 0 ? "shadows turned off"
                                                   : "the scene can shadow itself";
  plan.lighting.lightCount = std::max<std::size_t>(request.lightCount, 1);
  plan.lighting.shadowedCount =
      plan.shadowMaps ? std::min<std::size_t>({request.shadowedCount, render::kMaxShadowMaps,
                                               plan.lighting.lightCount})
                      : 0;
  plan.lighting.regions = request.regions;
  plan.lighting.glossyPass = plan.glossyPass;
  plan.lighting.clusterBudget = request.inputClustered ? 0 : request.clusterBudget;
  plan.lighting.clusterLayout = request.inputLayout;
  plan.shadowMapPx = request.shadowMapPx;
  plan.cubeFacePx = request.cubeFacePx > 0 ? request.cubeFacePx : render::cubeFacePxFor(scene);
  plan.cubeMapCoverage = request.inputLayout;
  plan.targetFrameMs = request.targetFrameMs;
  plan.softShadows = request.softShadows && plan.shadingByRatio && plan.shadowMaps;
  plan.softShadowMaps =
      plan.softShadows ? std::min<std::size_t>(request.shadowedCount, render::kMaxShadowMaps) : 0;
  plan.softShadowReason = !request.softShadows || plan.softShadows ? ""
                          : !plan.shadingByRatio ? "they need shading by ratio"
                                                 : "no shadow maps";
  return plan;
}

RenderPlan withShadowMapCapacity(RenderPlan plan, std::size_t capacity) {
  if (plan.lighting.shadowedCount > capacity) {
    plan.shadowedAskedFor = plan.lighting.shadowedCount;
    plan.lighting.shadowedCount = capacity;
  }
  plan.softShadowMaps = std::min(plan.softShadowMaps, capacity);
  return plan;
}

std::string RenderPlan::describe() const {
  std::string text = fmt::format("lights {}", lighting.lightCount);
  if (targetFrameMs) {
    text += fmt::format(" (adaptive, target {:.1f} ms)", *targetFrameMs);
  }
  text += shadowMaps ? fmt::format(", shadow maps {} at {} px", lighting.shadowedCount, shadowMapPx)
                     : fmt::format(", no shadow maps ({})", shadowReason);
  if (shadowMaps && shadowedAskedFor > 0) {
    text += fmt::format(" ({} asked for; the atlas holds {})", shadowedAskedFor,
                        lighting.shadowedCount);
  }
  text += lighting.regions ? ", regions on" : ", regions off";
  text += glossyPass
              ? fmt::format(", glossy L/H pass (|H| {}; {})", lighting.highCount, glossyReason)
              : fmt::format(", no glossy pass ({})", glossyReason);
  text += cubeMap ? fmt::format(", cube map of {} px ({})", cubeFacePx, cubeMapReason)
                  : fmt::format(", no cube map ({})", cubeMapReason);
  if (shadingByRatio) {
    text += fmt::format(", shading by ratio ({}, {})",
                        irradianceCube ? "irradiance cube: a diffuse material"
                                       : "no irradiance cube: no diffuse material",
                        glossyEnvironment
                            ? "clipped environment for the glossy lobes: a glossy material"
                            : "no glossy environment: no glossy material");
  } else if (!ratioReason.empty()) {
    text += fmt::format(", shading by the lights ({})", ratioReason);
  }
  if (softShadows) {
    text += fmt::format(
        ", soft shadows (each light's stratum of the sky; OpenGL: up to {} maps, those beyond "
        "N drawn from the strata)",
        softShadowMaps);
  } else if (!softShadowReason.empty()) {
    text += fmt::format(", hard shadows (soft: {})", softShadowReason);
  }
  if (lighting.clusterBudget > 0) {
    text += fmt::format(", clustering Q {}", lighting.clusterBudget);
  }
  if (composite) {
    text += fmt::format(
        "; composite into {} seen by {}: {} ({}); local scene: the floor plane{}",
        composite->plate, composite->camera,
        composite->differential
            ? "differential (the objects' shadows on the real surfaces; the render without them "
              "is kept while the lights are unchanged)"
            : "objects drawn over the plate, no differential pass",
        composite->reason,
        composite->proxyMeshes > 0 ? fmt::format(" and {} proxy meshes", composite->proxyMeshes)
                                   : std::string());
    if (composite->objectBounds && shadowMaps) {
      text += fmt::format("; shadow maps over the objects ({:.2f} m across), not the local scene: "
                          "the plate holds the real shadows",
                          2.0F * composite->objectBounds->radius());
    }
  }
  return text;
}

CompositePlan compositePlanFor(const scene::Scene& objects, std::size_t proxyMeshes) {
  CompositePlan plan;
  plan.proxyMeshes = proxyMeshes;
  if (objects.meshes.empty()) {
    plan.reason = "nothing synthetic to shadow the local scene";
    return plan;
  }
  bool aboveFloor = false;
  for (const scene::Mesh& mesh : objects.meshes) {
    for (const glm::vec3& p : mesh.positions) aboveFloor = aboveFloor || p.y > 0.0F;
  }
  plan.differential = aboveFloor || proxyMeshes > 0;
  plan.reason = plan.differential ? "objects stand above the floor and can shadow it"
                                  : "every object lies below the floor: none can shadow it";
  return plan;
}

FrameDecision decideFrame(const std::optional<FrameState>& last, const FrameState& now) {
  if (!last) {
    return FrameDecision{true, true};
  }
  const bool lightsChanged = last->inputSeq != now.inputSeq || last->lightCount != now.lightCount;
  const bool cameraChanged = last->cameraVersion != now.cameraVersion;
  const bool plateChanged = last->plateVersion != now.plateVersion;
  return FrameDecision{lightsChanged || cameraChanged || plateChanged, lightsChanged};
}

}  // namespace vem::view
