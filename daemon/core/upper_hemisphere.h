// The upper half of an equirectangular (Sphere) map as a polar (Hemisphere) map, the layout vemd's
// camera feeds: the same rows from the zenith to the horizon, the same columns. The two layouts
// count the azimuth from different origins (env_map.h: phi = psi - pi against phi = psi), so the
// result is the upper half turned by half a turn about +Y; for the samplers' and the studies'
// figures that changes nothing.
#pragma once

#include "core/env_map.h"

namespace vem {

// `sphere` must be a Sphere map of even height.
[[nodiscard]] EnvMap upperHemisphere(const EnvMap& sphere);

}  // namespace vem
