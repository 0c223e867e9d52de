// DropOldestQueue: drop-oldest when full, exact counts, close() semantics, and a producer/consumer
// stress run for ThreadSanitizer (VEM_TSAN builds).
#include "util/drop_oldest_queue.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace {

using vem::util::DropOldestQueue;
using namespace std::chrono_literals;

TEST(DropOldestQueue, FullQueueDropsTheOldestNotTheNewest) {
  DropOldestQueue<int> queue(3);
  for (int i = 0; i < 5; ++i) (void)queue.push(i);
  queue.close();
  std::vector<int> got;
  while (auto item = queue.pop()) got.push_back(*item);
  EXPECT_EQ(got, (std::vector<int>{2, 3, 4}));
}

TEST(DropOldestQueue, PushHandsBackTheEvictedItemForReuse) {
  DropOldestQueue<int> queue(2);
  EXPECT_FALSE(queue.push(10).has_value());
  EXPECT_FALSE(queue.push(11).has_value());
  const auto evicted = queue.push(12);
  ASSERT_TRUE(evicted.has_value());
  EXPECT_EQ(*evicted, 10);
}

TEST(DropOldestQueue, EveryDropIsCountedAndPushedEqualsPoppedPlusDroppedPlusWaiting) {
  DropOldestQueue<int> queue(4);
  for (int i = 0; i < 10; ++i) (void)queue.push(i);
  (void)queue.popFor(0ns);
  const auto c = queue.counters();
  EXPECT_EQ(c.pushed, 10u);
  EXPECT_EQ(c.dropped, 6u);
  EXPECT_EQ(c.popped, 1u);
  EXPECT_EQ(c.depth, 3u);
  EXPECT_EQ(c.maxDepth, 4u);
  EXPECT_EQ(c.pushed, c.popped + c.dropped + c.depth);
}

TEST(DropOldestQueue, NothingIsDroppedWhileThereIsRoom) {
  DropOldestQueue<int> queue(4);
  for (int i = 0; i < 4; ++i) (void)queue.push(i);
  EXPECT_EQ(queue.counters().dropped, 0u);
}

// A consumer waiting for an item must return as soon as the queue closes, not at its timeout
// (30 s here; the test gives up waiting after 10 s, so a missing wake-up fails, never hangs).
TEST(DropOldestQueue, CloseWakesAWaitingConsumer) {
  DropOldestQueue<int> queue(2);
  std::mutex mutex;
  std::condition_variable done;
  bool returned = false;
  std::optional<int> got = 99;
  std::thread consumer([&] {
    std::optional<int> item = queue.popFor(30s);
    std::lock_guard lock(mutex);
    got = item;
    returned = true;
    done.notify_all();
  });
  std::this_thread::sleep_for(20ms);  // let it wait (the test holds either way)
  queue.close();
  bool woke = false;
  {
    std::unique_lock lock(mutex);
    woke = done.wait_for(lock, 10s, [&] { return returned; });
  }
  consumer.join();
  EXPECT_TRUE(woke) << "close() left the consumer waiting";
  EXPECT_FALSE(got.has_value());
  EXPECT_TRUE(queue.finished());
}

TEST(DropOldestQueue, CloseStillDeliversWhatIsQueuedThenEnds) {
  DropOldestQueue<int> queue(3);
  (void)queue.push(1);
  (void)queue.push(2);
  queue.close();
  EXPECT_FALSE(queue.finished());
  EXPECT_EQ(queue.pop(), 1);
  EXPECT_EQ(queue.pop(), 2);
  EXPECT_EQ(queue.pop(), std::nullopt);
  EXPECT_TRUE(queue.finished());
}

TEST(DropOldestQueue, PushAfterCloseIsRefusedAndHandsTheItemBack) {
  DropOldestQueue<int> queue(3);
  queue.close();
  EXPECT_EQ(queue.push(7), 7);
  EXPECT_EQ(queue.pushOrWait(8), 8);
  EXPECT_EQ(queue.counters().pushed, 0u);
}

TEST(DropOldestQueue, PopForTimesOutOnAnOpenEmptyQueueWithoutEndingIt) {
  DropOldestQueue<int> queue(1);
  EXPECT_EQ(queue.popFor(1ms), std::nullopt);
  EXPECT_FALSE(queue.finished());
}

TEST(DropOldestQueue, PushOrWaitWaitsForRoomInsteadOfDropping) {
  DropOldestQueue<int> queue(1);
  constexpr int kItems = 200;
  std::thread producer([&] {
    for (int i = 0; i < kItems; ++i) EXPECT_FALSE(queue.pushOrWait(i).has_value());
    queue.close();
  });
  std::vector<int> got;
  while (auto item = queue.pop()) got.push_back(*item);
  producer.join();
  ASSERT_EQ(got.size(), std::size_t(kItems));
  for (int i = 0; i < kItems; ++i) EXPECT_EQ(got[std::size_t(i)], i);
  EXPECT_EQ(queue.counters().dropped, 0u);
}

// A producer waiting for room must return (its item handed back) when the queue closes. If
// close() failed to wake it, the test frees a slot after 10 s so the thread can end, and fails.
TEST(DropOldestQueue, CloseWakesAProducerWaitingForRoom) {
  DropOldestQueue<int> queue(1);
  (void)queue.push(1);
  std::mutex mutex;
  std::condition_variable done;
  bool returned = false;
  std::optional<int> back;
  std::thread producer([&] {
    std::optional<int> item = queue.pushOrWait(2);
    std::lock_guard lock(mutex);
    back = item;
    returned = true;
    done.notify_all();
  });
  std::this_thread::sleep_for(20ms);
  queue.close();
  bool woke = false;
  {
    std::unique_lock lock(mutex);
    woke = done.wait_for(lock, 10s, [&] { return returned; });
  }
  if (!woke) (void)queue.pop();  // frees the slot: its notification ends the wait
  producer.join();
  EXPECT_TRUE(woke) << "close() left the producer waiting";
  EXPECT_EQ(back, 2);
}

// Many items through a small queue from a fast producer to a slower consumer: items arrive in
// order, none twice, and the counts add up (a data race here is what TSan reports).
TEST(DropOldestQueue, ConcurrentProducerAndConsumerKeepOrderAndExactCounts) {
  DropOldestQueue<int> queue(4);
  constexpr int kItems = 20000;
  std::thread producer([&] {
    for (int i = 0; i < kItems; ++i) (void)queue.push(i);
    queue.close();
  });
  std::vector<int> got;
  int last = -1;
  bool ordered = true;
  bool counted = true;
  while (auto item = queue.pop()) {
    ordered = ordered && *item > last;
    last = *item;
    got.push_back(*item);
    if (got.size() % 64 == 0) {
      const auto c = queue.counters();  // read while the producer writes them
      counted = counted && c.pushed >= c.popped + c.dropped;
      std::this_thread::yield();
    }
  }
  producer.join();
  const auto c = queue.counters();
  EXPECT_TRUE(ordered);
  EXPECT_TRUE(counted);
  EXPECT_EQ(c.pushed, std::uint64_t(kItems));
  EXPECT_EQ(c.popped, got.size());
  EXPECT_EQ(c.popped + c.dropped, std::uint64_t(kItems));
  EXPECT_EQ(got.back(), kItems - 1);  // the newest is never the one dropped
}

}  // namespace
