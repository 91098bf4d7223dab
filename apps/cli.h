#pragma once
// Command-line parsing shared by the apps. MRPT's TCLAP returns false from parse() both for
// --help/--version (after printing them) and for a bad command line (after printing the
// error): tell the two apart so that a bad command line exits non-zero.

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <cstddef>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>

namespace swslam::cli
{
/** Parses; returns the exit code to return now (0 after --help/--version, 1 after an error),
 * or nothing to go on. */
inline std::optional<int> parse(TCLAP::CmdLine& cmd, int argc, char** argv)
{
  if (cmd.parse(argc, argv)) return std::nullopt;
  for (int i = 1; i < argc; i++)
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h") ||
        !std::strcmp(argv[i], "--version"))
      return 0;
  return 1;
}

/** A count option's value (read as a signed number, so that "-3" is not taken for 2^64 - 3),
 * checked to be at least `min`. Throws std::invalid_argument naming the option otherwise. */
inline size_t count(TCLAP::ValueArg<long long>& arg, long long min)
{
  if (arg.getValue() < min)
    throw std::invalid_argument("--" + arg.getName() + " must be at least " + std::to_string(min) + ", got " +
                                std::to_string(arg.getValue()));
  return static_cast<size_t>(arg.getValue());
}
}  // namespace swslam::cli
