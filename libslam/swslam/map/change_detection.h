#pragma once
// What changed between two surveys of a place (doc/sessions.md, "What changed"). Each survey's
// rays are counted in two grids: the hits (the cell at a ray's end) and the crossings (the
// cells a ray passes). A cell changed where one survey saw it solid (hit often, crossed no
// more often than hit: not vegetation that rays pass through) and the other saw it open
// (crossed often, never hit), with no hit of that other survey within a tolerance (a pose
// error of centimetres moves an edge, not an object). Changed cells are grouped into
// 8-connected regions; a region whose bounding box is shorter than min_extent on both sides
// is left out.

#include <swslam/map/params.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace swslam::map
{
class MapBuilder;

/** One survey's rays, counted: how often each cell was hit and crossed (exact counts, not
 * clamped as MRPT's cells are), on the map's cell lattice. */
class SurveyEvidence
{
 public:
  explicit SurveyEvidence(const MapParams& params);
  ~SurveyEvidence();
  SurveyEvidence(SurveyEvidence&&) noexcept;
  /** Counts node `id`'s rays from `vehicle_pose` (as MapBuilder::insert). */
  void insert(size_t id, const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& vehicle_pose);
  /** Hits of the cell holding global cell (gx, gy) (floor(x / resolution)); 0 outside. */
  int hits(int gx, int gy) const;
  int crossings(int gx, int gy) const;
  double resolution() const { return resolution_; }
  /** The global cells observed (hit or crossed), as a box [x0, x1) x [y0, y1). */
  void bounds(int& x0, int& y0, int& x1, int& y1) const;

 private:
  double resolution_;
  std::unique_ptr<MapBuilder> weighed_, reweighed_;  ///< the same rays under two weighings of hits and crossings
  int hit_ = 0, crossing_ = 0, hit2_ = 0, crossing2_ = 0;  ///< what one hit / crossing adds under each
  int64_t determinant_ = 0;
};

struct ChangeParams
{
  int solid_hits = 2;          ///< a solid cell is hit at least this often...
  double max_crossing_share = 1.0;  ///< ...and crossed at most this many times per hit
  int open_crossings = 5;      ///< an open cell is crossed at least this often, never hit
  double tolerance = 0.4;      ///< [m] no hit of the open survey within this of a changed cell
  double min_extent = 0.8;     ///< [m] a region's bounding box is at least this long on one side (a 1 m change at 0.2 m cells)
};

enum class ChangeKind
{
  Appeared,     ///< open before, solid now
  Disappeared,  ///< solid before, open now
};
const char* toString(ChangeKind k);

struct ChangeRegion
{
  ChangeKind kind = ChangeKind::Appeared;
  std::vector<std::pair<int, int>> cells;  ///< global cells (floor(x / resolution), floor(y / resolution))
  double x = 0, y = 0;                     ///< [m] centroid of the cells' centres
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;   ///< [m] bounding box of the cells
  double area = 0;                         ///< [m^2]
  double extent() const { return std::max(x1 - x0, y1 - y0); }
};

struct ChangeReport
{
  std::vector<ChangeRegion> regions;  ///< appeared first, then disappeared; larger first within each
  size_t compared_cells = 0;          ///< cells both surveys observed
  double resolution = 0;
  size_t count(ChangeKind k) const;
  double area(ChangeKind k) const;
};

/** The changes from `before` to `after`. Throws std::invalid_argument if their resolutions
 * differ. */
ChangeReport detectChanges(const SurveyEvidence& before, const SurveyEvidence& after,
                           const ChangeParams& params = ChangeParams());

}  // namespace swslam::map
