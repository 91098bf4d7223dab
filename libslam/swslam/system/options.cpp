#include <swslam/system/options.h>

namespace swslam::system
{
const common::ParamTable<SystemOptions>& SystemOptions::table()
{
  using P = SystemOptions;
  using common::atLeast;
  static const auto t =
      common::ParamTable<P>("system", "How the three modules run (doc/system.md).")
          .integer("input_queue_capacity", &P::input_queue_capacity, "", atLeast(1),
                   "threaded mode: scans waiting for tracking at most (reading waits when it is full)")
          .flag("final_full_optimization", &P::final_full_optimization, "optimize the whole graph once the input ends")
          .integer("max_printed_warnings", &P::max_printed_warnings, "", atLeast(0),
                   "skipped-scan messages printed per kind; all are counted")
          .integer("timestamp_resume_scans", &P::timestamp_resume_scans, "", atLeast(0),
                   "this many scans in order behind a stamp that jumped forward resume the log (0: never)")
          .real("timestamp_step_back", &P::timestamp_step_back, "s", common::between(0, 60),
                "a scan whose stamp equals the latest, or is at most this before it, is taken under its own stamp (0: none)")
          .integer("max_graph_lag", &P::max_graph_lag, "", atLeast(-1),
                   "threaded mode: keyframes the graph thread may lag behind tracking (0: none, as deterministic; -1: no bound)")
          .real("max_odometry_speed", &P::max_odometry_speed, "m/s", common::between(0, 1e4),
                "an odometry increment beyond this speed since the previous scan is dropped and said (0: no check)");
  return t;
}

}  // namespace swslam::system
