#include "core/light_generator.h"

#include <vector>

#include "core/havran_sampler.h"
#include "core/standard_sampler.h"
#include "core/surface_parameterization.h"
#include "util/contract.h"

namespace vem {

const char* samplerName(SamplerKind kind) {
  return kind == SamplerKind::Havran ? "havran" : "standard";
}

LightCells lightCellsFor(MapLayout layout, std::span<const glm::dvec2> pattern, SamplerKind kind) {
  std::vector<glm::dvec2> warp(pattern.begin(), pattern.end());
  if (kind == SamplerKind::Havran) {
    for (glm::dvec2& p : warp) {
      const CylinderPoint c = cylinderFromSquare(layout, p);
      p = {c.s, c.w};
    }
  }
  return buildLightCells(warp);
}

LightSet generateLights(const SamplingTables& t, std::span<const glm::dvec2> pattern,
                        SamplerKind kind, const LightCells& cells) {
  VEM_EXPECTS(cells.count == pattern.size());
  LightSet set;
  set.luminanceSr = t.luminanceSr;
  set.black = t.black;
  // Each light: its share of the luminance, luminanceSr / N, in its cell's colour (light_cells.h).
  std::vector<glm::dvec3> radiance;
  if (!t.black) {
    std::vector<double> edgeRows(cells.aEdges.size());
    if (kind == SamplerKind::Havran) {
      havranRowCoords(t, cells.aEdges, edgeRows);
    } else {
      standardRowCoords(t, cells.aEdges, edgeRows);
    }
    std::vector<glm::dvec2> rows(cells.cells.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
      rows[k] = {edgeRows[cells.cells[k].a0Edge], edgeRows[cells.cells[k].a1Edge]};
    }
    radiance = cellRadianceSr(
        t, cells, rows, kind == SamplerKind::Havran ? RowWeighting::Tent : RowWeighting::Box);
  }
  // Scaled from the floor-included importance to the map's luminance: sum of luminances = luminanceSr.
  const double scale = t.black ? 0.0 : t.luminanceSr / t.totalMass;
  // In the cells' k-d order, not the pattern's: consecutive points then lie side by side in the
  // warp domain and invert the same rows of the tables while they are in the cache.
  set.lights.resize(pattern.size());
  for (const LightCell& cell : cells.cells) {
    const std::size_t i = cell.light;
    const MapSample s =
        kind == SamplerKind::Havran ? havranSample(t, pattern[i]) : standardSample(t, pattern[i]);
    const glm::dvec3 rgb = t.black ? glm::dvec3(0.0) : scale * radiance[i];
    set.lights[i] = {std::uint32_t(i), glm::vec3(s.dir), glm::vec3(rgb)};
  }
  return set;
}

LightSet generateLights(const SamplingTables& t, std::span<const glm::dvec2> pattern,
                        SamplerKind kind) {
  return generateLights(t, pattern, kind, lightCellsFor(t.layout, pattern, kind));
}

}  // namespace vem
