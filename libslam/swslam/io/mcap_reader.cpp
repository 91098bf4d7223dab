#include <swslam/io/mcap_reader.h>

#include <lz4frame.h>
#include <zlib.h>
#include <zstd.h>

#include <cstring>
#include <filesystem>

namespace swslam::io
{
namespace
{
using namespace mcap;
constexpr uint64_t kRecordPrefix = 1 + 8;  // opcode, length

/** Little-endian fields of one record's body, each checked against the bytes left. */
class Fields
{
 public:
  Fields(const uint8_t* p, uint64_t size, const std::string& record) : p_(p), size_(size), record_(record) {}
  template <class T>
  T get()
  {
    T v = 0;
    need(sizeof(T), "a field");
    for (size_t i = 0; i < sizeof(T); i++) v |= T(p_[at_ + i]) << (8 * i);
    at_ += sizeof(T);
    return v;
  }
  /** A u32-length-prefixed string. */
  std::string string()
  {
    const uint32_t n = get<uint32_t>();
    need(n, "a string");
    std::string s(reinterpret_cast<const char*>(p_ + at_), n);
    at_ += n;
    return s;
  }
  /** A length-prefixed byte array (its prefix of `Len`): where it starts and its length. */
  template <class Len>
  const uint8_t* bytes(uint64_t& n)
  {
    n = get<Len>();
    need(n, "a byte array");
    const uint8_t* start = p_ + at_;
    at_ += n;
    return start;
  }
  const uint8_t* rest(uint64_t& n)
  {
    n = size_ - at_;
    const uint8_t* start = p_ + at_;
    at_ = size_;
    return start;
  }

 private:
  void need(uint64_t n, const char* what)
  {
    if (n > size_ - at_)
      throw McapError(record_ + ": " + what + " of " + std::to_string(n) + " bytes at byte " + std::to_string(at_) +
                      " of its " + std::to_string(size_) + " runs past its end");
  }
  const uint8_t* p_;
  uint64_t size_, at_ = 0;
  const std::string& record_;
};

std::string recordAt(uint64_t at) { return "MCAP record at byte " + std::to_string(at); }

std::string hex(uint8_t opcode)
{
  const char* digits = "0123456789abcdef";
  return std::string("0x") + digits[opcode >> 4] + digits[opcode & 15];
}

uint64_t readU64(const uint8_t* p)
{
  uint64_t v = 0;
  for (int i = 0; i < 8; i++) v |= uint64_t(p[i]) << (8 * i);
  return v;
}

/** Decompresses `src` into exactly `dst.size()` bytes; "" or the problem. */
std::string decompress(const std::string& compression, const uint8_t* src, uint64_t n, std::vector<uint8_t>& dst)
{
  if (compression.empty())
  {
    if (n != dst.size()) return std::to_string(n) + " bytes stored uncompressed";
    if (n > 0) std::memcpy(dst.data(), src, n);  // an empty chunk has no buffer
    return "";
  }
  if (compression == "zstd")
  {
    const size_t got = ZSTD_decompress(dst.data(), dst.size(), src, n);
    if (ZSTD_isError(got)) return std::string("zstd: ") + ZSTD_getErrorName(got);
    if (got != dst.size()) return "zstd gave " + std::to_string(got) + " bytes";
    return "";
  }
  // lz4 (frame format)
  LZ4F_dctx* ctx = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&ctx, LZ4F_VERSION))) return "lz4: no decompression context";
  size_t in_at = 0, out_at = 0;
  std::string problem;
  while (problem.empty())
  {
    size_t in = n - in_at, out = dst.size() - out_at;
    const size_t hint = LZ4F_decompress(ctx, dst.data() + out_at, &out, src + in_at, &in, nullptr);
    in_at += in;
    out_at += out;
    if (LZ4F_isError(hint))
      problem = std::string("lz4: ") + LZ4F_getErrorName(hint);
    else if (hint == 0 && in_at == n)
      break;  // every frame ended with the input
    else if (in == 0 && out == 0)
      problem = out_at == dst.size() ? "lz4: more data than stated" : "lz4: the compressed data ends inside a frame";
  }
  LZ4F_freeDecompressionContext(ctx);
  if (problem.empty() && out_at != dst.size()) problem = "lz4 gave " + std::to_string(out_at) + " bytes";
  return problem;
}
}  // namespace

