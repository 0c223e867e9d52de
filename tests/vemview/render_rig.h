// RenderRig: one scene, camera and environment map rendered by both renderers with the same
// shading lights, for vemview's agreement, convergence and golden-image tests: the OpenGL
// renderer headless (EGL), the Embree renderer with the same lights, and the Monte Carlo
// reference over the whole map.
#pragma once

#include <memory>
#include <string>

#include "client/embree/embree_scene.h"
#include "client/embree/reference_renderer.h"
#include "client/gl/gl_context.h"
#include "client/gl/gl_renderer.h"
#include "client/render/linear_image.h"
#include "client/render/shading_lights.h"
#include "client/scene/orbit_camera.h"
#include "client/scene/scene.h"
#include "core/cube_map.h"
#include "core/env_map.h"
#include "core/light.h"

namespace vem::testing {

struct RigOptions {
  std::string sceneName = "diffuse";  // a built-in scene
  std::string mapName = "park";       // ../shared/data/hdri/NAME.exr
  int widthPx = 160;
  int heightPx = 120;
  int shadowMapPx = 512;
  std::size_t maxLights = 1024;
};

// The sphere standing on a plane ("spheres") under sky.exr's sun, 320 x 240, 256 px maps: the
// contact-shadow rig of issue 20 part 3.
[[nodiscard]] RigOptions sphereOnAPlaneUnderTheSun();

class RenderRig {
 public:
  explicit RenderRig(const RigOptions& options);
  [[nodiscard]] render::ShadingLights lights(std::size_t count, std::size_t shadowed,
                                             bool regions = true, int clusterBudget = 0) const;
  [[nodiscard]] render::LinearImage gl(const render::ShadingLights& lights);
  [[nodiscard]] render::LinearImage embree(const render::ShadingLights& lights) const;
  [[nodiscard]] embree::ReferenceResult reference(double targetError, int maxSamples) const;
  [[nodiscard]] const scene::Scene& scene() const { return scene_; }
  [[nodiscard]] gl::GlRenderer& glRenderer() { return *glRenderer_; }

 private:
  RigOptions options_;
  scene::Scene scene_;
  scene::OrbitCamera camera_;
  EnvMap map_;
  LightSet allLights_;
  CubeMap cube_;
  render::LightingGeometry geometry_;
  std::unique_ptr<embree::EmbreeScene> embree_;
  std::unique_ptr<gl::GlContext> context_;
  std::unique_ptr<gl::GlRenderer> glRenderer_;
};

}  // namespace vem::testing
