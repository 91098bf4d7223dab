#include <swslam/map/scan_contribution.h>

#include <swslam/sensor/scan.h>

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace swslam::map
{
mrpt::maps::COccupancyGridMap2D::TInsertionOptions insertionOptions(const MapParams& p)
{
  mrpt::maps::COccupancyGridMap2D::TInsertionOptions o;
  o.maxDistanceInsertion = static_cast<float>(p.max_insertion_range);
  o.maxOccupancyUpdateCertainty = static_cast<float>(p.prob_occupied);
  // MRPT's cells hold the log-odds of being free: its "freeness certainty" is 1 - prop_free.
  o.maxFreenessUpdateCertainty = static_cast<float>(1 - p.prob_free);
  o.considerInvalidRangesAsFreeSpace = false;  // a ray without a return tells nothing
  o.decimation = 1;
  o.horizontalTolerance = static_cast<float>(p.horizontal_tolerance);
  o.wideningBeamsWithDistance = false;  // plain Bresenham-like rays, as the paper
  return o;
}

namespace
{
// MRPT grows a grid when a scan point comes within 15 cells of its border: stay clear.
constexpr int kScratchMarginCells = 20;
}  // namespace

mrpt::obs::CObservation2DRangeScan sanitizedScan(const mrpt::obs::CObservation2DRangeScan& obs,
                                                 const MapParams& params)
{
  // Same geometry checks and the same valid rays as the scan matcher.
  const sensor::Scan valid = sensor::scanFromObservation(obs);
  if (!obs.isPlanarScan(params.horizontal_tolerance))
    throw std::invalid_argument("map: scan '" + obs.sensorLabel + "' is not horizontal (sensor pose " +
                                obs.sensorPose.asString() + ")");
  const size_t n = obs.getScanSize();
  mrpt::obs::CObservation2DRangeScan out = obs;
  // MRPT 2.5's grid insertion steps its rays by aperture/N from -aperture/2, while the scan's
  // rays are aperture/(N-1) apart (CObservation2DRangeScan, CSinCosLookUpTableFor2DScans):
  // its last ray would be one step off. Widen the aperture to N/(N-1) of itself and turn the
  // sensor by half the widening so that MRPT traces every ray at its true angle.
  const double widened = obs.aperture * static_cast<double>(n) / static_cast<double>(n - 1);
  const bool upside_down = obs.sensorPose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>()(2, 2) < 0;
  const double turn = ((obs.rightToLeft != upside_down) ? 0.5 : -0.5) * (widened - obs.aperture);
  out.aperture = static_cast<float>(widened);
  out.sensorPose.setYawPitchRoll(obs.sensorPose.yaw() + turn, obs.sensorPose.pitch(),
                                 obs.sensorPose.roll());
  // A reading flagged valid but NaN, non-positive or at the max range is "no return".
  for (size_t i = 0; i < n; i++) out.setScanRangeValidity(i, false);
  for (int i : valid.beam_index) out.setScanRangeValidity(static_cast<size_t>(i), true);
  return out;
}

ScanContribution computeContribution(const mrpt::obs::CObservation2DRangeScan& obs,
                                     const mrpt::poses::CPose2D& vehicle_pose,
                                     const MapParams& params)
{
  ContributionScratch scratch;
  return computeContribution(obs, vehicle_pose, params, scratch);
}

ScanContribution computeContribution(const mrpt::obs::CObservation2DRangeScan& obs,
                                     const mrpt::poses::CPose2D& vehicle_pose,
                                     const MapParams& params, ContributionScratch& scratch_memory)
{
  if (!std::isfinite(vehicle_pose.x()) || !std::isfinite(vehicle_pose.y()) ||
      !std::isfinite(vehicle_pose.phi()))
    throw std::invalid_argument("map: vehicle pose " + vehicle_pose.asString() + " is not finite");
  const double res = params.resolution;
  const double max_range = params.max_insertion_range;
  const mrpt::poses::CPose2D sensor = vehicle_pose + mrpt::poses::CPose2D(obs.sensorPose);
  const double reach_limit = kMaxMapCellIndex * res / 2;  // the scan's reach stays inside too
  if (!(std::abs(sensor.x()) < reach_limit && std::abs(sensor.y()) < reach_limit))
    throw std::invalid_argument("map: the sensor at " + sensor.asString() + " (vehicle pose " +
                                vehicle_pose.asString() + ", sensor pose " + obs.sensorPose.asString() +
                                ") is farther than " + std::to_string(reach_limit) +
                                " m from the origin on an axis (" + std::to_string(kMaxMapCellIndex / 2) +
                                " cells of " + std::to_string(res) +
                                " m): a corrupt pose (bad odometry or sensor pose?)");

  // Farthest point MRPT may touch: valid rays are cut at max_range (rays without a return
  // insert nothing).
  double reach = 0;
  for (size_t i = 0; i < obs.getScanSize(); i++)
    if (obs.getScanRangeValidity(i)) reach = std::max(reach, std::min<double>(max_range, obs.getScanRange(i)));
  const int half = static_cast<int>(std::ceil(reach / res)) + kScratchMarginCells;
  const int cx = cellOf(sensor.x(), res), cy = cellOf(sensor.y(), res);
  const CellBox box{cx - half, cy - half, cx + half + 1, cy + half + 1};

  // setSize() refills the grid with 0.5 and keeps its memory when it is large enough.
  mrpt::maps::COccupancyGridMap2D& scratch = scratch_memory.grid;
  scratch.setSize(static_cast<float>(box.x0 * res), static_cast<float>(box.x1 * res),
                  static_cast<float>(box.y0 * res), static_cast<float>(box.y1 * res),
                  static_cast<float>(res), 0.5f);
  scratch.insertionOptions = insertionOptions(params);
  if (!scratch.insertObservation(obs, mrpt::poses::CPose3D(vehicle_pose)))
    throw std::invalid_argument("map: MRPT refused to insert scan '" + obs.sensorLabel + "'");
  // The scratch grid is aligned on global cells; it cannot have grown, but read its origin back.
  const int gx0 = static_cast<int>(std::lround(scratch.getXMin() / res));
  const int gy0 = static_cast<int>(std::lround(scratch.getYMin() / res));

  ScanContribution c;
  c.box = CellBox{INT32_MAX, INT32_MAX, INT32_MIN, INT32_MIN};
  const int w = static_cast<int>(scratch.getSizeX());
  for (int y = 0; y < static_cast<int>(scratch.getSizeY()); y++)
  {
    const auto* row = scratch.getRow(y);
    int first = 0, last = w - 1;
    while (first < w && row[first] == 0) first++;
    if (first == w) continue;
    while (row[last] == 0) last--;
    const uint32_t length = static_cast<uint32_t>(last - first + 1);
    c.runs.push_back({gy0 + y, gx0 + first, static_cast<uint32_t>(c.deltas.size()), length});
    c.deltas.insert(c.deltas.end(), row + first, row + last + 1);
    c.box.x0 = std::min(c.box.x0, gx0 + first);
    c.box.x1 = std::max(c.box.x1, gx0 + last + 1);
    c.box.y0 = std::min(c.box.y0, gy0 + y);
    c.box.y1 = std::max(c.box.y1, gy0 + y + 1);
  }
  if (c.runs.empty()) c.box = CellBox{};
  return c;
}

}  // namespace swslam::map
