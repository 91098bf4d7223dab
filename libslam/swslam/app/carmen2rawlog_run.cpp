#include <swslam/app/carmen2rawlog_run.h>

#include <swslam/app/exit_codes.h>
#include <swslam/io/carmen2rawlog.h>

#include <filesystem>
#include <ostream>
#include <stdexcept>

namespace swslam::app
{
int runCarmen2Rawlog(const Carmen2RawlogRunOptions& o, std::ostream& out, std::ostream& err)
{
  return exitCodeOf("swslam-carmen2rawlog", err, [&] {
    for (const auto& path : {o.output, o.ground_truth})
      if (!path.empty() && std::filesystem::exists(path) && !o.overwrite)
        throw std::runtime_error("'" + path + "' exists (use -w to overwrite)");

    io::Carmen2RawlogOptions c;
    c.input = o.input;
    c.output = o.output;
    c.ground_truth = o.ground_truth;
    c.compress_level = o.compress_level;
    c.params.max_range = o.max_range;
    c.params.laser_only = o.laser_only;
    c.params.repair_timestamps = o.repair_timestamps;
    c.reference_odometry = o.reference_odometry;
    if (o.quiet) c.params.max_printed_warnings = 0;

    const auto stats = io::carmen2rawlog(c, [&err](const std::string& m) { err << "warning: " << m << "\n"; });
    out << "wrote " << c.output;
    if (!c.ground_truth.empty()) out << " and " << c.ground_truth;
    out << "\n" << io::formatCarmenStats(stats);
    if (stats.damage.empty()) return kExitOk;
    err << "swslam-carmen2rawlog: " << stats.damage << "; wrote the " << stats.scans() << " scans before it\n";
    return kExitInputError;
  });
}

}  // namespace swslam::app
