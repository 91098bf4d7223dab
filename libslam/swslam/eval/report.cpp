#include <swslam/eval/report.h>
#include <swslam/eval/relations_io.h>

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace swslam::eval
{
namespace
{
std::string span(const std::vector<common::StampedPose>& poses)
{
  if (poses.empty()) return "no poses";
  const auto [lo, hi] = std::minmax_element(
      poses.begin(), poses.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
  char buf[96];
  std::snprintf(buf, sizeof(buf), "[%.6f, %.6f] s", lo->t, hi->t);
  return buf;
}

std::string line(const char* key, double value)
{
  char buf[128];
  std::snprintf(buf, sizeof(buf), "%s=%.6g\n", key, value);
  return buf;
}

std::string line(const char* key, size_t value)
{
  return std::string(key) + "=" + std::to_string(value) + "\n";
}
}  // namespace

std::vector<common::StampedPose> readNonEmptyTum(const std::string& path)
{
  auto poses = common::readTum(path);
  if (poses.empty()) throw std::runtime_error("'" + path + "' holds no poses");
  return poses;
}

TrajectoryEvaluation evaluateTrajectory(const std::vector<common::StampedPose>& est,
                                        const std::vector<common::StampedPose>& gt, double max_dt,
                                        double segment_length)
{
  const auto a = associate(est, gt, max_dt);
  if (a.pairs.size() < 2)
    throw std::runtime_error("only " + std::to_string(a.pairs.size()) +
                             " pose(s) associate within " + std::to_string(max_dt) +
                             " s (need 2): estimate spans " + span(est) +
                             ", ground truth " + span(gt));
  TrajectoryEvaluation e;
  e.est_poses = est.size();
  e.gt_poses = gt.size();
  e.matched = a.pairs.size();
  e.est_unmatched = a.est_unmatched;
  e.gt_unmatched = a.gt_unmatched;
  for (size_t i = 1; i < est.size(); i++) e.est_steps_back += est[i].t <= est[i - 1].t;
  e.max_dt = max_dt;
  e.segment_length = segment_length;
  e.ate = absoluteTrajectoryError(a.pairs);
  e.rpe_step = relativePoseError(a.pairs, consecutivePairs(a.pairs.size()));
  e.rpe_segment = relativePoseError(a.pairs, distancePairs(a.pairs, segment_length));
  return e;
}

std::string unmatchedWarning(const TrajectoryEvaluation& e)
{
  if (e.est_unmatched == 0) return "";
  char buf[400];
  std::snprintf(buf, sizeof(buf),
                "scored %zu of the %zu estimated poses: %zu have no ground-truth pose within %g s of their stamp",
                e.matched, e.est_poses, e.est_unmatched, e.max_dt);
  std::string s = buf;
  if (e.est_steps_back > 0)
    s += " (the estimate's stamps step back or repeat " + std::to_string(e.est_steps_back) +
         " time(s): were its scans' stamps out of order?)";
  else
    s += " (does the ground truth cover the run, at its rate?)";
  return s;
}

RelationsResult evaluateRelations(const std::vector<common::StampedPose>& est,
                                  const std::vector<Relation>& relations, double max_dt)
{
  if (relations.empty()) throw std::runtime_error("no relations to evaluate");
  const auto r = relationsError(est, relations, max_dt);
  if (r.used == 0)
  {
    std::vector<common::StampedPose> stamps;
    for (const auto& rel : relations)
    {
      stamps.push_back({rel.t1, {}});
      stamps.push_back({rel.t2, {}});
    }
    throw std::runtime_error("no relation has both stamps within " + std::to_string(max_dt) +
                             " s of an estimated pose: estimate spans " + span(est) +
                             ", relations " + span(stamps));
  }
  return r;
}

std::string formatTrajectoryEvaluation(const TrajectoryEvaluation& e)
{
  using mrpt::RAD2DEG;
  std::string s;
  s += line("est_poses", e.est_poses) + line("gt_poses", e.gt_poses);
  s += line("matched", e.matched) + line("est_unmatched", e.est_unmatched) +
       line("gt_unmatched", e.gt_unmatched) + line("max_dt", e.max_dt);
  const auto& p = e.ate.position;
  s += line("ate_rmse", p.rmse) + line("ate_mean", p.mean) + line("ate_median", p.median) +
       line("ate_max", p.max);
  s += line("align_x", e.ate.alignment.x()) + line("align_y", e.ate.alignment.y()) +
       line("align_yaw_deg", RAD2DEG(e.ate.alignment.phi()));
  s += line("rpe_pairs", e.rpe_step.translation.n) +
       line("rpe_trans_rmse", e.rpe_step.translation.rmse) +
       line("rpe_rot_rmse_deg", RAD2DEG(e.rpe_step.rotation.rmse)) +
       line("rpe_trans_within_5cm", e.rpe_step.share_within_5cm);
  s += line("rpe_seg_length", e.segment_length) +
       line("rpe_seg_pairs", e.rpe_segment.translation.n) +
       line("rpe_seg_trans_rmse", e.rpe_segment.translation.rmse) +
       line("rpe_seg_rot_rmse_deg", RAD2DEG(e.rpe_segment.rotation.rmse));

  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "# ATE %.4f m rmse (mean %.4f, median %.4f, max %.4f) over %zu associated poses;"
                " unmatched within %g s: %zu estimated, %zu ground truth\n"
                "# RPE per pose %.4f m, %.3f deg rmse (%zu pairs); per %g m of path %.4f m,"
                " %.3f deg rmse (%zu segments)\n",
                p.rmse, p.mean, p.median, p.max, e.matched, e.max_dt, e.est_unmatched,
                e.gt_unmatched, e.rpe_step.translation.rmse, RAD2DEG(e.rpe_step.rotation.rmse),
                e.rpe_step.translation.n, e.segment_length, e.rpe_segment.translation.rmse,
                RAD2DEG(e.rpe_segment.rotation.rmse), e.rpe_segment.translation.n);
  return s + buf;
}

std::string formatRelationsResult(const RelationsResult& r)
{
  using mrpt::RAD2DEG;
  const double d2 = RAD2DEG(1.0) * RAD2DEG(1.0);
  std::string s;
  s += line("relations", r.used + r.unmatched) + line("used", r.used) +
       line("unmatched", r.unmatched) + line("nonplanar", r.nonplanar);
  s += line("trans_abs_mean", r.translation.mean) + line("trans_abs_std", r.translation.stddev) +
       line("trans_sq_mean", r.translation_sq.mean) + line("trans_sq_std", r.translation_sq.stddev);
  s += line("rot_abs_mean_deg", RAD2DEG(r.rotation.mean)) +
       line("rot_abs_std_deg", RAD2DEG(r.rotation.stddev)) +
       line("rot_sq_mean_deg2", d2 * r.rotation_sq.mean) +
       line("rot_sq_std_deg2", d2 * r.rotation_sq.stddev);
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "# %zu of %zu relations used (%zu unmatched, %zu non-planar projected)\n"
                "# translational error %.4f +/- %.4f m (squared %.5f +/- %.5f m^2)\n"
                "# rotational error %.3f +/- %.3f deg (squared %.4f +/- %.4f deg^2)\n",
                r.used, r.used + r.unmatched, r.unmatched, r.nonplanar, r.translation.mean,
                r.translation.stddev, r.translation_sq.mean, r.translation_sq.stddev,
                RAD2DEG(r.rotation.mean), RAD2DEG(r.rotation.stddev), d2 * r.rotation_sq.mean,
                d2 * r.rotation_sq.stddev);
  return s + buf;
}

}  // namespace swslam::eval
