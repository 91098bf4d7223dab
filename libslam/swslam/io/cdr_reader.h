#pragma once
// A cursor over one CDR-serialized message (OMG CDR as ROS 2 writes it, XCDR1: a 4-byte
// encapsulation header, 0x00 0x00 big endian or 0x00 0x01 little endian, then the payload,
// each primitive aligned to its size counted from the payload's start). Every read is checked
// against the bytes left before anything is read or allocated: a length or count past them is
// a CdrError naming the byte, never an allocation.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace swslam::io
{
/** A CDR message that cannot be read: "CDR byte N of M: ...". */
class CdrError : public std::runtime_error
{
 public:
  using std::runtime_error::runtime_error;
};

class CdrReader
{
 public:
  /** Reads the encapsulation header; throws CdrError if it is not plain CDR (XCDR1) of
   * either byte order, or if fewer than 4 bytes are given. `data` must outlive the reader. */
  CdrReader(const uint8_t* data, size_t size);

  bool bigEndian() const { return big_endian_; }
  uint32_t u32();
  int32_t i32();
  float f32();
  double f64();
  /** A string: a u32 length counting its terminating NUL, then its bytes. */
  std::string string();
  /** A sequence's element count, checked: `count * min_element_bytes` must fit in the bytes
   * left (a count that cannot fit is a CdrError before anything is allocated). */
  uint32_t sequenceLength(size_t min_element_bytes);
  /** `n` floats (a count sequenceLength(4) checked). */
  std::vector<float> f32Array(uint32_t n);
  /** Throws CdrError unless every payload byte was read (up to 3 bytes of padding allowed:
   * serializers round the payload up to 4). */
  void expectEnd() const;

  /** Offset of the next byte, from the start of the buffer (the header included). */
  size_t offset() const { return at_; }
  size_t size() const { return size_; }

  /** Throws CdrError "CDR byte N of M: what". */
  [[noreturn]] void fail(const std::string& what) const;

 private:
  /** Aligns to `n` from the payload's start and checks that `n` bytes follow. */
  const uint8_t* take(size_t n, size_t align);
  template <class T>
  T primitive();

  const uint8_t* data_;
  size_t size_;
  size_t at_ = 4;
  bool big_endian_ = false;
};

}  // namespace swslam::io
