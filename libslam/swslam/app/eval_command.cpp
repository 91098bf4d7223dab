#include <swslam/app/eval_command.h>

#include <swslam/eval/consistency.h>
#include <swslam/eval/laser_optimum.h>
#include <swslam/eval/relations_io.h>
#include <swslam/eval/report.h>
#include <swslam/app/config.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <stdexcept>

namespace swslam::app
{
namespace
{
Config runConfig(const EvalOptions& o)
{
  if (o.config.empty())
    throw std::invalid_argument(o.command + " needs --config: the run's configuration says how the log is read"
                                " and matched");
  return loadConfig(o.config);
}

void laserOptimum(const EvalOptions& o, const std::vector<common::StampedPose>& estimate, std::ostream& out)
{
  const Config config = runConfig(o);
  const system::SystemParams& params = config.system;
  auto options = eval::laserOptimumOptions(params.tracking, params.loop_closure);
  if (o.radius) options.radius = *o.radius;
  if (!(options.radius > 0))
    throw std::invalid_argument(o.radius ? "--radius must be > 0" : "[tracking] dense_radius is 0: pass --radius");
  // Fail before the matching (minutes on a long log) rather than after it.
  if (!o.output.empty())
  {
    const auto out_dir = std::filesystem::absolute(o.output).parent_path();
    if (!std::filesystem::is_directory(out_dir))
      throw std::runtime_error("cannot write '" + o.output + "': no directory '" + out_dir.string() + "'");
  }
  out << eval::laserOptimumReport(o.reference, estimate, params.plicp, params.graph_optimizer, options, o.max_dt,
                                  static_cast<size_t>(o.stride), params.tracking.min_range, config.carmen,
                                  o.sensor_label, o.output);
}

void consistency(const EvalOptions& o, const std::vector<common::StampedPose>& estimate, std::ostream& out)
{
  eval::ConsistencyOptions options;
  options.radius = o.radius.value_or(3.0);
  if (!(options.radius > 0)) throw std::invalid_argument("--radius must be > 0");
  if (o.min_gap < 0 || o.revisit_gap < 0)
    throw std::invalid_argument("--min-gap and --revisit-gap must be >= 0");
  const Config config = runConfig(o);
  const system::SystemParams& params = config.system;
  std::vector<std::string> names{o.estimate};
  std::vector<std::vector<common::StampedPose>> trajectories{estimate};
  for (const auto& other : o.compare)
  {
    names.push_back(other);
    trajectories.push_back(eval::readNonEmptyTum(other));
  }
  options.min_gap = static_cast<size_t>(o.min_gap);
  options.revisit_gap = static_cast<size_t>(o.revisit_gap);
  options.min_segment = params.plicp.min_segment_length;
  out << eval::consistencyReport(o.reference, names, trajectories, options, o.max_dt,
                                 static_cast<size_t>(o.stride), params.tracking.min_range, config.carmen,
                                 o.sensor_label);
}
}  // namespace

void runEval(const EvalOptions& o, std::ostream& out, std::ostream& err)
{
  const auto commands = evalCommands();
  if (std::find(commands.begin(), commands.end(), o.command) == commands.end())
    throw std::invalid_argument("unknown command '" + o.command + "' (ate, relations, consistency, laser-optimum)");
  if (!(o.max_dt >= 0)) throw std::invalid_argument("--max-dt must be >= 0");
  if (!(o.segment > 0)) throw std::invalid_argument("--segment must be > 0");
  if (o.stride < 1) throw std::invalid_argument("--stride must be >= 1");

  const auto estimate = eval::readNonEmptyTum(o.estimate);
  if (o.command == "laser-optimum")
    laserOptimum(o, estimate, out);
  else if (o.command == "consistency")
    consistency(o, estimate, out);
  else if (o.command == "ate")
  {
    const auto e = eval::evaluateTrajectory(estimate, eval::readNonEmptyTum(o.reference), o.max_dt, o.segment);
    if (const std::string warning = eval::unmatchedWarning(e); !warning.empty())
      err << "swslam-eval: warning: " << o.estimate << ": " << warning << "\n";
    out << eval::formatTrajectoryEvaluation(e);
  }
  else
    out << eval::formatRelationsResult(eval::evaluateRelations(estimate, eval::readRelations(o.reference), o.max_dt));
}

}  // namespace swslam::app
