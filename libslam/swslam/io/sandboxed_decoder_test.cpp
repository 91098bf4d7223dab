#include <swslam/io/sandboxed_decoder.h>

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace swslam::io;

namespace
{
/** The failure that stops reading `decoder` (fails the test if it ends cleanly); `read` gets
 * the frames before it. */
DecodeFailure failureOf(SandboxedDecoder& decoder, std::vector<DecodedFrame>* read = nullptr)
{
  DecodedFrame f;
  try
  {
    while (decoder.next(f))
      if (read) read->push_back(f);
  }
  catch (const DecodeFailure& e)
  {
    return e;
  }
  ADD_FAILURE() << "the decoding ended cleanly";
  return DecodeFailure("", {});
}

/** True if this process has no child left, not even an unreaped one. */
bool noChildLeft()
{
  errno = 0;
  return waitpid(-1, nullptr, WNOHANG) < 0 && errno == ECHILD;
}

constexpr uint64_t kSmallBudget = uint64_t(64) << 20;
}  // namespace

TEST(SandboxedDecoder, PassesFramesWithTheirPositionsThenEndsCleanly)
{
  {
    SandboxedDecoder decoder([](DecodeChannel& ch) {
      for (uint64_t k = 0; k < 3; k++)
      {
        ch.mark({k, 100 * k});
        ch.send(0.25 * double(k), std::string(k * 1000, char('a' + k)));
      }
      ch.mark({3, 300});
    });
    DecodedFrame f;
    for (uint64_t k = 0; k < 3; k++)
    {
      ASSERT_TRUE(decoder.next(f));
      EXPECT_EQ(f.at.index, k);
      EXPECT_EQ(f.at.offset, 100 * k);
      EXPECT_DOUBLE_EQ(f.fraction, 0.25 * double(k));
      EXPECT_EQ(f.payload, std::string(k * 1000, char('a' + k)));
    }
    EXPECT_FALSE(decoder.next(f));
    EXPECT_EQ(f.at.index, 3u);
    EXPECT_EQ(f.at.offset, 300u);
    EXPECT_DOUBLE_EQ(f.fraction, 1.0);
    EXPECT_FALSE(decoder.next(f));
  }
  EXPECT_TRUE(noChildLeft());
}

TEST(SandboxedDecoder, AnExceptionIsAFailureWithItsMessageAtTheMarkedPlace)
{
  SandboxedDecoder decoder([](DecodeChannel& ch) {
    ch.mark({0, 0});
    ch.send(0.1, "good");
    ch.mark({1, 42});
    throw std::runtime_error("a bad length");
  });
  std::vector<DecodedFrame> read;
  const DecodeFailure e = failureOf(decoder, &read);
  ASSERT_EQ(read.size(), 1u);
  EXPECT_EQ(read[0].payload, "good");
  EXPECT_STREQ(e.what(), "a bad length");
  EXPECT_EQ(e.at().index, 1u);
  EXPECT_EQ(e.at().offset, 42u);
  // Every later call fails the same way.
  DecodedFrame f;
  EXPECT_THROW(decoder.next(f), DecodeFailure);
}

TEST(SandboxedDecoder, ACrashIsAFailureNamingTheSignalAtTheMarkedPlace)
{
  {
    SandboxedDecoder decoder([](DecodeChannel& ch) {
      ch.mark({0, 0});
      ch.send(0.1, "good");
      ch.mark({7, 1234});
      std::raise(SIGSEGV);
    });
    std::vector<DecodedFrame> read;
    const DecodeFailure e = failureOf(decoder, &read);
    EXPECT_EQ(read.size(), 1u);
    EXPECT_STREQ(e.what(), "the decoder crashed with SIGSEGV");
    EXPECT_EQ(e.at().index, 7u);
    EXPECT_EQ(e.at().offset, 1234u);
  }
  EXPECT_TRUE(noChildLeft());
  SandboxedDecoder aborting([](DecodeChannel&) { std::abort(); });
  EXPECT_STREQ(failureOf(aborting).what(), "the decoder crashed with SIGABRT");
}

TEST(SandboxedDecoder, AllocationsBeyondTheBudgetFailThere)
{
  const auto t0 = std::chrono::steady_clock::now();
  // At once (a damaged length), and bit by bit (a damaged count of small items).
  SandboxedDecoder at_once([](DecodeChannel& ch) {
    ch.mark({2, 20});
    std::vector<char> v(uint64_t(4) << 30);
    ch.send(0, std::string(1, v[0]));
  }, kSmallBudget);
  const DecodeFailure e = failureOf(at_once);
  EXPECT_STREQ(e.what(), "decoding it needed more than 64 MB of memory (the decoder's budget)");
  EXPECT_EQ(e.at().index, 2u);

  SandboxedDecoder bit_by_bit([](DecodeChannel& ch) {
    ch.mark({3, 30});
    std::vector<std::vector<char>> chunks;
    for (;;) chunks.emplace_back(1 << 16, 'x');  // touched: real memory, not just addresses
  }, kSmallBudget);
  EXPECT_STREQ(failureOf(bit_by_bit).what(), "decoding it needed more than 64 MB of memory (the decoder's budget)");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
}

