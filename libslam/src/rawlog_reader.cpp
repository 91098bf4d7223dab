#include "swslam/rawlog_reader.h"

#include <algorithm>
#include <sstream>

#include <mrpt/core/exceptions.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

namespace swslam
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
}  // namespace

RawlogReader::RawlogReader(const std::string& path) : path_(path)
{
  bool opened = false;
  try
  {
    opened = file_.open(path);
  }
  catch (const std::exception&)
  {
  }
  if (!opened) throw std::runtime_error("rawlog: cannot open '" + path + "'");
  archive_ = std::make_unique<mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZInputStream>>(file_);
}

RawlogReader::~RawlogReader() = default;

bool RawlogReader::next(RawlogItem& item)
{
  using namespace mrpt::obs;
  while (pending_.empty())
  {
    const uint64_t pos_before = file_.getPosition();
    mrpt::serialization::CSerializable::Ptr obj;
    try
    {
      *archive_ >> obj;
    }
    catch (const std::exception& e)
    {
      // A read that fails without consuming a byte is the clean end of the file.
      if (file_.getPosition() == pos_before && file_.checkEOF()) return false;
      throw RawlogError("rawlog '" + path_ + "': corrupt or truncated entry #" +
                            std::to_string(entries_) + " (at byte " + std::to_string(pos_before) +
                            "): " + mrptMessages(e),
                        entries_);
    }
    entries_++;
    if (!obj) continue;
    if (auto obs = std::dynamic_pointer_cast<CObservation>(obj))
    {
      pending_.push_back({obs, nullptr});
    }
    else if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(obj))
    {
      for (const auto& o : *sf) pending_.push_back({o, nullptr});
    }
    else if (auto acts = std::dynamic_pointer_cast<CActionCollection>(obj))
    {
      if (auto mv = acts->getBestMovementEstimation())
        pending_.push_back({nullptr, std::make_shared<CActionRobotMovement2D>(*mv)});
    }
    // Other object kinds (maps, poses...) are not part of the input stream: skipped.
  }
  item = std::move(pending_.front());
  pending_.pop_front();
  return true;
}

double RawlogReader::fractionRead() const
{
  const double total = static_cast<double>(file_.getTotalBytesCount());
  return total > 0 ? std::min(1.0, static_cast<double>(file_.getPosition()) / total) : 1.0;
}

}  // namespace swslam
