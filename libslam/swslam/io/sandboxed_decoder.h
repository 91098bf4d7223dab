#pragma once
// Decoding of untrusted input in a child process. A decoder that trusts the lengths it reads
// (MRPT's deserializers do) crashes, or allocates gigabytes, on a damaged file; run in a
// forked child under a memory budget (an address-space limit, and a watch of its resident
// memory, which also holds under AddressSanitizer), its failure becomes an error of the parent
// that names the place in the input and what happened, and the frames it sent before stay
// valid.
//
// The child runs the work given to the constructor: before each risky step it marks where in
// the input it is (a page shared with the parent, so that a crash can be placed), and it
// sends what it decoded as frames (length-prefixed, over a pipe), which the parent reads one
// by one. Construct it before the process starts threads: the child is a fork of the parent,
// and a lock another thread held at the fork would stay held in the child.

#include <chrono>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

namespace swslam::io
{
/** Where in the input the child was: an entry index and the entry's byte offset. */
struct DecodePosition
{
  uint64_t index = 0;
  uint64_t offset = 0;
};

/** One frame the child sent: the position marked when it was sent, the fraction of the input
 * read, and its bytes. */
struct DecodedFrame
{
  DecodePosition at;
  double fraction = 0;
  std::string payload;
};

/** The decoding failed at `at()`: the work threw (its message), or the child died (how). */
class DecodeFailure : public std::runtime_error
{
 public:
  DecodeFailure(const std::string& what, DecodePosition at) : std::runtime_error(what), at_(at) {}
  DecodePosition at() const { return at_; }

 private:
  DecodePosition at_;
};

/** The child's side: what the work calls. */
class DecodeChannel
{
 public:
  virtual ~DecodeChannel() = default;
  /** Marks the position of the step about to run (a crash or an error is reported there). */
  virtual void mark(DecodePosition at) = 0;
  /** Sends a frame at the marked position. */
  virtual void send(double fraction, const std::string& payload) = 0;
};

/** Each decoder's child may grow its address space, and its resident memory, by this much
 * beyond their sizes at the fork: far above what one rawlog entry needs (a scan of 2^20 rays
 * is 9 MB), far below what a damaged count asks for (MRPT reached 23.6 GB on one). */
constexpr uint64_t kDecoderMemoryBudget = uint64_t(1) << 30;
/** How often the child's resident memory is compared with the budget, in its CPU time: it
 * can overshoot by what it touches meanwhile (tens of MB). */
constexpr std::chrono::microseconds kResidentWatchPeriod{10000};
/** The largest frame the parent accepts (a frame is one re-serialized rawlog item). */
constexpr uint64_t kMaxDecodedFrameBytes = uint64_t(256) << 20;
/** A child that stays this long at one marked position while the parent waits for it is
 * stuck (one rawlog entry decodes in milliseconds): it is stopped, and that is the failure. */
constexpr std::chrono::milliseconds kDecoderStallTimeout{60000};

class SandboxedDecoder
{
 public:
  /** Runs in the child: decodes the input and sends its frames. Returning ends the input
   * cleanly; throwing a std::exception is a failure with its message, at the marked
   * position. */
  using Work = std::function<void(DecodeChannel&)>;

  /** Forks the child that runs `work` with its address space limited to its size at the fork
   * plus `memory_budget` bytes (RLIMIT_AS), and stopped if its resident memory grows by more
   * than that (memory the limit does not see, e.g. under AddressSanitizer, whose allocator
   * maps its space in advance) or if it stays `stall_timeout` at one marked position while
   * the parent waits. Throws std::runtime_error if the child cannot be
   * started. */
  explicit SandboxedDecoder(Work work, uint64_t memory_budget = kDecoderMemoryBudget,
                            std::chrono::milliseconds stall_timeout = kDecoderStallTimeout);
  /** Stops the child if it still runs, and reaps it. */
  ~SandboxedDecoder();
  SandboxedDecoder(const SandboxedDecoder&) = delete;
  SandboxedDecoder& operator=(const SandboxedDecoder&) = delete;

  /** The next frame; false at the clean end (then `frame.at` is the last marked position and
   * `frame.fraction` 1). Throws DecodeFailure when the work threw or the child died, and on
   * every call after that. */
  bool next(DecodedFrame& frame);

 private:
  struct Shared;
  /** Reaps the child (killing it first if `kill_first`); returns its wait status. */
  int reap(bool kill_first);
  /** The failure after the pipe ended without an end frame: the child's death. */
  DecodeFailure deathFailure();
  /** Stops the child and keeps `f` for every later next(); returns it. */
  DecodeFailure failed(DecodeFailure f);
  /** Reads `len` bytes from the pipe (fewer only at its end). Throws DecodeFailure if the
   * child stays at one position for the stall timeout meanwhile. */
  size_t receive(void* buf, size_t len);

  Shared* shared_ = nullptr;  ///< the page shared with the child
  int fd_ = -1;               ///< the pipe's read end
  int pid_ = -1;              ///< the child, until reaped
  uint64_t memory_budget_;
  std::chrono::milliseconds stall_timeout_;
  std::string failure_;       ///< set once the decoding failed: every later next() throws it
  DecodePosition failed_at_;
  bool ended_ = false;
};

/** "1 GB", "512 MB": a byte count for messages. */
std::string formatBytes(uint64_t bytes);

}  // namespace swslam::io
