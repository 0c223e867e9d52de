#include "client/gl/environment_lighting_textures.h"

#include <span>

namespace vem::gl {

void EnvironmentLightingTextures::update(const render::EnvironmentLighting* lighting,
                                         std::uint64_t version) {
  if (lighting == nullptr) {
    lighting_ = nullptr;
    version_.reset();
    return;
  }
  if (lighting == lighting_ && version_ == version) return;
  lighting_ = lighting;
  version_ = version;
  irradiance_.update(lighting->irradiance.levels.empty() ? nullptr : &lighting->irradiance,
                     version);
  const bool filtered = lighting->specularModel == render::SpecularModel::FilteredSampling;
  clipped_.update(filtered && !lighting->clipped.levels.empty() ? &lighting->clipped : nullptr,
                  version);
  specular_.resize(lighting->specular.size());
  for (std::size_t m = 0; m < lighting->specular.size(); ++m) {
    if (!lighting->specular[m] || filtered) {
      specular_[m].reset();
      continue;
    }
    if (!specular_[m]) specular_[m].emplace();
    specular_[m]->update(&lighting->specular[m]->prefiltered, version);
  }
}

void EnvironmentLightingTextures::bindMaterial(const GlProgram& program, std::size_t materialIndex,
                                               GLenum irradianceUnit, GLenum specularUnit) const {
  irradiance_.bind(irradianceUnit);
  program.set("uIrradiance", int(irradianceUnit));
  program.set("uHasIrradiance", irradiance_.present() ? 1 : 0);
  const bool filtered = lighting_ != nullptr &&
                        lighting_->specularModel == render::SpecularModel::FilteredSampling;
  const bool specular =
      lighting_ != nullptr && materialIndex < lighting_->specular.size() &&
      lighting_->specular[materialIndex].has_value() &&
      (filtered ? clipped_.present()
                : materialIndex < specular_.size() && specular_[materialIndex].has_value());
  program.set("uSpecularByRatio", specular ? 1 : 0);
  program.set("uPrefiltered", int(specularUnit));
  program.set("uFilteredSamples", specular && filtered ? render::kFilteredSamples : 0);
  if (!specular) {
    EnvironmentCube::unbind(specularUnit);
    return;
  }
  if (filtered) {
    clipped_.bind(specularUnit);
    program.set("uFilteredFacePx", float(lighting_->clipped.levels.front().facePx));
    program.set("uFilteredTopLevel", float(lighting_->clipped.levels.size() - 1));
    return;
  }
  specular_[materialIndex]->bind(specularUnit);
  const render::DirectionalAlbedo& albedo = lighting_->specular[materialIndex]->albedo;
  program.set("uAlbedoScale", std::span<const float>(albedo.scale));
  program.set("uAlbedoBias", std::span<const float>(albedo.bias));
  program.set("uSpecularLookupBlend", lighting_->specular[materialIndex]->lookupBlend);
}

}  // namespace vem::gl
