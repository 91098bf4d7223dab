#include <swslam/io/rawlog_reader.h>

#include <swslam/io/gzip_file.h>
#include <swslam/io/read_progress.h>
#include <swslam/sensor/input_bounds.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <sstream>

#include <mrpt/core/exceptions.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

namespace swslam::io
{
namespace
{
/** MRPT's exception text without its call-stack backtraces: the "Message:" lines of the
 * nested exceptions, outermost first (or the whole text if it has none). */
std::string mrptMessages(const std::exception& e)
{
  const std::string text = mrpt::exception_to_str(e);
  std::istringstream lines(text);
  std::string line, out;
  const std::string tag = "Message:";
  while (std::getline(lines, line))
  {
    if (line.compare(0, tag.size(), tag) != 0) continue;
    const size_t start = line.find_first_not_of(' ', tag.size());
    if (start == std::string::npos) continue;
    out += (out.empty() ? "" : ": ") + line.substr(start);
  }
  return out.empty() ? text : out;
}

// The start of a CObservation2DRangeScan entry (versions 6-8) up to its ray count: MRPT
// allocates 9 bytes per ray before it reads them, so a corrupt count of 2^32 asked for 38 GB
// (a segfault where the allocator gave up, minutes of page faults where it did not).
constexpr char kScanClass[] = "mrpt::obs::CObservation2DRangeScan";
constexpr char kPoseClass[] = "mrpt::poses::CPose3D";
constexpr size_t kScanClassLen = sizeof(kScanClass) - 1, kPoseClassLen = sizeof(kPoseClass) - 1;
// class tag, name, version, aperture, rightToLeft, maxRange; pose tag, name, version (3:
// 12 doubles), end marker; then the ray count.
constexpr size_t kPoseAt = 1 + kScanClassLen + 1 + 4 + 1 + 4;
constexpr size_t kRayCountAt = kPoseAt + 1 + kPoseClassLen + 1 + 12 * 8 + 1;

/** The ray count of the scan entry that `head` starts, if it is one of the known layout. */
std::optional<uint32_t> scanRayCount(const std::string& head)
{
  if (head.size() < kRayCountAt + 4) return std::nullopt;
  auto u8 = [&](size_t i) { return static_cast<uint8_t>(head[i]); };
  if (u8(0) != (0x80 | kScanClassLen) || head.compare(1, kScanClassLen, kScanClass) != 0) return std::nullopt;
  const uint8_t version = u8(1 + kScanClassLen);
  if (version < 6 || version > 8) return std::nullopt;
  if (u8(kPoseAt) != (0x80 | kPoseClassLen) || head.compare(kPoseAt + 1, kPoseClassLen, kPoseClass) != 0 ||
      u8(kPoseAt + 1 + kPoseClassLen) != 3 || u8(kRayCountAt - 1) != 0x88)
    return std::nullopt;
  return uint32_t(u8(kRayCountAt)) | uint32_t(u8(kRayCountAt + 1)) << 8 |
         uint32_t(u8(kRayCountAt + 2)) << 16 | uint32_t(u8(kRayCountAt + 3)) << 24;  // little-endian
}

/** The archive the reader parses: the file with a look-ahead, so that an entry's start can be
 * checked before MRPT reads it. */
class LookaheadArchive : public mrpt::serialization::CArchive
{
 public:
  explicit LookaheadArchive(GzipFile& in) : in_(in) {}
  /** The next `n` bytes of the file (fewer at its end), not consumed. */
  const std::string& peek(size_t n)
  {
    char buf[256];
    while (ahead_.size() < n)
    {
      const size_t ask = std::min(sizeof(buf), n - ahead_.size());
      const size_t got = in_.read(buf, ask);
      ahead_.append(buf, got);
      if (got < ask) break;  // the end (or damage, which the next read reports after this data)
    }
    return ahead_;
  }

 protected:
  size_t write(const void*, size_t) override { throw std::logic_error("rawlog: the reader cannot write"); }
  size_t read(void* buf, size_t len) override
  {
    const size_t from_ahead = std::min(len, ahead_.size());
    std::memcpy(buf, ahead_.data(), from_ahead);
    ahead_.erase(0, from_ahead);
    return from_ahead + (from_ahead < len ? in_.read(static_cast<char*>(buf) + from_ahead, len - from_ahead) : 0);
  }

