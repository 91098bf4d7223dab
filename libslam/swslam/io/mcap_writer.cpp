#include <swslam/io/mcap_writer.h>

#include <swslam/io/mcap_reader.h>

#include <zlib.h>

#include <algorithm>
#include <stdexcept>

namespace swslam::io
{
namespace
{
using namespace mcap;

/** Little-endian fields of a record's body. */
struct Body
{
  std::vector<uint8_t> b;
  template <class T>
  Body& put(T v)
  {
    for (size_t i = 0; i < sizeof(T); i++) b.push_back(uint8_t(uint64_t(v) >> (8 * i)));
    return *this;
  }
  Body& str(const std::string& s)
  {
    put<uint32_t>(uint32_t(s.size()));
    b.insert(b.end(), s.begin(), s.end());
    return *this;
  }
  /** Bytes prefixed by their length as a `Len`. */
  template <class Len>
  Body& bytes(const std::vector<uint8_t>& v)
  {
    put<Len>(Len(v.size()));
    b.insert(b.end(), v.begin(), v.end());
    return *this;
  }
};

std::vector<uint8_t> recordBytes(uint8_t opcode, const std::vector<uint8_t>& body)
{
  Body r;
  r.put<uint8_t>(opcode).put<uint64_t>(body.size());
  r.b.insert(r.b.end(), body.begin(), body.end());
  return r.b;
}
}  // namespace

McapWriter::McapWriter(const std::string& path, const std::string& profile, const std::string& library)
    : path_(path), file_(path, std::ios::binary | std::ios::trunc)
{
  if (!file_) throw std::runtime_error("cannot create '" + path + "'");
  file_.write(reinterpret_cast<const char*>(kMagic), 8);
  pos_ = 8;
  record(kHeader, Body().str(profile).str(library).b);
}

void McapWriter::record(uint8_t opcode, const std::vector<uint8_t>& body)
{
  const std::vector<uint8_t> r = recordBytes(opcode, body);
  file_.write(reinterpret_cast<const char*>(r.data()), std::streamsize(r.size()));
  pos_ += r.size();
}

uint16_t McapWriter::addSchema(const std::string& name, const std::string& encoding, const std::string& data)
{
  const auto id = uint16_t(schemas_.size() + 1);
  Body b;
  b.put<uint16_t>(id).str(name).str(encoding).bytes<uint32_t>(std::vector<uint8_t>(data.begin(), data.end()));
  schemas_.push_back(b.b);
  record(kSchema, b.b);
  return id;
}

uint16_t McapWriter::addChannel(uint16_t schema, const std::string& topic, const std::string& message_encoding,
                                const std::map<std::string, std::string>& metadata)
{
  const auto id = uint16_t(channels_.size() + 1);
  Body entries;
  for (const auto& [k, v] : metadata) entries.str(k).str(v);
  Body b;
  b.put<uint16_t>(id).put<uint16_t>(schema).str(topic).str(message_encoding).bytes<uint32_t>(entries.b);
  channels_.push_back(b.b);
  record(kChannel, b.b);
  return id;
}

void McapWriter::write(uint16_t channel, uint64_t log_time, const std::vector<uint8_t>& data)
{
  if (chunk_.empty()) chunk_start_ = chunk_end_ = log_time;
  chunk_start_ = std::min(chunk_start_, log_time);
  chunk_end_ = std::max(chunk_end_, log_time);
  chunk_index_[channel].push_back({log_time, chunk_.size()});
  Body b;
  b.put<uint16_t>(channel).put<uint32_t>(sequence_++).put<uint64_t>(log_time).put<uint64_t>(log_time);
  b.b.insert(b.b.end(), data.begin(), data.end());
  const std::vector<uint8_t> r = recordBytes(kMessage, b.b);
  chunk_.insert(chunk_.end(), r.begin(), r.end());
  first_ = messages_ == 0 ? log_time : std::min(first_, log_time);
  last_ = std::max(last_, log_time);
  messages_++;
  counts_[channel]++;
  if (chunk_.size() >= kMcapChunkBytes) closeChunk();
}

void McapWriter::closeChunk()
{
  if (chunk_.empty()) return;
  const uint64_t chunk_at = pos_;
  const auto crc = uint32_t(crc32(crc32(0, nullptr, 0), chunk_.data(), uInt(chunk_.size())));
  Body c;
  c.put<uint64_t>(chunk_start_).put<uint64_t>(chunk_end_).put<uint64_t>(chunk_.size()).put<uint32_t>(crc).str("");
  c.bytes<uint64_t>(chunk_);
  record(kChunk, c.b);
  const uint64_t chunk_length = pos_ - chunk_at, indexes_at = pos_;
  Body offsets;
  for (const auto& [channel, entries] : chunk_index_)
  {
    offsets.put<uint16_t>(channel).put<uint64_t>(pos_);
    Body pairs;
    for (const auto& [time, offset] : entries) pairs.put<uint64_t>(time).put<uint64_t>(offset);
    record(kMessageIndex, Body().put<uint16_t>(channel).bytes<uint32_t>(pairs.b).b);
  }
  Body index;
  index.put<uint64_t>(chunk_start_).put<uint64_t>(chunk_end_).put<uint64_t>(chunk_at).put<uint64_t>(chunk_length);
  index.bytes<uint32_t>(offsets.b).put<uint64_t>(pos_ - indexes_at).str("");
  index.put<uint64_t>(chunk_.size()).put<uint64_t>(chunk_.size());  // compressed, uncompressed
  chunk_indexes_.push_back(index.b);
  chunk_.clear();
  chunk_index_.clear();
}

void McapWriter::close()
{
  closeChunk();
  record(kDataEnd, Body().put<uint32_t>(0).b);  // no CRC of the data section
  const uint64_t summary_at = pos_;
  Body groups;
  const auto group = [&](uint8_t opcode, const std::vector<std::vector<uint8_t>>& bodies) {
    const uint64_t at = pos_;
    for (const auto& b : bodies) record(opcode, b);
    if (!bodies.empty()) groups.put<uint8_t>(opcode).put<uint64_t>(at).put<uint64_t>(pos_ - at);
  };
  group(kSchema, schemas_);
  group(kChannel, channels_);
  Body counts;
  for (const auto& [channel, n] : counts_) counts.put<uint16_t>(channel).put<uint64_t>(n);
  Body stats;
  stats.put<uint64_t>(messages_).put<uint16_t>(uint16_t(schemas_.size())).put<uint32_t>(uint32_t(channels_.size()));
  stats.put<uint32_t>(0).put<uint32_t>(0).put<uint32_t>(uint32_t(chunk_indexes_.size()));  // attachments, metadata
  stats.put<uint64_t>(first_).put<uint64_t>(last_).bytes<uint32_t>(counts.b);
  group(kStatistics, {stats.b});
  group(kChunkIndex, chunk_indexes_);
  const uint64_t offsets_at = pos_;
  for (size_t at = 0; at < groups.b.size(); at += 17)
    record(kSummaryOffset, std::vector<uint8_t>(groups.b.begin() + long(at), groups.b.begin() + long(at + 17)));
  record(kFooter, Body().put<uint64_t>(summary_at).put<uint64_t>(offsets_at).put<uint32_t>(0).b);
  file_.write(reinterpret_cast<const char*>(kMagic), 8);
  file_.close();
  if (!file_) throw std::runtime_error("cannot write '" + path_ + "' (is the disk full?)");
}

}  // namespace swslam::io
