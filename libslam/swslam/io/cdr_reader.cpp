#include <swslam/io/cdr_reader.h>

#include <cstring>

namespace swslam::io
{
CdrReader::CdrReader(const uint8_t* data, size_t size) : data_(data), size_(size)
{
  if (size < 4) fail("shorter than the 4-byte encapsulation header");
  if (data[0] != 0 || data[1] > 1)
    fail("encapsulation " + std::to_string(data[0]) + " " + std::to_string(data[1]) +
         " is not plain CDR (0 0: big endian, 0 1: little endian)");
  big_endian_ = data[1] == 0;
}

void CdrReader::fail(const std::string& what) const
{
  throw CdrError("CDR byte " + std::to_string(at_) + " of " + std::to_string(size_) + ": " + what);
}

const uint8_t* CdrReader::take(size_t n, size_t align)
{
  const size_t pad = (align - (at_ - 4) % align) % align;  // alignment counts from the payload
  if (pad > size_ - at_ || n > size_ - at_ - pad)
    fail("a value of " + std::to_string(n) + " bytes runs past the message's end");
  at_ += pad;
  const uint8_t* p = data_ + at_;
  at_ += n;
  return p;
}

template <class T>
T CdrReader::primitive()
{
  uint8_t bytes[sizeof(T)];
  std::memcpy(bytes, take(sizeof(T), sizeof(T)), sizeof(T));
  const bool host_big = false;  // the targets (x86, ARM Linux) are little endian
  if (big_endian_ != host_big)
    for (size_t i = 0; i < sizeof(T) / 2; i++) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  T v;
  std::memcpy(&v, bytes, sizeof(T));
  return v;
}

uint32_t CdrReader::u32() { return primitive<uint32_t>(); }
int32_t CdrReader::i32() { return primitive<int32_t>(); }
float CdrReader::f32() { return primitive<float>(); }
double CdrReader::f64() { return primitive<double>(); }

std::string CdrReader::string()
{
  const uint32_t n = u32();
  if (n > size_ - at_)
    fail("a string of " + std::to_string(n) + " bytes, but " + std::to_string(size_ - at_) + " are left");
  const char* p = reinterpret_cast<const char*>(take(n, 1));
  if (n == 0) return "";  // some writers give an empty string no NUL
  if (p[n - 1] != '\0') fail("a string of " + std::to_string(n) + " bytes that does not end in NUL");
  return std::string(p, n - 1);
}

uint32_t CdrReader::sequenceLength(size_t min_element_bytes)
{
  const uint32_t n = u32();
  if (min_element_bytes > 0 && n > (size_ - at_) / min_element_bytes)
    fail("a sequence of " + std::to_string(n) + " elements of at least " + std::to_string(min_element_bytes) +
         " bytes, but " + std::to_string(size_ - at_) + " bytes are left");
  return n;
}

std::vector<float> CdrReader::f32Array(uint32_t n)
{
  if (n > (size_ - at_) / 4) fail("an array of " + std::to_string(n) + " floats runs past the message's end");
  std::vector<float> v(n);
  for (float& x : v) x = f32();
  return v;
}

void CdrReader::expectEnd() const
{
  if (size_ - at_ > 3) fail(std::to_string(size_ - at_) + " bytes past the message's end");
}

}  // namespace swslam::io
