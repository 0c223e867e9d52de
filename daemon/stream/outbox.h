// Outbox: what one streaming connection still has to send, as newest-only slots: one light frame,
// one environment frame, one status, plus a short queue of replies (the hello first), which are
// never replaced. Putting a light frame into a slot whose frame was not sent yet replaces it and
// counts a skip for this client; environment frames and statuses replace silently.
//
// next() hands out the next message to write: replies first, then the light frame, then the
// environment frame and the status; after a light frame, a waiting environment frame or status
// goes before the next light frame, so a client that barely keeps up still gets them.
//
// A server paces a slow reader (client_lag.h) by asking only for replies while it holds the rest:
// the slots keep being replaced meanwhile, so the client then gets the newest of each.
//
// Messages are serialized once and shared by every connection (shared_ptr<const std::string>).
// Pure; not thread-safe (the server's io thread owns each outbox).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>

#include "stream/shared_bytes.h"

namespace vem::stream {

class Outbox {
 public:
  static constexpr std::size_t kMaxReplies = 32;

  // Replaces an unsent light frame (one skip) and adds `alreadySkipped` (frames coalesced before
  // they reached this outbox).
  void putLights(SharedBytes message, std::uint64_t alreadySkipped = 0);
  void putEnvironment(SharedBytes message) { environment_ = std::move(message); }
  void putStatus(SharedBytes message) { status_ = std::move(message); }
  // False when kMaxReplies replies already wait (the client sends faster than it reads).
  [[nodiscard]] bool putReply(SharedBytes message);

  // The next message to write, taken out of its slot; null when nothing waits.
  [[nodiscard]] SharedBytes next();

  [[nodiscard]] bool hasReply() const { return !replies_.empty(); }
  [[nodiscard]] bool empty() const {
    return replies_.empty() && !lights_ && !environment_ && !status_;
  }
  [[nodiscard]] std::uint64_t skippedLights() const { return skippedLights_; }
  [[nodiscard]] std::uint64_t sentLights() const { return sentLights_; }

 private:
  std::deque<SharedBytes> replies_;
  SharedBytes lights_;
  SharedBytes environment_;
  SharedBytes status_;
  bool lastWasLights_ = false;
  std::uint64_t skippedLights_ = 0;
  std::uint64_t sentLights_ = 0;
};

}  // namespace vem::stream
