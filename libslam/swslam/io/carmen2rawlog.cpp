#include <swslam/io/carmen2rawlog.h>

#include <swslam/common/gzip_output.h>
#include <swslam/common/tum_io.h>

#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace swslam::io
{
CarmenStats carmen2rawlog(const Carmen2RawlogOptions& opts, CarmenLogReader::WarningSink warn)
{
  if (opts.compress_level < 0 || opts.compress_level > 9)
    throw std::invalid_argument("carmen2rawlog: compress level must be in 0..9, got " +
                                std::to_string(opts.compress_level));
  // The log's ODOM lines would mix with the reference odometry, and a reading stamped before
  // the previous one is dropped by a reader (the motion then comes out wrong).
  if (opts.reference_odometry && (!opts.params.laser_only || !opts.params.repair_timestamps))
    throw std::invalid_argument(
        "carmen2rawlog: reference odometry needs laser-only conversion with repaired timestamps "
        "(--laser-only --repair-timestamps)");
  // Two of the files the same (however spelled) would write one over the other, or over the log.
  const auto same = [](const std::string& a, const std::string& b) {
    std::error_code ec;
    return !a.empty() && !b.empty() &&
           std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec);
  };
  if (same(opts.output, opts.input) || same(opts.ground_truth, opts.input) || same(opts.ground_truth, opts.output))
    throw std::invalid_argument("carmen2rawlog: the input '" + opts.input + "', the rawlog '" + opts.output +
                                "' and the ground truth '" + opts.ground_truth + "' must be different files");
  CarmenLogReader reader(opts.input, opts.params, std::move(warn));
  std::vector<common::StampedPose> reference;
  std::string damage;
  // What the input could not give is no failure to write the rawlog: said as itself.
  std::optional<std::runtime_error> unreadable;
  const auto fail = [&](const std::string& why) {
    unreadable.emplace(why);
    throw *unreadable;
  };
  try
  {
    common::writeGzipAtomically(opts.output, opts.compress_level, [&](mrpt::io::CStream& out) {
      auto archive = mrpt::serialization::archiveFrom(out);
      CarmenRecord rec;
      for (;;)
      {
        try
        {
          if (!reader.next(rec)) break;
        }
        catch (const GzipError& e)
        {
          // The lines before the damage are good: they are converted, and the damage said.
          damage = e.what();
          break;
        }
        catch (const std::exception& e)
        {
          fail(e.what());
        }
        if (opts.reference_odometry && rec.reference_pose)  // only scans carry one
        {
          mrpt::obs::CObservationOdometry odometry;
          odometry.sensorLabel = "REFERENCE_ODOMETRY";
          odometry.timestamp = rec.observation->timestamp;
          odometry.odometry = *rec.reference_pose;
          archive << odometry;
        }
        archive << *rec.observation;
        if (rec.reference_pose) reference.push_back({rec.timestamp, *rec.reference_pose});
      }
      if (reader.stats().scans() == 0 && !damage.empty()) fail("carmen2rawlog: " + damage);
      if (reader.stats().scans() == 0) fail("carmen2rawlog: no laser scan in '" + opts.input + "' (is it a CARMEN log?)");
    });
  }
  catch (const std::exception&)
  {
    if (unreadable) throw *unreadable;
    throw;
  }
  if (!opts.ground_truth.empty()) common::writeTum(opts.ground_truth, reference);
  CarmenStats stats = reader.stats();
  stats.damage = damage;
  return stats;
}

std::string formatCarmenStats(const CarmenStats& s)
{
  std::ostringstream o;
  o << "scans: " << s.scans() << "\n";
  for (const auto& [label, l] : s.lasers)
  {
    o << "  " << label << ": " << l.scans << " scans, beams " << l.min_beams;
    if (l.max_beams != l.min_beams) o << ".." << l.max_beams;
    o << ", aperture " << l.aperture * 180 / M_PI << " deg, max_range " << l.max_range
      << " m (" << l.max_range_source << "), invalid rays " << l.invalid_rays << " of "
      << l.rays << "\n";
  }
  o << "odometry: " << s.odometry;
  const bool fields = s.odometry_source == CarmenOdometrySource::LaserFields;
  if (s.odometry_source == CarmenOdometrySource::None)
    o << " (the log has none)";
  else if (s.odometry_dropped)
    o << " (" << s.odometry_dropped << (fields ? " laser-line odometry readings" : " ODOM lines")
      << " dropped: laser only)";
  else
    o << (fields ? " (from the FLASER/RLASER odom_x odom_y odom_theta fields: the log has no ODOM lines)"
                 : " (from the ODOM lines)");
  o << "\nPARAM lines: " << s.params << "\n";
  o << "malformed lines: " << s.malformed;
  if (s.malformed) o << " (first at line " << s.first_malformed_line << ")";
  o << "\n";
  for (const auto& [msg, n] : s.unknown_messages)
    o << "skipped " << msg << " lines: " << n << " (message type not converted)\n";
  o << "timestamp problems: " << s.timestampProblems() << "\n";
  for (const auto& [stream, t] : s.timestamps)
  {
    o << "  ";
    o << stream << ": " << t.count << " stamps, " << t.non_increasing << " non-increasing, "
      << t.forward_jumps << " forward jumps";
    if (t.negative) o << ", " << t.negative << " negative (written as 0)";
    if (t.out_of_range) o << ", " << t.out_of_range << " out of range (lines skipped)";
    if (s.repairing)
      o << "; repaired " << t.repaired << " (period " << t.repair_period << " s)";
    else if (t.non_increasing + t.forward_jumps > 0)
      o << "; kept as logged (use --repair-timestamps)";
    o << "\n";
  }
  if (s.timestamp_offset != 0)
    o << "laser timestamps negative: all timestamps shifted by +" << s.timestamp_offset
      << " s (negative times are not representable in MRPT)\n";
  if (s.geometry_warnings) o << "geometry warnings: " << s.geometry_warnings << "\n";
  if (s.saturation_glitches) o << "readings above the saturation value (no return): " << s.saturation_glitches << "\n";
  if (!s.damage.empty()) o << "input damaged, converted up to there: " << s.damage << "\n";
  return o.str();
}

}  // namespace swslam::io