uint64_t mcapExpansionBound(const std::string& compression, uint64_t compressed)
{
  if (compression == "lz4") return compressed * 255 + (64u << 10);
  if (compression == "zstd") return compressed * 32768;
  return compressed;
}

bool hasMcapMagic(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  uint8_t magic[8] = {};
  f.read(reinterpret_cast<char*>(magic), 8);
  return f.gcount() == 8 && std::memcmp(magic, kMagic, 8) == 0;
}

McapReader::McapReader(const std::string& path) : path_(path), file_(path, std::ios::binary)
{
  std::error_code ec;
  size_ = std::filesystem::file_size(path, ec);
  if (!file_ || ec) throw std::runtime_error("cannot open '" + path + "'");
  if (!hasMcapMagic(path)) throw McapError("'" + path + "' is not an MCAP file: it does not start with its magic");
  offset_ = 8;
  file_.seekg(8);
  if (!nextRecord() || opcode_ != kHeader)
    fail(8, "the file does not begin with a Header record (opcode 0x01)");
}

void McapReader::fail(uint64_t at, const std::string& what)
{
  done_ = true;
  chunk_.clear();
  throw McapError(recordAt(at) + ": " + what);
}

bool McapReader::nextRecord()
{
  const uint64_t left = size_ - offset_;
  if (left < kRecordPrefix)
    fail(offset_, "the file ends after " + std::to_string(left) +
                      " bytes, inside a record's opcode and length, before its DataEnd and Footer (a truncated file)");
  uint8_t prefix[kRecordPrefix];
  file_.read(reinterpret_cast<char*>(prefix), kRecordPrefix);
  record_at_ = offset_;
  opcode_ = prefix[0];
  const uint64_t length = readU64(prefix + 1);
  offset_ += kRecordPrefix;
  if (length > size_ - offset_)
    fail(record_at_, "opcode " + hex(opcode_) + " states " + std::to_string(length) +
                         " bytes, but the file has " + std::to_string(size_ - offset_) + " left (a truncated file?)");
  const bool wanted = opcode_ == kHeader || opcode_ == kSchema || opcode_ == kChannel || opcode_ == kMessage ||
                      opcode_ == kChunk;
  if (!wanted)
  {
    file_.seekg(static_cast<std::streamoff>(offset_ + length));  // indexes, statistics, attachments...
    offset_ += length;
    record_.clear();
    return opcode_ != kDataEnd && opcode_ != kFooter;
  }
  if (length > kMaxMcapChunkBytes)
    fail(record_at_, "a record of " + std::to_string(length) + " bytes, more than the " +
                         std::to_string(kMaxMcapChunkBytes) + " this reader holds");
  record_.resize(length);
  file_.read(reinterpret_cast<char*>(record_.data()), static_cast<std::streamsize>(length));
  if (static_cast<uint64_t>(file_.gcount()) != length) fail(record_at_, "the file could not be read");
  offset_ += length;
  return true;
}

