#include "stream/publisher_fan_out.h"

#include <algorithm>
#include <utility>

#include "util/contract.h"

namespace vem::stream {

namespace {
constexpr int kTagShift = 56;
constexpr std::uint64_t kConnectionMask = (std::uint64_t{1} << kTagShift) - 1;
}  // namespace

PublisherFanOut::PublisherFanOut(std::vector<Publisher*> publishers)
    : publishers_(std::move(publishers)) {
  VEM_EXPECTS(publishers_.size() <= 255);
  VEM_EXPECTS(std::ranges::none_of(publishers_, [](Publisher* p) { return p == nullptr; }));
}

void PublisherFanOut::publishLights(SharedBytes message) {
  for (Publisher* p : publishers_) p->publishLights(message);
}

void PublisherFanOut::publishEnvironment(const CubeVariant& variant, SharedBytes message) {
  for (Publisher* p : publishers_) p->publishEnvironment(variant, message);
}

void PublisherFanOut::publishStatus(const Status& status) {
  for (Publisher* p : publishers_) p->publishStatus(status);
}

CubemapDemand PublisherFanOut::cubemapDemand() const {
  CubemapDemand merged;
  for (const Publisher* p : publishers_) {
    for (const VariantDemand& wanted : p->cubemapDemand().variants) {
      auto it = std::ranges::find(merged.variants, wanted.variant, &VariantDemand::variant);
      if (it == merged.variants.end()) {
        merged.variants.push_back(wanted);
      } else {
        it->rateHz = std::max(it->rateHz, wanted.rateHz);
      }
    }
  }
  std::ranges::sort(merged.variants, {}, &VariantDemand::variant);
  return merged;
}

std::vector<PendingControl> PublisherFanOut::takeControls() {
  std::vector<PendingControl> all;
  for (std::size_t i = 0; i < publishers_.size(); ++i) {
    for (PendingControl& pending : publishers_[i]->takeControls()) {
      VEM_EXPECTS(pending.connection <= kConnectionMask);
      pending.connection |= std::uint64_t(i) << kTagShift;
      all.push_back(std::move(pending));
    }
  }
  return all;
}

void PublisherFanOut::reply(std::uint64_t connection, const ControlReply& reply) {
  const std::size_t index = connection >> kTagShift;
  VEM_EXPECTS(index < publishers_.size());
  publishers_[index]->reply(connection & kConnectionMask, reply);
}

std::string PublisherFanOut::note() const {
  std::string joined;
  for (const Publisher* p : publishers_) {
    const std::string one = p->note();
    if (one.empty()) continue;
    if (!joined.empty()) joined += "; ";
    joined += one;
  }
  return joined;
}

}  // namespace vem::stream
