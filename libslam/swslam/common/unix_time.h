#pragma once
// The range of timestamps taken as physical: Unix time in seconds from 1970 to 2200. MRPT's
// clock cannot hold much more (its 100 ns ticks since 1601 overflow near the year 30800, and
// times before 1970 wrap), so a stamp beyond it came out of a conversion as 0 while the
// reference file kept it: microseconds instead of seconds, or one damaged stamp, left a run one
// usable scan. Such a stamp is reported, never passed on.

#include <string>

namespace swslam::common
{
/** 2200-01-01T00:00:00Z, in seconds since 1970. */
constexpr double kLatestPlausibleTime = 7258118400.0;

/** True if `t` [s] is a finite Unix time in [1970, 2200). */
bool plausibleUnixTime(double t);

/** For a stamp beyond the range: " (milliseconds rather than seconds?)" (or microseconds,
 * nanoseconds) if dividing by that unit brings it into the range, else "". */
std::string timeUnitHint(double t);

}  // namespace swslam::common
