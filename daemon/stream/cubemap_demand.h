// CubemapDemand: the environment frames the connected clients want, summed up for the processing
// thread: each distinct CubeVariant (face size, levels, preview) some client subscribed to, with
// the highest rate any of them asked for. Empty: nobody wants cube maps, none are built.
// Pure value type, header only.
#pragma once

#include <algorithm>
#include <span>
#include <vector>

#include "stream/subscription.h"

namespace vem::stream {

struct VariantDemand {
  CubeVariant variant;
  double rateHz = 0.0;
  friend bool operator==(const VariantDemand&, const VariantDemand&) = default;
};

struct CubemapDemand {
  std::vector<VariantDemand> variants;  // sorted by variant, each once
  [[nodiscard]] bool any() const { return !variants.empty(); }
  friend bool operator==(const CubemapDemand&, const CubemapDemand&) = default;
};

[[nodiscard]] inline CubemapDemand cubemapDemand(std::span<const Subscription> subscriptions) {
  CubemapDemand demand;
  for (const Subscription& s : subscriptions) {
    if (!s.wantsCubemaps()) continue;
    auto it = std::ranges::find(demand.variants, s.cube, &VariantDemand::variant);
    if (it == demand.variants.end()) {
      demand.variants.push_back({s.cube, s.cubemapRateHz});
    } else {
      it->rateHz = std::max(it->rateHz, s.cubemapRateHz);
    }
  }
  std::ranges::sort(demand.variants, {}, &VariantDemand::variant);
  return demand;
}

}  // namespace vem::stream
