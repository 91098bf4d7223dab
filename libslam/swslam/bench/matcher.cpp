#include <swslam/bench/matcher.h>

#include <swslam/correlative/search.h>
#include <swslam/correlative/search_setup.h>
#include <swslam/geometry/sensor_frame.h>
#include <swslam/io/rawlog_reader.h>
#include <swslam/plicp/correspondences.h>
#include <swslam/plicp/run.h>
#include <swslam/tracking/scan_matcher.h>

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/slam/CICP.h>
#include <mrpt/system/CTicTac.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>

namespace swslam::bench
{
namespace
{
using mrpt::obs::CObservation2DRangeScan;
using mrpt::poses::CPose2D;

/** A matcher under test: relative vehicle pose of `cur` w.r.t. `ref` from `guess`, which is
 * measured (the reference motion, as odometry or a matched motion would predict it) or a mere
 * guess (identity: no prediction). */
struct Estimate
{
  CPose2D pose;
  int iterations = 0;
  bool ok = true;
  bool searched = false;  ///< the correlative search ran
};
using MatcherFn = std::function<Estimate(const CObservation2DRangeScan&, const CObservation2DRangeScan&,
                                         const CPose2D& guess, bool guess_measured)>;

double quantile(std::vector<double> v, double q)
{
  if (v.empty()) return 0;
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(q * (v.size() - 1) + 0.5));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

MatcherFn plicpMatcher(const plicp::PlicpParams& params)
{
  return [params](const CObservation2DRangeScan& a, const CObservation2DRangeScan& b,
                  const CPose2D& guess, bool) {
    // PLICP works in the sensor frame: convert the vehicle-frame guess and result.
    const CPose2D s(a.sensorPose);
    const plicp::ReferenceScan ref(sensor::scanFromObservation(a), params);
    const plicp::MatchResult r = plicp::matchScans(ref, sensor::scanFromObservation(b), geometry::sensorMotion(s, guess), params);
    return Estimate{geometry::vehicleMotion(s, r.pose), r.iterations, r.ok()};
  };
}

/** PLICP as tracking uses it: tracking's scan matcher (tracking::ScanMatcher: the match, the
 * correlative search when the match or an unmeasured guess calls for it, the choice), against
 * the reference scan alone, whose rays the search's grid holds (built per pair, and timed). A
 * match the search's choice leaves unmatched counts as failed, at the guess. */
MatcherFn plicpSearchMatcher(const plicp::PlicpParams& params, const correlative::CorrelativeParams& search,
                             const tracking::TrackingParams& tracking)
{
  const tracking::ScanForms forms{params, search.resolution, search.max_range};
  return [params, search, tracking, forms](const CObservation2DRangeScan& a, const CObservation2DRangeScan& b,
                                           const CPose2D& guess, bool guess_measured) {
    const CPose2D s(a.sensorPose);
    const auto ref = std::make_shared<const plicp::ReferenceScan>(sensor::scanFromObservation(a), params);
    const tracking::Submap submap(ref, [&] { return correlative::scanRays(ref->scan, search.max_range); });
    const tracking::PreparedScan cur(sensor::scanFromObservation(b), forms);
    tracking::Prediction prediction;
    prediction.guess = geometry::sensorMotion(s, guess);
    prediction.measured = guess_measured;
    const tracking::ScanMatch m = tracking::ScanMatcher(tracking, params, search).match(submap, cur, prediction);
    if (m.unmatched) return Estimate{guess, m.iterations, false, m.searched};
    return Estimate{geometry::vehicleMotion(s, m.match.pose), m.iterations, m.match.ok(), m.searched};
  };
}

MatcherFn cicpMatcher(mrpt::slam::TICPAlgorithm algorithm)
{
  return [algorithm](const CObservation2DRangeScan& a, const CObservation2DRangeScan& b,
                     const CPose2D& guess, bool) {
    mrpt::maps::CSimplePointsMap m1, m2;
    m1.insertObservation(a);
    m2.insertObservation(b);
    mrpt::slam::CICP icp;  // MRPT's default parameters
    icp.options.ICP_algorithm = algorithm;
    mrpt::slam::CICP::TReturnInfo info;
    const auto pdf = icp.Align(&m1, &m2, guess, info);
    return Estimate{pdf->getMeanVal(), static_cast<int>(info.nIterations), true};
  };
}
}  // namespace

std::vector<MatcherRow> benchmarkMatchers(const io::ScansWithTruth& data, size_t stride,
                                          const plicp::PlicpParams& plicp_params, const std::string& only,
                                          const correlative::CorrelativeParams& search_params,
                                          const tracking::TrackingParams& tracking)
{
  std::vector<std::pair<std::string, MatcherFn>> methods = {
      {"plicp", plicpMatcher(plicp_params)},
      {"plicp+search", plicpSearchMatcher(plicp_params, search_params, tracking)},
      {"cicp-classic", cicpMatcher(mrpt::slam::icpClassic)},
      {"cicp-lm", cicpMatcher(mrpt::slam::icpLevenbergMarquardt)}};
  if (!only.empty())
  {
    const auto it = std::find_if(methods.begin(), methods.end(),
                                 [&](const auto& m) { return m.first == only; });
    if (it == methods.end())
      throw std::invalid_argument("unknown matcher '" + only +
                                  "' (expected plicp, plicp+search, cicp-classic or cicp-lm)");
    methods = {*it};
  }
  std::vector<MatcherRow> rows;
  for (const std::string init : {"identity", "reference"})
  {
    for (const auto& [name, match] : methods)
    {
      MatcherRow row;
      row.method = name;
      row.init = init;
      std::vector<double> times_us, trans_err;
      double sq_t = 0, sq_r = 0, iters = 0;
      for (size_t k = 0; k + stride < data.scans.size(); k += stride)
      {
        const CPose2D ref_motion = data.truth[k + stride] - data.truth[k];
        const CPose2D guess = init == "identity" ? CPose2D() : ref_motion;
        mrpt::system::CTicTac timer;
        const Estimate e = match(*data.scans[k], *data.scans[k + stride], guess, init == "reference");
        times_us.push_back(timer.Tac() * 1e6);
        const double et = (e.pose.translation() - ref_motion.translation()).norm();
        const double er = std::remainder(e.pose.phi() - ref_motion.phi(), 2 * M_PI);
        trans_err.push_back(et);
        sq_t += et * et;
        sq_r += er * er;
        iters += e.iterations;
        row.failures += e.ok ? 0 : 1;
        row.searched += e.searched ? 1 : 0;
        row.pairs++;
        row.estimates.push_back({e.pose, e.ok});
      }
      if (row.pairs == 0) continue;
      row.median_us = quantile(times_us, 0.5);
      row.p95_us = quantile(times_us, 0.95);
      row.mean_iters = iters / row.pairs;
      row.trans_median_m = quantile(trans_err, 0.5);
      row.trans_rmse_m = std::sqrt(sq_t / row.pairs);
      row.rot_rmse_deg = std::sqrt(sq_r / row.pairs) * 180 / M_PI;
      row.frac_under_5cm =
          std::count_if(trans_err.begin(), trans_err.end(), [](double x) { return x < geometry::kMotionAgreement; }) /
          static_cast<double>(row.pairs);
      rows.push_back(row);
    }
  }
  return rows;
}

PlicpFloor plicpFloor(const io::ScansWithTruth& data, size_t stride, const plicp::PlicpParams& params)
{
  PlicpFloor f;
  std::vector<double> conversion, index, search, total;
  for (size_t k = 0; k + stride < data.scans.size(); k += stride)
  {
    const CObservation2DRangeScan& a = *data.scans[k];
    const CPose2D guess =
        geometry::sensorMotion(CPose2D(a.sensorPose), data.truth[k + stride] - data.truth[k]);
    mrpt::system::CTicTac timer;
    sensor::Scan ref_scan = sensor::scanFromObservation(a);
    const sensor::Scan cur = sensor::scanFromObservation(*data.scans[k + stride]);
    const double t_conversion = timer.Tac();
    timer.Tic();
    const plicp::ReferenceScan ref(std::move(ref_scan), params);
    const double t_index = timer.Tac();
    timer.Tic();
    plicp::findCorrespondences(
        ref.scan, ref.index, plicp::transformed(cur, Eigen::Vector3d(guess.x(), guess.y(), guess.phi())),
        params.max_correspondence_dist);
    const double t_search = timer.Tac();
    conversion.push_back(t_conversion * 1e6);
    index.push_back(t_index * 1e6);
    search.push_back(t_search * 1e6);
    total.push_back((t_conversion + t_index + t_search) * 1e6);
  }
  f.pairs = total.size();
  f.conversion_us = quantile(conversion, 0.5);
  f.index_us = quantile(index, 0.5);
  f.search_us = quantile(search, 0.5);
  f.total_us = quantile(total, 0.5);
  return f;
}

std::string formatFloor(const PlicpFloor& f)
{
  char buf[256];
  std::snprintf(buf, sizeof(buf),
                "%-13s init=%-9s pairs=%zu median_us=%.1f conversion_us=%.1f index_us=%.1f "
                "search_us=%.1f",
                "plicp-floor", "reference", f.pairs, f.total_us, f.conversion_us, f.index_us,
                f.search_us);
  return buf;
}

SearchFloor searchFloor(const io::ScansWithTruth& data, size_t stride, const plicp::PlicpParams& plicp_params,
                        const correlative::CorrelativeParams& search_params, const tracking::TrackingParams& tracking)
{
  SearchFloor f;
  std::vector<double> first, grid, bnb, total, evaluated;
  // Identity is a guess: with search_first_match it is searched first, and PLICP runs from the
  // search's best pose; else PLICP from identity runs first, and the search only if it says so.
  const bool search_first = tracking::searchFirst(false, tracking.search_first_match);
  for (size_t k = 0; k + stride < data.scans.size(); k += stride)
  {
    const CObservation2DRangeScan& a = *data.scans[k];
    const CPose2D guess = geometry::sensorMotion(CPose2D(a.sensorPose), CPose2D());
    f.pairs++;
    mrpt::system::CTicTac timer;
    const plicp::ReferenceScan ref(sensor::scanFromObservation(a), plicp_params);
    const sensor::Scan cur = sensor::scanFromObservation(*data.scans[k + stride]);
    const double t_scans = timer.Tac();
    double t_plicp = 0;
    if (!search_first)
    {
      timer.Tic();
      const plicp::MatchResult m = plicp::matchScans(ref, cur, guess, plicp_params);
      t_plicp = timer.Tac();
      if (!tracking::searchNeeded(tracking::searchTrigger(m, guess, tracking), false, false, false))
        continue;
    }
    f.searched++;
    timer.Tic();
    const correlative::ScorePyramid pyramid =
        correlative::searchPyramid(correlative::scanRays(ref.scan, search_params.max_range), search_params);
    const double t_grid = timer.Tac();
    timer.Tic();
    const auto best = correlative::searchBranchAndBound(
        pyramid, correlative::thinPoints(cur.points, search_params.resolution, search_params.max_range),
        correlative::searchWindow(search_params, guess), search_params.min_score);
    const double t_bnb = timer.Tac();
    if (best)
    {
      evaluated.push_back(static_cast<double>(best->bounds_evaluated));
      const size_t levels = best->evaluated_by_level.size();
      if (f.evaluated_by_level.size() < levels)
      {
        f.evaluated_by_level.resize(levels, 0.0);
        f.expanded_by_level.resize(levels, 0.0);
      }
      for (size_t h = 0; h < levels; h++)
      {
        f.evaluated_by_level[h] += static_cast<double>(best->evaluated_by_level[h]);
        f.expanded_by_level[h] += static_cast<double>(best->expanded_by_level[h]);
      }
    }
    if (search_first)
    {
      timer.Tic();
      plicp::matchScans(ref, cur, best ? CPose2D(best->pose.x(), best->pose.y(), best->pose.z()) : guess, plicp_params);
      t_plicp = timer.Tac();
    }
    first.push_back((t_scans + t_plicp) * 1e6);
    grid.push_back(t_grid * 1e6);
    bnb.push_back(t_bnb * 1e6);
    total.push_back((t_scans + t_plicp + t_grid + t_bnb) * 1e6);
  }
  f.plicp_us = quantile(first, 0.5);
  f.grid_us = quantile(grid, 0.5);
  f.bnb_us = quantile(bnb, 0.5);
  f.total_us = quantile(total, 0.5);
  f.evaluated_median = evaluated.empty() ? 0.0 : quantile(evaluated, 0.5);
  for (size_t h = 0; h < f.evaluated_by_level.size(); h++)
  {
    f.evaluated_by_level[h] /= static_cast<double>(evaluated.size());
    f.expanded_by_level[h] /= static_cast<double>(evaluated.size());
  }
  return f;
}

std::string formatSearchFloor(const SearchFloor& f)
{
  char buf[256];
  std::snprintf(buf, sizeof(buf),
                "%-13s init=%-9s pairs=%zu searched=%zu median_us=%.1f plicp_us=%.1f grid_us=%.1f bnb_us=%.1f "
                "evaluated_median=%.0f by_level=",
                "search-floor", "identity", f.pairs, f.searched, f.total_us, f.plicp_us, f.grid_us, f.bnb_us,
                f.evaluated_median);
  std::string out = buf;
  for (size_t k = f.evaluated_by_level.size(); k-- > 0;)
  {
    std::snprintf(buf, sizeof(buf), "%.0f/%.0f%s", f.evaluated_by_level[k], f.expanded_by_level[k], k > 0 ? "," : "");
    out += buf;
  }
  return out;
}

MissExplanation explainMisses(const io::ScansWithTruth& data, size_t stride, const MatcherRow& from_identity,
                              const plicp::PlicpParams& plicp_params,
                              const correlative::CorrelativeParams& search_params)
{
  if (from_identity.method != "plicp+search" || from_identity.init != "identity")
    throw std::invalid_argument("explainMisses: needs the plicp+search row from identity, not " +
                                from_identity.method + " from " + from_identity.init);
  MissExplanation out;
  for (size_t k = 0; k + stride < data.scans.size(); k += stride, out.pairs++)
  {
    if (out.pairs >= from_identity.estimates.size())
      throw std::invalid_argument("explainMisses: the row has fewer pairs than the data at this stride");
    const MatcherRow::PairEstimate& e = from_identity.estimates[out.pairs];
    const CObservation2DRangeScan& a = *data.scans[k];
    const CObservation2DRangeScan& b = *data.scans[k + stride];
    const CPose2D ref_motion = data.truth[k + stride] - data.truth[k];
    if ((e.pose.translation() - ref_motion.translation()).norm() < geometry::kMotionAgreement) continue;
    out.misses++;
    // Both poses' own PLICP matches, in the reference sensor frame.
    const CPose2D s(a.sensorPose);
    const plicp::ReferenceScan ref(sensor::scanFromObservation(a), plicp_params);
    const sensor::Scan cur = sensor::scanFromObservation(b);
    const plicp::MatchResult at_ref = plicp::matchScans(ref, cur, geometry::sensorMotion(s, ref_motion), plicp_params);
    if (!at_ref.ok() ||
        (geometry::vehicleMotion(s, at_ref.pose).translation() - ref_motion.translation()).norm() >= geometry::kMotionAgreement)
      continue;  // no optimum of the pair at the reference
    const plicp::MatchResult at_chosen = plicp::matchScans(ref, cur, geometry::sensorMotion(s, e.pose), plicp_params);
    if (!e.ok || !at_chosen.ok() || at_ref.inliers > at_chosen.inliers)
    {
      out.supported++;
      continue;
    }
    const correlative::ScorePyramid pyramid =
        correlative::searchPyramid(correlative::scanRays(ref.scan, search_params.max_range), search_params);
    const auto points = correlative::thinPoints(cur.points, search_params.resolution, search_params.max_range);
    auto score = [&](const CPose2D& p) {
      return correlative::scoreAt(pyramid.levels.front(), points, Eigen::Vector3d(p.x(), p.y(), p.phi()));
    };
    if (score(at_ref.pose) > score(at_chosen.pose)) out.supported++;
  }
  if (out.pairs != from_identity.estimates.size())
    throw std::invalid_argument("explainMisses: the row has more pairs than the data at this stride");
  if (out.pairs > 0) out.best_share = static_cast<double>(out.pairs - out.misses + out.supported) / out.pairs;
  return out;
}

std::string formatMisses(const MissExplanation& m)
{
  char buf[256];
  std::snprintf(buf, sizeof(buf), "%-13s init=%-9s pairs=%zu misses=%zu supported=%zu best_frac_under_5cm=%.3f",
                "misses", "identity", m.pairs, m.misses, m.supported, m.best_share);
  return buf;
}

std::string formatRow(const MatcherRow& r)
{
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "%-13s init=%-9s pairs=%zu median_us=%.1f p95_us=%.1f iters=%.1f "
                "trans_median_m=%.4f trans_rmse_m=%.4f rot_rmse_deg=%.3f frac_under_5cm=%.3f "
                "failures=%zu",
                r.method.c_str(), r.init.c_str(), r.pairs, r.median_us, r.p95_us, r.mean_iters,
                r.trans_median_m, r.trans_rmse_m, r.rot_rmse_deg, r.frac_under_5cm, r.failures);
  std::string row = buf;
  if (r.method == "plicp+search") row += " searched=" + std::to_string(r.searched);
  return row;
}

}  // namespace swslam::bench
