#include "core/light_generator.h"

#include "core/color.h"
#include "core/havran_sampler.h"
#include "core/standard_sampler.h"

namespace vem {
namespace {

// The colour per unit luminance at a sample; grey where the map is black there.
glm::dvec3 chromaAt(const EnvMap& map, const SamplingTables& t, const MapSample& s,
                    SamplerKind kind) {
  BlendedPixel p;
  if (kind == SamplerKind::Havran) {
    p = blendedPixelAt(map, t, s.r, s.xc);
  } else {
    const int x = std::min(int(s.xc), t.width - 1);
    const int y = std::min(int(s.r), t.height - 1);
    p.rgb = sanitizedRgb(map, x, y) + glm::dvec3(t.floorY);
    p.luminance = luminance(p.rgb);
  }
  return p.luminance > 0 ? p.rgb / p.luminance : glm::dvec3(1.0);
}

}  // namespace

const char* samplerName(SamplerKind kind) {
  return kind == SamplerKind::Havran ? "havran" : "standard";
}

LightSet generateLights(const EnvMap& map, const SamplingTables& t,
                        std::span<const glm::dvec2> pattern, SamplerKind kind) {
  LightSet set;
  set.luminanceSr = t.luminanceSr;
  set.black = t.black;
  set.lights.reserve(pattern.size());
  const double share = t.black ? 0.0 : t.luminanceSr / double(pattern.size());
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    const MapSample s =
        kind == SamplerKind::Havran ? havranSample(t, pattern[i]) : standardSample(t, pattern[i]);
    const glm::dvec3 rgb = share * chromaAt(map, t, s, kind);
    set.lights.push_back({std::uint32_t(i), glm::vec3(s.dir), glm::vec3(rgb)});
  }
  return set;
}

}  // namespace vem
