#include <swslam/map/change_detection.h>

#include <swslam/map/builder.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <tuple>

namespace swslam::map
{
namespace
{
/** `params` with the crossings weighed by the least update MRPT makes (certainty 0.5 still
 * changes a cell by one unit): a second weighing of the same rays. */
MapParams reweighed(MapParams params)
{
  params.prob_free = 0.5;
  return params;
}

/** What one hit and one crossing add to a cell under `params`: one ray 3 m straight ahead,
 * its end cell and a cell it crossed. */
std::pair<int, int> updatesOf(const MapParams& params)
{
  MapBuilder probe(params);
  mrpt::obs::CObservation2DRangeScan scan;
  scan.aperture = 0.01f;
  scan.maxRange = 30;
  scan.rightToLeft = true;
  scan.resizeScanAndAssign(2, 3.0f, false);
  scan.setScanRangeValidity(0, true);
  const double res = params.resolution;
  probe.insert(0, scan, mrpt::poses::CPose2D(0.5 * res, 0.5 * res, 0));
  const int end = static_cast<int>(std::floor((0.5 * res + 3.0) / res));
  const int hit = probe.cellSum(end, 0), crossing = probe.cellSum(end / 2, 0);
  if (!(hit < 0 && crossing > 0)) throw std::invalid_argument("changes: the map's probabilities make no update");
  return {-hit, crossing};
}

/** Whether survey `s` hit a cell within `r` cells of (gx, gy). */
bool hitNear(const SurveyEvidence& s, int gx, int gy, int r)
{
  for (int dy = -r; dy <= r; dy++)
    for (int dx = -r; dx <= r; dx++)
      if (dx * dx + dy * dy <= r * r && s.hits(gx + dx, gy + dy) > 0) return true;
  return false;
}

bool solid(const SurveyEvidence& s, int gx, int gy, const ChangeParams& p)
{
  const int h = s.hits(gx, gy);
  return h >= p.solid_hits && s.crossings(gx, gy) <= p.max_crossing_share * h;
}

bool open(const SurveyEvidence& s, int gx, int gy, const ChangeParams& p)
{
  return s.crossings(gx, gy) >= p.open_crossings && s.hits(gx, gy) == 0;
}

ChangeRegion regionOf(ChangeKind kind, std::vector<std::pair<int, int>> cells, double res)
{
  ChangeRegion r;
  r.kind = kind;
  r.x0 = r.y0 = 1e300;
  r.x1 = r.y1 = -1e300;
  for (const auto& [gx, gy] : cells)
  {
    r.x += (gx + 0.5) * res;
    r.y += (gy + 0.5) * res;
    r.x0 = std::min(r.x0, gx * res);
    r.y0 = std::min(r.y0, gy * res);
    r.x1 = std::max(r.x1, (gx + 1) * res);
    r.y1 = std::max(r.y1, (gy + 1) * res);
  }
  r.x /= static_cast<double>(cells.size());
  r.y /= static_cast<double>(cells.size());
  r.area = static_cast<double>(cells.size()) * res * res;
  r.cells = std::move(cells);
  return r;
}
}  // namespace

SurveyEvidence::SurveyEvidence(const MapParams& params)
    : resolution_(params.resolution),
      weighed_(std::make_unique<MapBuilder>(params)),
      reweighed_(std::make_unique<MapBuilder>(reweighed(params)))
{
  std::tie(hit_, crossing_) = updatesOf(params);
  std::tie(hit2_, crossing2_) = updatesOf(reweighed(params));
  determinant_ = static_cast<int64_t>(hit_) * crossing2_ - static_cast<int64_t>(crossing_) * hit2_;
  if (determinant_ == 0) throw std::invalid_argument("changes: the map's probabilities weigh hits and crossings alike");
}

SurveyEvidence::~SurveyEvidence() = default;
SurveyEvidence::SurveyEvidence(SurveyEvidence&&) noexcept = default;

void SurveyEvidence::insert(size_t id, const mrpt::obs::CObservation2DRangeScan& scan,
                            const mrpt::poses::CPose2D& vehicle_pose)
{
  weighed_->insert(id, scan, vehicle_pose);
  reweighed_->insert(id, scan, vehicle_pose);
}

// Each cell's two sums are -hit h + crossing c and -hit2 h + crossing2 c: solved for h and c.
int SurveyEvidence::hits(int gx, int gy) const
{
  const int64_t v = weighed_->cellSum(gx, gy), v2 = reweighed_->cellSum(gx, gy);
  return static_cast<int>(std::llround(static_cast<double>(crossing_ * v2 - crossing2_ * v) / determinant_));
}

int SurveyEvidence::crossings(int gx, int gy) const
{
  const int64_t v = weighed_->cellSum(gx, gy), v2 = reweighed_->cellSum(gx, gy);
  return static_cast<int>(std::llround(static_cast<double>(hit_ * v2 - hit2_ * v) / determinant_));
}

void SurveyEvidence::bounds(int& x0, int& y0, int& x1, int& y1) const
{
  const CellBox b = weighed_->cellBox();
  x0 = b.x0, y0 = b.y0, x1 = b.x1, y1 = b.y1;
}

const char* toString(ChangeKind k) { return k == ChangeKind::Appeared ? "appeared" : "disappeared"; }

size_t ChangeReport::count(ChangeKind k) const
{
  return static_cast<size_t>(std::count_if(regions.begin(), regions.end(), [&](const auto& r) { return r.kind == k; }));
}

double ChangeReport::area(ChangeKind k) const
{
  double a = 0;
  for (const auto& r : regions)
    if (r.kind == k) a += r.area;
  return a;
}

ChangeReport detectChanges(const SurveyEvidence& before, const SurveyEvidence& after, const ChangeParams& p)
{
  const double res = after.resolution();
  if (std::abs(before.resolution() - res) > 1e-9 * res)
    throw std::invalid_argument("changes: the surveys' resolutions differ (" + std::to_string(before.resolution()) +
                                " and " + std::to_string(res) + " m)");
  const int r = static_cast<int>(std::ceil(p.tolerance / res - 1e-9));
  ChangeReport report;
  report.resolution = res;

  // Every cell the later survey observed, against the same cell of the earlier one.
  int x0, y0, x1, y1;
  after.bounds(x0, y0, x1, y1);
  const int w = x1 - x0, h = y1 - y0;
  std::vector<int8_t> mark(static_cast<size_t>(w) * h, -1);  // -1 none, else a ChangeKind
  for (int cy = 0; cy < h; cy++)
    for (int cx = 0; cx < w; cx++)
    {
      const int gx = x0 + cx, gy = y0 + cy;
      const bool seen_after = after.hits(gx, gy) > 0 || after.crossings(gx, gy) > 0;
      const bool seen_before = before.hits(gx, gy) > 0 || before.crossings(gx, gy) > 0;
      if (!seen_after || !seen_before) continue;
      report.compared_cells++;
      if (solid(before, gx, gy, p) && open(after, gx, gy, p) && !hitNear(after, gx, gy, r))
        mark[static_cast<size_t>(cy) * w + cx] = static_cast<int8_t>(ChangeKind::Disappeared);
      else if (solid(after, gx, gy, p) && open(before, gx, gy, p) && !hitNear(before, gx, gy, r))
        mark[static_cast<size_t>(cy) * w + cx] = static_cast<int8_t>(ChangeKind::Appeared);
    }

  // 8-connected regions of one kind.
  for (int start = 0; start < w * h; start++)
  {
    if (mark[start] < 0) continue;
    const auto kind = static_cast<ChangeKind>(mark[start]);
    std::vector<std::pair<int, int>> cells;
    std::deque<int> todo{start};
    mark[start] = -1;
    while (!todo.empty())
    {
      const int k = todo.front();
      todo.pop_front();
      const int cx = k % w, cy = k / w;
      cells.emplace_back(x0 + cx, y0 + cy);
      for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++)
        {
          const int nx = cx + dx, ny = cy + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          const int n = ny * w + nx;
          if (mark[n] == static_cast<int8_t>(kind))
          {
            mark[n] = -1;
            todo.push_back(n);
          }
        }
    }
    ChangeRegion region = regionOf(kind, std::move(cells), res);
    if (region.extent() >= p.min_extent - 1e-9) report.regions.push_back(std::move(region));
  }
  std::stable_sort(report.regions.begin(), report.regions.end(), [](const ChangeRegion& x, const ChangeRegion& y) {
    if (x.kind != y.kind) return x.kind == ChangeKind::Appeared;
    return x.cells.size() > y.cells.size();
  });
  return report;
}

}  // namespace swslam::map
