#pragma once
// The saved map's nodes as localization matches against them: each node's pose (fixed), its
// sensor's mounting and its scan, kept compact and built into PLICP's reference form when a
// scan is matched against it (plicp/reference_store.h).

#include <swslam/correlative/score_grid.h>
#include <swslam/plicp/params.h>
#include <swslam/plicp/reference_store.h>
#include <swslam/sensor/scan.h>

#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace swslam::localize
{
class MapNodes
{
 public:
  /** Node i at vehicle pose `poses[i]` (map frame) saw `scans[i]` (its sensor_pose the
   * mounting). Throws std::invalid_argument if the counts differ, there is no node, or the
   * nodes' scans come from more than one sensor (label, beam count, aperture or mounting). */
  MapNodes(const std::vector<mrpt::poses::CPose2D>& poses, std::vector<sensor::Scan> scans,
           const plicp::PlicpParams& plicp);

  size_t size() const { return poses_.size(); }
  const mrpt::poses::CPose2D& pose(size_t id) const { return poses_.at(id); }
  /** Node id's sensor pose in the map frame. */
  mrpt::poses::CPose2D sensorPose(size_t id) const { return poses_.at(id) + mounts_.at(id); }
  std::shared_ptr<const plicp::ReferenceScan> reference(size_t id) const { return store_.get(id); }

  /** The node whose sensor pose is nearest `sensor_pose` (map frame): least distance plus
   * `rotation_length` times the heading difference (a turn moves the points that much). */
  size_t nearest(const mrpt::poses::CPose2D& sensor_pose, double rotation_length) const;

  /** Gives `scan` the map's sensor's identity (node 0's label, beam count, aperture and
   * mounting), which PLICP requires of the two scans it matches (plicp.h): a log of the same
   * scanner under another label, or of another 2D scanner, matches the map's nodes. The match
   * is between the two sensors' own frames, so the scan's points are what counts; the caller
   * keeps the scan's own mounting for its vehicle pose. */
  void asMapSensor(sensor::Scan& scan) const;

  /** The rays, up to max_range, of the `count` nodes whose sensors are nearest node id's (it
   * among them) and within 2 max_range of it (a farther node's rays reach no point of a scan
   * taken there), in node id's sensor frame: a search's reference around that node. */
  std::vector<correlative::Ray> raysAround(size_t id, size_t count, double max_range) const;

 private:
  std::vector<mrpt::poses::CPose2D> poses_, mounts_;
  std::string label_;
  size_t beam_count_ = 0;
  double aperture_ = 0;
  plicp::ReferenceStore store_;
};

}  // namespace swslam::localize
