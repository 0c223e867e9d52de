// PublisherFanOut: one Publisher that hands everything to several (vemd with both the WebSocket
// server and the MQTT publisher). Cube-map demand is merged (each variant once, at the highest
// rate any of them asks); control requests are collected from all, their `connection` tagged with
// the publisher they came from (the top 8 bits), so that reply() goes back to it.
// Borrows the publishers; they outlive it.
#pragma once

#include <vector>

#include "stream/publisher.h"

namespace vem::stream {

class PublisherFanOut final : public Publisher {
 public:
  explicit PublisherFanOut(std::vector<Publisher*> publishers);

  void publishLights(SharedBytes message) override;
  void publishEnvironment(const CubeVariant& variant, SharedBytes message) override;
  void publishStatus(const Status& status) override;
  [[nodiscard]] CubemapDemand cubemapDemand() const override;
  [[nodiscard]] std::vector<PendingControl> takeControls() override;
  void reply(std::uint64_t connection, const ControlReply& reply) override;
  [[nodiscard]] std::string note() const override;  // the publishers' notes, joined by "; "

 private:
  std::vector<Publisher*> publishers_;
};

}  // namespace vem::stream
