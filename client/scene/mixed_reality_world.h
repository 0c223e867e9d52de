// The simulated real world of a composite (issue 21), so mixed reality runs and is measured with
// no camera: a room corner of real surfaces, the synthetic objects to put into it, and the plate
// camera that films it.
//
// - Real surfaces ("the real world"): a tiled floor (y = 0, 0.5 m tiles of two albedos, a
//   12 x 12 m square: a texture the albedo estimate must follow), a box (0.5 m, albedo
//   (0.55, 0.45, 0.35)) standing on it, and a wall behind (z = -1.6 m, 2.6 m high, albedo 0.5).
// - Proxies of them (the local scene a user gives with --local-scene): the same box and wall,
//   with the floor plane of local_scene.h; their materials do not matter (drawn white).
// - Synthetic objects: a Lambertian sphere (radius 0.3, albedo 0.7) and a GGX sphere (radius 0.2,
//   roughness 0.3, F0 0.9 / 0.7 / 0.35) standing on the floor in front of the box, where their
//   shadows fall on tiles and on the box.
// - The plate camera: 640 x 480, fx = fy = 560 px, principal point (325, 236) (OpenCV's pixel
//   centres), its eye at (0.25, 0.95, 2.1) m looking at (-0.05, 0.28, 0) with +Y up.
// World frame and units of scene/scene.h (metres, +Y up).
#pragma once

#include "client/scene/scene.h"
#include "client/scene/view_camera.h"

namespace vem::scene {

struct PlateIntrinsicsPx {
  int widthPx = 640;
  int heightPx = 480;
  double fxPx = 560.0;
  double fyPx = 560.0;
  double cxPx = 325.0;
  double cyPx = 236.0;
};

struct MixedRealityWorld {
  Scene realSurfaces;     // what the plate shows
  Scene proxies;          // the local scene as a user would model it: the box and the wall
  Scene objects;          // the synthetic objects
  Scene realWithObjects;  // the truth: realSurfaces and objects together
  PlateIntrinsicsPx intrinsics;
  glm::mat4 plateViewFromWorld{1.0F};  // OpenGL's view frame
};

[[nodiscard]] MixedRealityWorld mixedRealityWorld();

// The plate camera of `world` as the renderers take it (near 0.05 m, far 60 m).
[[nodiscard]] ViewCamera plateViewCamera(const MixedRealityWorld& world);

}  // namespace vem::scene