void McapReader::openChunk()
{
  const std::string where = recordAt(record_at_) + " (a Chunk)";
  Fields f(record_.data(), record_.size(), where);
  f.get<uint64_t>();  // message start time
  f.get<uint64_t>();  // message end time
  const uint64_t size = f.get<uint64_t>();
  const uint32_t crc = f.get<uint32_t>();
  const std::string compression = f.string();
  uint64_t stored = 0;
  const uint8_t* data = f.bytes<uint64_t>(stored);
  if (compression != "" && compression != "zstd" && compression != "lz4")
    fail(record_at_, "a Chunk compressed with '" + compression + "' (this reader knows zstd, lz4 and none)");
  if (size > kMaxMcapChunkBytes || size > mcapExpansionBound(compression, stored))
    fail(record_at_, "a Chunk of " + std::to_string(stored) + " bytes (" +
                         (compression.empty() ? std::string("uncompressed") : compression) + ") states " +
                         std::to_string(size) + " bytes uncompressed, more than " +
                         std::to_string(std::min(kMaxMcapChunkBytes, mcapExpansionBound(compression, stored))) +
                         " (its compression's most, and the 1 GiB bound)");
  chunk_.assign(size, 0);
  if (const std::string problem = decompress(compression, data, stored, chunk_); !problem.empty())
    fail(record_at_, "a Chunk stating " + std::to_string(size) + " bytes uncompressed cannot be decompressed: " +
                         problem);
  const uint32_t got = static_cast<uint32_t>(crc32(crc32(0, nullptr, 0), chunk_.data(), static_cast<uInt>(size)));
  if (crc != 0 && got != crc)  // 0: no CRC written
    fail(record_at_, "a Chunk whose records' CRC is " + std::to_string(got) + ", not the stated " +
                         std::to_string(crc) + " (damaged data)");
  chunk_at_ = 0;
}

bool McapReader::take(uint8_t opcode, const uint8_t* body, uint64_t size, McapMessage& out, const std::string& where)
{
  Fields f(body, size, where);
  if (opcode == kSchema)
  {
    const uint16_t id = f.get<uint16_t>();
    schemas_[id] = f.string();
  }
  else if (opcode == kChannel)
  {
    McapChannel c;
    c.id = f.get<uint16_t>();
    const uint16_t schema = f.get<uint16_t>();
    c.topic = f.string();
    c.message_encoding = f.string();
    if (schema != 0)
    {
      const auto it = schemas_.find(schema);
      if (it == schemas_.end()) throw McapError(where + ": a Channel of schema " + std::to_string(schema) + ", not defined before it");
      c.schema_name = it->second;
    }
    channels_[c.id] = c;
  }
  else if (opcode == kMessage)
  {
    out.channel_id = f.get<uint16_t>();
    f.get<uint32_t>();  // sequence
    out.log_time = f.get<uint64_t>();
    f.get<uint64_t>();  // publish time
    if (!channels_.count(out.channel_id))
      throw McapError(where + ": a Message on channel " + std::to_string(out.channel_id) + ", not defined before it");
    uint64_t n = 0;
    const uint8_t* data = f.rest(n);
    out.data.assign(data, data + n);
    return true;
  }
  return false;
}

bool McapReader::next(McapMessage& out)
{
  try
  {
    while (!done_)
    {
      while (chunk_at_ < chunk_.size())  // the open chunk's records
      {
        const uint64_t at = chunk_at_, left = chunk_.size() - at;
        const std::string where = recordAt(record_at_) + " (a Chunk), at its uncompressed byte " + std::to_string(at);
        if (left < kRecordPrefix) throw McapError(where + ": " + std::to_string(left) + " bytes, not a record");
        const uint64_t length = readU64(chunk_.data() + at + 1);
        if (length > left - kRecordPrefix)
          throw McapError(where + ": a record of " + std::to_string(length) + " bytes, but the chunk has " +
                          std::to_string(left - kRecordPrefix) + " left");
        chunk_at_ += kRecordPrefix + length;
        if (take(chunk_[at], chunk_.data() + at + kRecordPrefix, length, out, where)) return true;
      }
      chunk_.clear();
      chunk_at_ = 0;
      if (!nextRecord())
      {
        done_ = true;
        return false;
      }
      if (opcode_ == kChunk)
        openChunk();
      else if (take(opcode_, record_.data(), record_.size(), out, recordAt(record_at_)))
        return true;
    }
  }
  catch (const McapError&)
  {
    done_ = true;
    chunk_.clear();
    throw;
  }
  return false;
}

}  // namespace swslam::io
