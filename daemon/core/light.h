// Light and LightSet: the directional lights the core produces from an environment map.
//
// - `dir` is the unit vector from the scene toward the light, in the world frame of env_map.h
//   (right-handed, +Y up).
// - `rgb` is the light's irradiance contribution: radiance times solid angle (map units x sr), so
//   a Lambertian surface with normal n receives E = sum_i rgb_i max(0, n . dir_i).
// - `id` is the index of the sampling-pattern point the light came from: its identity across
// frames.
//   A set from the sampler lists lights in id order, so its first k lights are exactly the k-light
//   set (the progressive property, paper 004 section 3.2).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace vem {

struct Light {
  std::uint32_t id = 0;
  glm::vec3 dir{0.0F, 1.0F, 0.0F};
  glm::vec3 rgb{0.0F};
};

struct LightSet {
  std::vector<Light> lights;
  // Integral of the map's luminance over solid angle (map units x sr): the frame's total power that
  // the temporal filter smooths. The lights' luminances sum to it (each carries an equal share).
  double luminanceSr = 0.0;
  // True when the map had no light at all: the lights then keep well-defined directions (the
  // pattern through a uniform distribution) and carry rgb exactly 0.
  bool black = false;
};

}  // namespace vem
