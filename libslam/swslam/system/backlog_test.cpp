// The count of work handed to another thread: waiting for it to catch up, and closing.
#include <swslam/system/backlog.h>

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

using swslam::system::Backlog;

TEST(Backlog, WaitReturnsAtOnceWhenAtMostNArePending)
{
  Backlog b;
  EXPECT_TRUE(b.waitAtMost(0));
  b.added();
  b.added();
  EXPECT_EQ(b.pending(), 2u);
  EXPECT_TRUE(b.waitAtMost(2));
  b.done();
  EXPECT_TRUE(b.waitAtMost(1));
  b.done();
  b.done();  // more done() than added(): stays at 0
  EXPECT_EQ(b.pending(), 0u);
}

TEST(Backlog, ProducerWaitsUntilTheConsumerHasCaughtUp)
{
  // The producer hands over one item at a time and waits for it: the consumer has always
  // finished every item but the one in hand when the producer goes on.
  Backlog b;
  std::atomic<int> handed{0}, finished{0};
  std::thread consumer([&] {
    while (finished < 200)
      if (finished < handed)
      {
        std::this_thread::yield();
        finished++;
        b.done();
      }
      else
        std::this_thread::yield();
  });
  for (int i = 0; i < 200; i++)
  {
    ASSERT_TRUE(b.waitAtMost(0));
    EXPECT_EQ(finished.load(), i);
    b.added();
    handed++;
  }
  consumer.join();
  EXPECT_EQ(b.pending(), 0u);
}

TEST(Backlog, ClosingReleasesAWaitingProducer)
{
  Backlog b;
  b.added();
  bool result = true;
  std::thread producer([&] { result = b.waitAtMost(0); });  // waits: one is pending
  b.close();
  producer.join();
  EXPECT_FALSE(result);
  EXPECT_FALSE(b.waitAtMost(5));
}
