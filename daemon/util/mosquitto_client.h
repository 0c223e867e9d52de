// A libmosquitto client set up for a vemcast MQTT address (util/mqtt_url.h), as vemd's publisher
// (stream/mqtt_publisher.h), the clients' stream transport (client/mqtt_transport.h) and the camera
// list (client/camera_list.h) need it: MQTT 5, TCP_NODELAY, the client id given or "vemcast-" and 12 random hex
// digits, the user name (the options' or else the
// address's) and password, and for mqtts:// TLS with the broker verified against caFile or the
// system's CAs (OpenSSL's default directory, or $SSL_CERT_DIR) and its host name, a client
// certificate and key, and never a passphrase prompt. Also the sentences for libmosquitto's
// failures. libmosquitto 2.0 (libmosquitto-dev); mosquitto_lib_init runs once per process.
#pragma once

#include <expected>
#include <memory>
#include <string>
#include <string_view>

#include "util/mqtt_url.h"

struct mosquitto;

namespace vem::util {

struct MqttSecurity {
  std::string username;  // empty: the address's USER@, else none
  std::string password;  // needs a user name
  std::string caFile;    // mqtts://: PEM CA certificates; empty: the system's
  std::string certFile;  // mqtts://: a client certificate (PEM) and its unencrypted key
  std::string keyFile;
};

struct MosquittoDeleter {
  void operator()(mosquitto* client) const;
};
using MosquittoPtr = std::unique_ptr<mosquitto, MosquittoDeleter>;

struct MosquittoClient {
  MosquittoPtr handle;
  std::string id;  // the MQTT client id
};

// A client for `url` with `security`, passing `userdata` to its callbacks; one sentence naming the
// option or file when they are unusable (a password without a user name, a certificate without
// its key or without mqtts://, a file that cannot be read).
// `clientId` "": a random one.
[[nodiscard]] std::expected<MosquittoClient, std::string> newMosquittoClient(
    const MqttUrl& url, const MqttSecurity& security, void* userdata,
    const std::string& clientId = "");

// mosquitto_reason_string of an MQTT 5 reason code with its first letter in lower case, to end a
// sentence ("not authorized").
[[nodiscard]] std::string brokerReasonText(int reasonCode);

// Why a libmosquitto call or connection failed, to end a sentence: from its MOSQ_ERR_* code, errno
// just after it (for MOSQ_ERR_ERRNO) and the first error libmosquitto logged meanwhile (for TLS,
// OpenSSL's reason: "TLS: certificate verify failed").
[[nodiscard]] std::string mosquittoFailureText(int rc, int errnoValue,
                                               std::string_view loggedError);

}  // namespace vem::util
