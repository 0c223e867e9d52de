#include "core/upper_hemisphere.h"

#include <cstddef>

#include "util/contract.h"

namespace vem {

EnvMap upperHemisphere(const EnvMap& sphere) {
  VEM_EXPECTS(sphere.layout == MapLayout::Sphere && sphere.height % 2 == 0);
  EnvMap out{MapLayout::Hemisphere, sphere.width, sphere.height / 2, {}};
  out.rgb.assign(sphere.rgb.begin(), sphere.rgb.begin() + std::ptrdiff_t(out.pixelCount() * 3));
  return out;
}

}  // namespace vem
