// The MQTT transport of a StreamClient (stream_transport.h): a camera's stream through an MQTT 5
// broker (docs/protocol.md, "MQTT"), with libmosquitto 2.0.
//
// - Address and security: mqtt://[USER@]HOST[:PORT]/PREFIX/CAMERA or mqtts:// (mqtt_url.h); user
//   name and password, TLS with the broker verified against caFile or the system's CAs and its
//   host name, client certificates (util/mosquitto_client.h). Client id "vemcast-<12 hex digits>".
// - Topics, all at QoS 0: PREFIX/CAMERA/hello, /status, /lights (when subscription.lights) and
//   /cubemap (when subscription.cubemapRateHz > 0); PREFIX/CAMERA/reply/CLIENT_ID at QoS 1, for
//   control replies. Each payload goes through decodeServerMessage (server_message_decoder.h); one
//   that does not decode is refused in one sentence (logged once per distinct reason, counted in
//   decodeErrors) and the client stays subscribed; an empty one (a retained message cleared) is
//   ignored; one of another protocol major stops the client for good (Refused, the decoder's
//   sentence). A retained Status with offline true is just a status.
// - States: Connecting until the broker's CONNACK and both SUBACKs (within connectTimeout);
//   Connected then (hello() holds the retained Hello once it arrives; it is not awaited); Waiting
//   with one sentence when a connection fails ("the connection to the broker HOST:PORT failed:
//   ...") or is lost ("... was lost"), reconnecting after an exponential backoff (util/backoff.h,
//   initialBackoff to maxBackoff); Refused for good when the broker refuses the credentials
//   (CONNACK 134 bad user name or password, 135 not authorized: "the broker HOST:PORT refused the
//   connection: not authorized").
// - Control: a ClientMessage{control, request_id} published to PREFIX/CAMERA/control at QoS 1 with
//   the MQTT 5 properties Response Topic (the reply topic) and Correlation Data (the request id's 8
//   bytes, big-endian); the ControlReply with that request id fulfils the future. A PUBACK with a
//   reason code >= 128 fails it ("the broker refused the control message: not authorized": the
//   ACL), so does one with "no matching subscribers" (no vemd listens: no reply would come), and
//   so does the end of the connection. No token: the broker's ACL decides.
//
// Threads: one network thread of its own runs libmosquitto's loop (mosquitto_loop, with
// mosquitto_threaded_set) and every callback; it connects with mosquitto_connect_bind_async, so
// resolving, connecting and the TLS handshake never run on the caller's thread. Not
// mosquitto_loop_start with mosquitto_reconnect_delay_set: in libmosquitto 2.0.11 that thread
// never retries a first connection that failed at once (broker down), ends for good on a TLS
// failure, and counts its delays in whole seconds growing with the square of the attempt.
// sendControl publishes from the caller's thread (libmosquitto queues it and wakes the loop).
#pragma once

#include <expected>
#include <memory>
#include <string>

#include "client/client_state.h"
#include "client/stream_transport.h"

namespace vem::client {

// Checks the address, credentials and certificate files and starts the network thread; one
// sentence when they are unusable. Borrows `options` and `state`, which must outlive the transport.
[[nodiscard]] std::expected<std::unique_ptr<StreamTransport>, std::string> startMqttTransport(
    const StreamClientOptions& options, ClientState& state);

}  // namespace vem::client
