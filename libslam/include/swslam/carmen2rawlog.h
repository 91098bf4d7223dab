#pragma once
// CARMEN log -> observation-only MRPT rawlog (+ TUM reference trajectory), the library
// side of swslam-carmen2rawlog.

#include <swslam/carmen_log.h>

#include <string>

namespace swslam
{
struct Carmen2RawlogOptions
{
  std::string input;             ///< CARMEN log, plain or .gz
  std::string output;            ///< rawlog to write (gzip-compressed)
  std::string ground_truth;      ///< TUM file of the scans' reference poses; empty: none
  int compress_level = 5;        ///< gzip level of the rawlog, 0-9
  CarmenParams params;
};

/** Converts, writing both outputs atomically. Throws std::runtime_error naming the
 * problem if the input cannot be read or holds no laser scan (nothing is written then). */
CarmenStats carmen2rawlog(const Carmen2RawlogOptions& opts,
                          CarmenLogReader::WarningSink warn = {});

}  // namespace swslam
