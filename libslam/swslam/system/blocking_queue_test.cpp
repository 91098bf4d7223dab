// The module threads' input queue: order, closing, and a bounded queue's back-pressure.
#include <swslam/system/blocking_queue.h>

#include <gtest/gtest.h>

#include <thread>
#include <vector>

using swslam::system::BlockingQueue;

TEST(BlockingQueue, FirstInFirstOutAndDrainsAfterClose)
{
  BlockingQueue<int> q;
  for (int i = 0; i < 5; i++) EXPECT_TRUE(q.push(i));
  q.close();
  EXPECT_FALSE(q.push(99));
  for (int i = 0; i < 5; i++) EXPECT_EQ(q.pop(), i);
  EXPECT_EQ(q.pop(), std::nullopt);
  EXPECT_EQ(q.tryPop(), std::nullopt);
  EXPECT_EQ(q.peakSize(), 5u);
}

TEST(BlockingQueue, ConsumerThreadGetsEverythingInOrder)
{
  BlockingQueue<int> q(3);  // bounded: the producer must wait for the consumer
  std::vector<int> got;
  std::thread consumer([&] {
    while (auto v = q.pop()) got.push_back(*v);
  });
  for (int i = 0; i < 1000; i++) ASSERT_TRUE(q.push(i));
  q.close();
  consumer.join();
  ASSERT_EQ(got.size(), 1000u);
  for (int i = 0; i < 1000; i++) EXPECT_EQ(got[i], i);
  EXPECT_LE(q.peakSize(), 3u);
}

TEST(BlockingQueue, ClosingReleasesAProducerWaitingForRoom)
{
  BlockingQueue<int> q(1);
  ASSERT_TRUE(q.push(1));
  bool result = true;
  std::thread producer([&] { result = q.push(2); });  // waits: the queue is full
  q.close();
  producer.join();
  EXPECT_FALSE(result);
  EXPECT_EQ(q.pop(), 1);
  EXPECT_EQ(q.pop(), std::nullopt);
}