TEST(SandboxedDecoder, ResidentMemoryTheAddressSpaceLimitDoesNotSeeIsWithinTheBudgetToo)
{
  // Pages mapped before the fork are in the child's address space from its start: touching
  // them grows only its resident memory, as AddressSanitizer's allocator does with the space
  // it maps in advance (where RLIMIT_AS never fails an allocation).
  constexpr size_t kMapped = size_t(512) << 20;
  void* mapped = mmap(nullptr, kMapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  ASSERT_NE(mapped, MAP_FAILED);
  const auto t0 = std::chrono::steady_clock::now();
  SandboxedDecoder touching([mapped](DecodeChannel& ch) {
    ch.mark({4, 40});
    std::memset(mapped, 1, kMapped);
    ch.send(0, "all touched");
  }, kSmallBudget);
  const DecodeFailure e = failureOf(touching);
  munmap(mapped, kMapped);
  EXPECT_STREQ(e.what(), "decoding it needed more than 64 MB of memory (the decoder's budget)");
  EXPECT_EQ(e.at().index, 4u);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
  EXPECT_TRUE(noChildLeft());
}

TEST(SandboxedDecoder, ExitingWithoutTheEndIsAFailure)
{
  SandboxedDecoder decoder([](DecodeChannel& ch) {
    ch.mark({5, 50});
    _exit(4);
  });
  const DecodeFailure e = failureOf(decoder);
  EXPECT_STREQ(e.what(), "the decoder stopped (exit status 4) before the end");
  EXPECT_EQ(e.at().index, 5u);
}

TEST(SandboxedDecoder, AChildStuckAtOnePositionIsStopped)
{
  using std::chrono::milliseconds;
  const auto t0 = std::chrono::steady_clock::now();
  SandboxedDecoder stuck([](DecodeChannel& ch) {
    ch.mark({0, 0});
    ch.send(0, "good");
    ch.mark({9, 90});
    for (;;) pause();
  }, kDecoderMemoryBudget, milliseconds(300));
  std::vector<DecodedFrame> read;
  const DecodeFailure e = failureOf(stuck, &read);
  EXPECT_EQ(read.size(), 1u);
  EXPECT_STREQ(e.what(), "the decoder made no progress for 300 ms on this entry (stuck: stopped)");
  EXPECT_EQ(e.at().index, 9u);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);

  // Slow, but moving on (entries that give no frame): not stuck.
  SandboxedDecoder slow([](DecodeChannel& ch) {
    for (uint64_t k = 0; k < 8; k++)
    {
      ch.mark({k, k});
      usleep(100000);
    }
  }, kDecoderMemoryBudget, milliseconds(300));
  DecodedFrame f;
  EXPECT_FALSE(slow.next(f));
  EXPECT_EQ(f.at.index, 7u);
}

TEST(SandboxedDecoder, DestroyedEarlyItStopsItsChildWhateverItDoes)
{
  const auto t0 = std::chrono::steady_clock::now();
  {
    // A child blocked writing into a full pipe.
    SandboxedDecoder writing([](DecodeChannel& ch) {
      for (;;) ch.send(0, std::string(4096, 'x'));
    });
    DecodedFrame f;
    ASSERT_TRUE(writing.next(f));
    // A child that hangs.
    SandboxedDecoder hanging([](DecodeChannel&) {
      for (;;) pause();
    });
  }
  EXPECT_TRUE(noChildLeft());
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);
}

namespace
{
pid_t g_test_process = 0;
std::string g_marker;
/** An exit handler of the parent's: leaves a mark if another process runs it. */
void markIfRunByAnotherProcess()
{
  if (getpid() == g_test_process) return;
  if (FILE* f = std::fopen(g_marker.c_str(), "w")) std::fclose(f);
}
}  // namespace

TEST(SandboxedDecoder, TheChildRunsNoneOfTheParentsExitHandlers)
{
  g_test_process = getpid();
  g_marker = "/tmp/swslam_sandbox_atexit_" + std::to_string(getpid());
  std::remove(g_marker.c_str());
  std::atexit(markIfRunByAnotherProcess);
  for (int failing : {0, 1})
  {
    SandboxedDecoder decoder([failing](DecodeChannel&) {
      if (failing) throw std::runtime_error("x");
    });
    DecodedFrame f;
    if (failing)
      EXPECT_THROW(decoder.next(f), DecodeFailure);
    else
      EXPECT_FALSE(decoder.next(f));
  }
  EXPECT_NE(access(g_marker.c_str(), F_OK), 0) << "the child ran the parent's exit handlers";
  std::remove(g_marker.c_str());
}

TEST(SandboxedDecoder, FormatsByteCounts)
{
  EXPECT_EQ(formatBytes(uint64_t(1) << 30), "1 GB");
  EXPECT_EQ(formatBytes(uint64_t(64) << 20), "64 MB");
  EXPECT_EQ(formatBytes(512), "512 bytes");
}