 private:
  GzipFile& in_;
  std::string ahead_;
};

/** The child's work: decodes the rawlog's entries with MRPT and sends each item
 * re-serialized, an entry's position marked before MRPT reads it. */
void decodeRawlog(const std::string& path, DecodeChannel& channel)
{
  using namespace mrpt::obs;
  GzipFile file(path);
  const ReadProgress progress(path);
  LookaheadArchive archive(file);
  mrpt::io::CMemoryStream buffer;
  auto send = [&](const mrpt::serialization::CSerializable& item) {
    buffer.clear();
    mrpt::serialization::archiveFrom(buffer) << item;
    channel.send(progress.fraction(file.position()),
                 std::string(static_cast<const char*>(buffer.getRawBufferData()), buffer.getTotalBytesCount()));
  };
  for (uint64_t entry = 0;; entry++)
  {
    // Marked before the look-ahead reads on, so that a damaged stream found there is this
    // entry's, not the last one's.
    channel.mark({entry, file.position() - archive.peek(0).size()});
    const std::string& head = archive.peek(kRayCountAt + 4);
    channel.mark({entry, file.position() - head.size()});
    if (head.empty()) return;  // the clean end of the file
    if (const auto rays = scanRayCount(head))
      if (const std::string problem = sensor::rayCountProblem(*rays); !problem.empty())
        throw std::runtime_error(problem);
    mrpt::serialization::CSerializable::Ptr obj;
    try
    {
      archive >> obj;
    }
    catch (const std::exception& e)
    {
      throw std::runtime_error(mrptMessages(e));
    }
    if (!obj) continue;
    if (auto obs = std::dynamic_pointer_cast<CObservation>(obj))
    {
      send(*obs);
    }
    else if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(obj))
    {
      for (const auto& o : *sf)
        if (o) send(*o);
    }
    else if (auto acts = std::dynamic_pointer_cast<CActionCollection>(obj))
    {
      if (auto mv = acts->getBestMovementEstimation()) send(*mv);
    }
    // Other object kinds (maps, poses...) are not part of the input stream: skipped.
  }
}
}  // namespace

RawlogReader::RawlogReader(const std::string& path) : path_(path)
{
  try
  {
    GzipFile probe(path);  // here, so that the constructor says it
  }
  catch (const std::exception&)
  {
    throw std::runtime_error("rawlog: cannot open '" + path + "'");
  }
  decoder_ = std::make_unique<SandboxedDecoder>([path](DecodeChannel& channel) { decodeRawlog(path, channel); });
}

RawlogReader::~RawlogReader() = default;

bool RawlogReader::next(RawlogItem& item)
{
  auto corrupt = [&](DecodePosition at, const std::string& why) {
    return RawlogError("rawlog '" + path_ + "': corrupt or truncated entry #" + std::to_string(at.index) +
                           " (at byte " + std::to_string(at.offset) + "): " + why,
                       at.index);
  };
  if (refused_) throw *refused_;
  try
  {
    if (!decoder_->next(frame_))
    {
      entries_ = frame_.at.index;
      fraction_ = 1;
      return false;
    }
  }
  catch (const DecodeFailure& f)
  {
    entries_ = f.at().index;  // the entries before the damaged one
    throw corrupt(f.at(), f.what());
  }
  entries_ = frame_.at.index + 1;
  fraction_ = frame_.fraction;
  mrpt::serialization::CSerializable::Ptr obj;
  try
  {
    mrpt::io::CMemoryStream in;
    in.assignMemoryNotOwn(frame_.payload.data(), frame_.payload.size());
    mrpt::serialization::archiveFrom(in) >> obj;
  }
  catch (const std::exception& e)
  {
    throw corrupt(frame_.at, "its decoded item could not be read back: " + mrptMessages(e));
  }
  item.observation = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj);
  item.odometry_increment = std::dynamic_pointer_cast<mrpt::obs::CActionRobotMovement2D>(obj);
  if (!item.observation && !item.odometry_increment)
    throw corrupt(frame_.at, "its decoded item is neither an observation nor an odometry increment");
  // Read whole, but past the bounds every reader applies (a scan inside a sensory frame had
  // its ray count checked only by the decoder's memory budget).
  if (const auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(item.observation))
  {
    std::string problem = sensor::rayCountProblem(scan->getScanSize());
    if (problem.empty()) problem = sensor::mountingProblem(scan->sensorPose);
    if (!problem.empty())
    {
      entries_ = frame_.at.index;
      refused_ = std::make_shared<RawlogError>("rawlog '" + path_ + "': entry #" + std::to_string(frame_.at.index) +
                                                   " (at byte " + std::to_string(frame_.at.offset) + "): scan '" +
                                                   scan->sensorLabel + "': " + problem,
                                               frame_.at.index);
      throw *refused_;
    }
  }
  return true;
}

double RawlogReader::fractionRead() const { return fraction_; }

}  // namespace swslam::io
