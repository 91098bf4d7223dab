#pragma once
// The `swslam-rawlog2bag` program: an MRPT rawlog converted to a ROS 1 bag
// (io/rawlog2bag.h), an existing output kept unless told otherwise. The options are plain
// values: the program's executable fills them without loading the library.

#include <swslam/io/rawlog2bag.h>

#include <iosfwd>

namespace swslam::app
{
struct Rawlog2BagRunOptions
{
  io::Rawlog2BagOptions conversion;
  bool overwrite = false;  ///< replace an existing output (else it is an error)
};

/** Runs; prints what it wrote to `out`. Returns 0, or 1 after printing the problem to `err`
 * (nothing written). */
int runRawlog2Bag(const Rawlog2BagRunOptions& opts, std::ostream& out, std::ostream& err);

}  // namespace swslam::app
