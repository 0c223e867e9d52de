// LightTextures: one frame's render::ShadingLights as the lighting shader reads them (paper 004
// section 5.2, "TexL"): per light set (diffuse, glossy L, glossy H) an RGBA32F buffer texture of
// two texels per light, (dir.xyz, shadow slot) and (rgb, peak fraction), plus its angular-region
// lists as a flat R32UI index buffer and an R32UI offsets buffer (core/angular_regions.h's
// RegionLightLists), and the fixed region tables as R32UI cube maps (GL face order, nearest filtering) holding
// AngularRegions::regionOfTexel. An H light takes the shadow slot of the L light it comes from.
//
// Texture units: kFirstLightUnit .. kFirstLightUnit + 11 (shaders/lighting.frag.glsl's samplers).
#pragma once

#include <span>

#include "client/gl/gl_handle.h"
#include "client/gl/gl_program.h"
#include "client/gl/texture_buffer.h"
#include "client/render/shading_lights.h"

namespace vem::gl {

inline constexpr GLenum kFirstLightUnit = 0;
inline constexpr GLenum kLightUnitCount = 12;

class LightTextures {
 public:
  explicit LightTextures(const render::LightingGeometry& geometry);
  // Uploads the frame's lights; aborts when the lists do not belong to this geometry (a bug).
  // peakFractions: per diffuse light, its share of the peaks that shading by ratio takes light
  // by light (render::peakFractionsOf; empty: 0).
  void upload(const render::ShadingLights& lights, std::span<const float> peakFractions = {});
  // Binds the textures and sets the sampler and count uniforms of `program` (in use).
  void bind(const GlProgram& program) const;
  [[nodiscard]] bool glossyUploaded() const { return glossy_; }

 private:
  struct LightSetTextures {
    TextureBuffer lights{GL_RGBA32F};
    TextureBuffer list{GL_R32UI};
    TextureBuffer offsets{GL_R32UI};
    GlTexture regions;
    std::size_t regionCount = 0;
  };
  void bindSet(const GlProgram& program, const LightSetTextures& set, GLenum firstUnit,
               const char* prefix) const;

  LightSetTextures diffuse_;
  LightSetTextures low_;
  LightSetTextures high_;
  float cosCone_ = 1.0F;
  int diffuseCount_ = 0;
  bool diffuseRegions_ = false;
  bool glossy_ = false;
  int maxConeLights_ = 1;
};

}  // namespace vem::gl
