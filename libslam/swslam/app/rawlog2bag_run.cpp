#include <swslam/app/rawlog2bag_run.h>

#include <swslam/app/exit_codes.h>

#include <filesystem>
#include <ostream>
#include <stdexcept>

namespace swslam::app
{
int runRawlog2Bag(const Rawlog2BagRunOptions& o, std::ostream& out, std::ostream& err)
{
  return exitCodeOf("swslam-rawlog2bag", err, [&] {
    const io::Rawlog2BagOptions& c = o.conversion;
    if (std::filesystem::exists(c.output) && !o.overwrite)
      throw std::runtime_error("'" + c.output + "' exists (use -w to overwrite)");
    const auto stats = io::rawlog2bag(c);
    out << "wrote " << c.output << "\n" << io::formatRawlog2BagStats(stats, c);
    return kExitOk;
  });
}

}  // namespace swslam::app
