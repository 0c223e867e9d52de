#include "client/gl/light_textures.h"

#include <cmath>
#include <string>
#include <vector>

#include "core/cube_map_lookup.h"
#include "util/contract.h"

namespace vem::gl {
namespace {

GlTexture regionCube(const AngularRegions& regions) {
  GlTexture texture = GlTexture::create();
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture.id());
  const int f = regions.faceSize;
  VEM_EXPECTS(regions.regionOfTexel.size() == cubeTexelCount(f));  // 6 F^2 regions
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (int face = 0; face < kCubeFaceCount; ++face) {
    const std::uint32_t* texels = regions.regionOfTexel.data() + std::size_t(face * f * f);
    glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_R32UI, f, f, 0,
                 GL_RED_INTEGER, GL_UNSIGNED_INT, texels);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

// Two texels a light: (dir, slot), (rgb, peak fraction); slot -1 when `slots` is empty, peak 0
// when `peaks` is.
std::vector<float> packLights(const LightSet& set, const std::vector<std::int32_t>& slots,
                              std::span<const float> peaks = {}) {
  std::vector<float> out;
  out.reserve(set.lights.size() * 8);
  for (std::size_t i = 0; i < set.lights.size(); ++i) {
    const Light& light = set.lights[i];
    const float slot = i < slots.size() ? float(slots[i]) : -1.0F;
    const float peak = i < peaks.size() ? peaks[i] : 0.0F;
    out.insert(out.end(), {light.dir.x, light.dir.y, light.dir.z, slot, light.rgb.x, light.rgb.y,
                           light.rgb.z, peak});
  }
  return out;
}

void uploadLists(TextureBuffer& list, TextureBuffer& offsets, const RegionLightLists& lists) {
  list.upload(std::span<const std::uint32_t>(lists.lightIndices));
  offsets.upload(std::span<const std::uint32_t>(lists.offsets));
}

}  // namespace

LightTextures::LightTextures(const render::LightingGeometry& geometry) {
  for (LightSetTextures* set : {&diffuse_, &low_, &high_}) {
    set->lights.upload(std::span<const float>());
    set->list.upload(std::span<const std::uint32_t>());
    set->offsets.upload(std::span<const std::uint32_t>());
  }
  diffuse_.regions = regionCube(geometry.diffuseRegions);
  diffuse_.regionCount = geometry.diffuseRegions.count();
  low_.regions = regionCube(geometry.glossyRegions.low);
  low_.regionCount = geometry.glossyRegions.low.count();
  high_.regions = regionCube(geometry.glossyRegions.high);
  high_.regionCount = geometry.glossyRegions.high.count();
  cosCone_ = float(std::cos(geometry.glossyRegions.coneHalfAngleRad));
}

void LightTextures::upload(const render::ShadingLights& lights,
                           std::span<const float> peakFractions) {
  const std::size_t n = lights.diffuse.lights.size();
  // One shadow slot per diffuse light, or none; one peak fraction per diffuse light, or none.
  VEM_EXPECTS(lights.shadowSlotOfDiffuse.empty() || lights.shadowSlotOfDiffuse.size() == n);
  VEM_EXPECTS(peakFractions.empty() || peakFractions.size() == n);
  diffuse_.lights.upload(std::span<const float>(
      packLights(lights.diffuse, lights.shadowSlotOfDiffuse, peakFractions)));
  diffuseCount_ = int(n);
  diffuseRegions_ = !lights.diffuseLists.offsets.empty();
  if (diffuseRegions_) {
    // The lists were built on this renderer's diffuse regions.
    VEM_EXPECTS(lights.diffuseLists.offsets.size() == diffuse_.regionCount + 1);
    uploadLists(diffuse_.list, diffuse_.offsets, lights.diffuseLists);
  }
  glossy_ = lights.glossy.has_value();
  if (!glossy_) return;
  const GlossyLightSets& sets = *lights.glossy;
  // The lists were built on this renderer's glossy regions; H is a prefix of L; one shadow slot
  // per L light, or none.
  VEM_EXPECTS(sets.lowLists.offsets.size() == low_.regionCount + 1 &&
              sets.highLists.offsets.size() == high_.regionCount + 1);
  VEM_EXPECTS(sets.high.lights.size() <= sets.low.lights.size());
  VEM_EXPECTS(lights.shadowSlotOfLow.empty() ||
              lights.shadowSlotOfLow.size() == sets.low.lights.size());
  low_.lights.upload(std::span<const float>(packLights(sets.low, lights.shadowSlotOfLow)));
  high_.lights.upload(std::span<const float>(packLights(sets.high, lights.shadowSlotOfLow)));
  uploadLists(low_.list, low_.offsets, sets.lowLists);
  uploadLists(high_.list, high_.offsets, sets.highLists);
  maxConeLights_ = int(std::max<std::size_t>(1, std::min<std::size_t>(lights.maxConeLights,
                                                                       1U << 30U)));
}

void LightTextures::bindSet(const GlProgram& program, const LightSetTextures& set,
                            GLenum firstUnit, const char* prefix) const {
  const std::string p = std::string("u") + prefix;
  set.lights.bind(firstUnit);
  program.set((p + "Lights").c_str(), int(firstUnit));
  set.list.bind(firstUnit + 1);
  program.set((p + "List").c_str(), int(firstUnit + 1));
  set.offsets.bind(firstUnit + 2);
  program.set((p + "Offsets").c_str(), int(firstUnit + 2));
  glActiveTexture(GL_TEXTURE0 + firstUnit + 3);
  glBindTexture(GL_TEXTURE_CUBE_MAP, set.regions.id());
  program.set((p + "Regions").c_str(), int(firstUnit + 3));
}

void LightTextures::bind(const GlProgram& program) const {
  bindSet(program, diffuse_, kFirstLightUnit, "Diffuse");
  bindSet(program, low_, kFirstLightUnit + 4, "Low");
  bindSet(program, high_, kFirstLightUnit + 8, "High");
  program.set("uDiffuseCount", diffuseCount_);
  program.set("uDiffuseUseRegions", diffuseRegions_ ? 1 : 0);
  program.set("uCosCone", cosCone_);
  program.set("uMaxConeLights", maxConeLights_);
}

}  // namespace vem::gl
