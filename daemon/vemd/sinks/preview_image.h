// The preview image: the polar environment map as an 8-bit picture with the lights marked on it,
// as in paper 004's figure 1 (the captured hemisphere with the chosen lights as green marks).
//
// - Geometry: the map as stored (env_map.h), scaled up by an integer factor with nearest
//   neighbour, so map pixel (x, y) covers image pixels [s x, s x + s) x [s y, s y + s). For the
//   Hemisphere layout (vemd's polar map) column x spans phi in 2 pi [x, x + 1) / W from the left
//   edge (phi = 0, +X) and row y spans theta in (pi / 2) [y, y + 1) / H from the zenith at the top
//   to the horizon at the bottom. A direction lands at (s xc, s yc), its continuous map
//   coordinates (mapCoordsOfDirection); marks crossing the phi = 0 seam wrap around.
// - Tone mapping: Reinhard's global operator (Reinhard et al. 2002, "Photographic tone
//   reproduction", eq. 1-3 without the white point): Lw = Rec. 709 luminance, the log-average
//   Lavg = exp(mean over pixels of ln(1e-6 + Lw)), L = 0.18 Lw / Lavg, Ld = L / (1 + L); each
//   channel is scaled by Ld / Lw, clamped to [0, 1] and sRGB-encoded. Every image is tone mapped
//   on its own (paper 004 smooths Lavg over time for display; a preview every N frames need not).
//   NaN, infinite and negative channels count as 0.
// - Marks: each light is a filled green disc (BGR 0,255,0) of radius s (1.5 + 3.5 sqrt(Y / Ymax))
//   pixels, Y the light's Rec. 709 luminance and Ymax the brightest light's, so a disc's area grows
//   with its power; each cluster is an orange ring (BGR 0,165,255) drawn under the lights, of the
//   clustering's radius in rows (Clustering::radiusRad / thetaMax H s pixels, at least s).
#pragma once

#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <opencv2/core/mat.hpp>

#include "core/env_map.h"
#include "core/light.h"
#include "core/light_clustering.h"

namespace vem::vemd {

inline const cv::Vec3b kPreviewLightBgr{0, 255, 0};
inline const cv::Vec3b kPreviewClusterBgr{0, 165, 255};

struct PreviewStyle {
  int scale = 2;  // image pixels per map pixel, >= 1
};

// The continuous map coordinates (xc in [0, W), yc in [0, H], yc > H below a hemisphere's horizon)
// of a unit direction: the inverse of the pixel-centre formulas of env_map.h.
[[nodiscard]] glm::dvec2 mapCoordsOfDirection(MapLayout layout, int width, int height,
                                              glm::dvec3 dir);

// The tone-mapped map, 8-bit BGR (OpenCV's order), (W s) x (H s), without marks.
[[nodiscard]] cv::Mat toneMappedMap(const EnvMap& map, int scale);

// The tone-mapped map with `lights` (and, when not null, `clustering`'s clusters) marked.
[[nodiscard]] cv::Mat previewImage(const EnvMap& map, const LightSet& lights,
                                   const Clustering* clustering, const PreviewStyle& style);

}  // namespace vem::vemd
