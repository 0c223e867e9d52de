// DropOldestQueue: a bounded queue between a producer that keeps its own pace and a consumer: vemd's
// capture thread and its processing thread, or the processing thread and the MQTT sender
// (stream/mqtt_publisher.h). When it is full, push() drops the OLDEST item to make room and counts the
// drop, so the producer never waits for the consumer: a camera keeps its pace whatever the
// processing or the sinks do, and the consumer always gets the freshest frames.
//
// - pushOrWait() is the lossless alternative for a producer that has no pace of its own (a replay
//   as fast as possible): it waits for room instead of dropping.
// - close() ends the stream: later pushes are refused, the consumer still gets what is queued and
//   then pop() returns nullopt at once. close() wakes a consumer and a producer that wait.
// - Thread-safe for any number of producers and consumers (one mutex, two condition variables);
//   the counters are exact and read under the same lock.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <utility>

#include "util/contract.h"

namespace vem::util {

struct QueueCounters {
  std::uint64_t pushed = 0;   // items accepted (dropped ones included)
  std::uint64_t popped = 0;   // items handed to a consumer
  std::uint64_t dropped = 0;  // items evicted unseen to make room
  std::size_t depth = 0;      // items waiting now
  std::size_t maxDepth = 0;   // most items ever waiting
};

template <typename T>
class DropOldestQueue {
 public:
  explicit DropOldestQueue(std::size_t capacity) : capacity_(capacity) { VEM_EXPECTS(capacity >= 1); }

  DropOldestQueue(const DropOldestQueue&) = delete;
  DropOldestQueue& operator=(const DropOldestQueue&) = delete;

  // Queues `item`, evicting the oldest item when full. Returns what left the producer's hands
  // unqueued, so its storage can be reused: the evicted item, or `item` itself once the queue is
  // closed; nullopt when nothing was evicted. Never blocks on the consumer.
  [[nodiscard]] std::optional<T> push(T item) {
    std::optional<T> evicted;
    {
      std::lock_guard lock(mutex_);
      if (closed_) return item;
      if (items_.size() == capacity_) {
        evicted.emplace(std::move(items_.front()));
        items_.pop_front();
        ++counters_.dropped;
      }
      enqueueLocked(std::move(item));
    }
    notEmpty_.notify_one();
    return evicted;
  }

  // Queues `item`, waiting while the queue is full. Returns `item` back when the queue is or gets
  // closed (it was not queued), nullopt when it was queued.
  [[nodiscard]] std::optional<T> pushOrWait(T item) {
    {
      std::unique_lock lock(mutex_);
      notFull_.wait(lock, [&] { return closed_ || items_.size() < capacity_; });
      if (closed_) return item;
      enqueueLocked(std::move(item));
    }
    notEmpty_.notify_one();
    return std::nullopt;
  }

  // The oldest item, waiting up to `timeout` for one; nullopt on timeout or when the queue is
  // closed and empty (finished() tells which).
  [[nodiscard]] std::optional<T> popFor(std::chrono::nanoseconds timeout) {
    std::optional<T> item;
    {
      std::unique_lock lock(mutex_);
      if (!notEmpty_.wait_for(lock, timeout, [&] { return closed_ || !items_.empty(); })) {
        return std::nullopt;
      }
      if (items_.empty()) return std::nullopt;  // closed and drained
      item.emplace(std::move(items_.front()));
      items_.pop_front();
      ++counters_.popped;
      counters_.depth = items_.size();
    }
    notFull_.notify_one();
    return item;
  }

  // The oldest item, waiting as long as it takes; nullopt once closed and empty.
  [[nodiscard]] std::optional<T> pop() {
    for (;;) {
      if (auto item = popFor(std::chrono::hours(1))) return item;
      if (finished()) return std::nullopt;
    }
  }

  void close() {
    {
      std::lock_guard lock(mutex_);
      closed_ = true;
    }
    notEmpty_.notify_all();
    notFull_.notify_all();
  }

  // Closed and empty: pop() will never return an item again.
  [[nodiscard]] bool finished() const {
    std::lock_guard lock(mutex_);
    return closed_ && items_.empty();
  }
  [[nodiscard]] bool closed() const {
    std::lock_guard lock(mutex_);
    return closed_;
  }
  [[nodiscard]] QueueCounters counters() const {
    std::lock_guard lock(mutex_);
    return counters_;
  }
  [[nodiscard]] std::size_t capacity() const { return capacity_; }

 private:
  void enqueueLocked(T item) {
    items_.push_back(std::move(item));
    ++counters_.pushed;
    counters_.depth = items_.size();
    if (counters_.depth > counters_.maxDepth) counters_.maxDepth = counters_.depth;
  }

  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable notEmpty_;
  std::condition_variable notFull_;
  std::deque<T> items_;
  QueueCounters counters_;
  bool closed_ = false;
};

}  // namespace vem::util
