// Publisher: where vemd's stream goes, as the processing thread sees it (stream_sink.h,
// stream_control.h): the WebSocket server (stream_server.h), the MQTT publisher
// (mqtt_publisher.h), or both (publisher_fan_out.h). Every call returns without waiting for the
// network or a client; messages are serialized once by the caller and shared.
//
// Control requests come back through takeControls() on the processing thread, between frames;
// `connection` in a PendingControl names where the answer to reply() goes (a WebSocket connection,
// an MQTT response topic), as the publisher that handed it out understands it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "proto/vem_stream.pb.h"
#include "stream/cubemap_demand.h"
#include "stream/shared_bytes.h"
#include "stream/subscription.h"

namespace vem::stream {

struct PendingControl {
  std::uint64_t connection = 0;
  std::uint64_t requestId = 0;
  Control command;
};

class Publisher {
 public:
  virtual ~Publisher() = default;

  // A serialized ServerMessage with a LightFrame.
  virtual void publishLights(SharedBytes message) = 0;
  // A serialized environment frame of `variant`, built because cubemapDemand() asked for it.
  virtual void publishEnvironment(const CubeVariant& variant, SharedBytes message) = 0;
  // The daemon's status; each publisher fills in what only it knows (clients, drops).
  virtual void publishStatus(const Status& status) = 0;
  // The cube maps wanted now, each variant at the highest rate asked.
  [[nodiscard]] virtual CubemapDemand cubemapDemand() const = 0;
  // Control requests received since the last call, oldest first.
  [[nodiscard]] virtual std::vector<PendingControl> takeControls() = 0;
  virtual void reply(std::uint64_t connection, const ControlReply& reply) = 0;
  // One clause for vemd's statistics line ("mqtt ... connected, 3 dropped"); empty: nothing to say.
  [[nodiscard]] virtual std::string note() const { return {}; }
};

}  // namespace vem::stream
