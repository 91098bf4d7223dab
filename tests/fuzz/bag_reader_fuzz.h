#pragma once
// Shared by the bag harnesses (ros1_bag, ros2_bag): a reader over the input as a file, read to
// its end. Documented error paths: std::runtime_error from the constructor, a BagError from
// next(). Promises checked: the error's message index is the count of messages read; every
// scan has at most sensor::kMaxScanRays rays; fractionRead() stays in [0, 1].

#include "fuzz_input.h"

#include <swslam/io/bag_reader.h>
#include <swslam/sensor/input_bounds.h>

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <memory>

namespace swslam::fuzz
{
/** Reads the input, written as `name`, with a Reader (BagReaderBase) to its end. */
template <class Reader>
int readBag(const uint8_t* data, size_t size, const std::string& name)
{
  const std::string path = writeInput(data, size, name);
  std::unique_ptr<Reader> reader;
  try
  {
    reader = std::make_unique<Reader>(path, io::BagReaderOptions{});
  }
  catch (const std::runtime_error&)
  {
    return 0;
  }
  mrpt::obs::CObservation::Ptr o;
  try
  {
    while (reader->next(o))
      if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o))
        SWSLAM_FUZZ_CHECK(s->getScanSize() <= sensor::kMaxScanRays, std::to_string(s->getScanSize()) + " rays");
  }
  catch (const io::BagError& e)
  {
    SWSLAM_FUZZ_CHECK(e.message() == reader->messagesRead(), e.what());
  }
  const double f = reader->fractionRead();
  SWSLAM_FUZZ_CHECK(f >= 0 && f <= 1, "fractionRead() = " + std::to_string(f));
  return 0;
}
}  // namespace swslam::fuzz
