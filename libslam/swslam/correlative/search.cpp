#include <swslam/correlative/search.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>

namespace swslam::correlative
{
namespace
{
/** The motion prior's cost of a translation d from the window's centre (increasing in d, so
 * a block's nearest point bounds it). */
double translationCost(const SearchWindow& w, double d) { return w.cost_per_m * d + w.cost_per_m2 * d * d; }
/** Cells of the points turned by theta and moved by t, into `out` (resized to the points'). */
void rotatedCells(const ScoreGrid& g, const std::vector<Eigen::Vector2d>& pts, double theta,
                  const Eigen::Vector2d& t, std::vector<Eigen::Vector2i>& out)
{
  // g.cellOf(R p + t), in a loop without calls or growth.
  const double c = std::cos(theta), s = std::sin(theta);
  const double ox = g.origin.x(), oy = g.origin.y(), r = g.resolution;
  out.resize(pts.size());
  for (size_t k = 0; k < pts.size(); k++)
  {
    const double x = c * pts[k].x() - s * pts[k].y() + t.x(), y = s * pts[k].x() + c * pts[k].y() + t.y();
    out[k] = {cellFloor((x - ox) / r), cellFloor((y - oy) / r)};
  }
}
std::vector<Eigen::Vector2i> rotatedCells(const ScoreGrid& g, const std::vector<Eigen::Vector2d>& pts,
                                          double theta, const Eigen::Vector2d& t)
{
  std::vector<Eigen::Vector2i> out;
  rotatedCells(g, pts, theta, t, out);
  return out;
}

int32_t sumAt(const ScoreGrid& g, const std::vector<Eigen::Vector2i>& cells, int i, int j)
{
  int32_t sum = 0;
  for (const auto& c : cells) sum += g.at(c.x() + i, c.y() + j);
  return sum;
}

/** The window's half side in cells, checked against kMaxWindowCells before it becomes an int. */
int halfCells(double half_xy, double resolution)
{
  const double n = std::floor(half_xy / resolution + 1e-9);
  if (!(n >= 0 && n <= kMaxWindowCells))
    throw std::invalid_argument("search window: +-" + std::to_string(half_xy) + " m at " + std::to_string(resolution) +
                                " m is not 0 to " + std::to_string(kMaxWindowCells) + " cells");
  return static_cast<int>(n);
}

/** Smallest sum that reaches min_score (at least 1: a pose touching no cell is no result). */
int32_t threshold(double min_score, size_t n)
{
  return std::max<int32_t>(1, static_cast<int32_t>(std::ceil(min_score * 255.0 * n - 1e-9)));
}

/** The lattice's poses and their objectives: angle k, translation centre + (i, j) cells. */
class Lattice
{
 public:
  Lattice(const ScoreGrid& base, const std::vector<Eigen::Vector2d>& points, const SearchWindow& w)
      : w_(w), res_(base.resolution), n_(halfCells(w.half_xy, base.resolution)), angles_(windowAngles(w)),
        norm_(255.0 * points.size())
  {
    // Every offset searched is within [-n, n] cells on both axes, at every level (the levels
    // share the base grid's size). Per angle, a point whose cell stays inside the grid for all
    // of them is summed without bounds checks, one that stays outside is left out (it scores
    // 0), and only the rest are checked.
    // All angles' terms are kept in two arrays, each angle's a range of them.
    std::vector<Eigen::Vector2i> cells;
    for (double a : angles_)
    {
      Terms t{inside_.size(), 0, border_.size(), 0};
      rotatedCells(base, points, a, w.centre.head<2>(), cells);
      for (const auto& c : cells)
      {
        if (c.x() + n_ < 0 || c.y() + n_ < 0 || c.x() - n_ >= base.width || c.y() - n_ >= base.height) continue;
        if (c.x() - n_ >= 0 && c.y() - n_ >= 0 && c.x() + n_ < base.width && c.y() + n_ < base.height)
          inside_.push_back(c.y() * base.width + c.x());
        else
          border_.push_back(c);
      }
      t.inside_end = inside_.size();
      t.border_end = border_.size();
      terms_.push_back(t);
      angle_cost_.push_back(w.cost_per_rad * std::abs(std::remainder(a - w.centre.z(), 2 * M_PI)));
    }
    // The translation cost of a block depends only on its gap from the centre in cells.
    for (int gi = 0; gi <= n_; gi++)
      for (int gj = 0; gj <= n_; gj++) gap_cost_.push_back(translationCost(w_, res_ * std::hypot(gi, gj)));
  }
  int n() const { return n_; }
  bool excluded(int i, int j) const
  {
    return correlative::excluded(w_, w_.centre.head<2>() + res_ * Eigen::Vector2d(i, j));
  }
  int angleCount() const { return static_cast<int>(angles_.size()); }
  int32_t sum(const ScoreGrid& level, int k, int i, int j) const
  {
    const Terms& t = terms_[k];
    const int16_t* cells = level.cells.data() + (static_cast<ptrdiff_t>(j) * level.width + i);
    int32_t sum = 0;
    for (size_t m = t.inside_begin; m < t.inside_end; m++) sum += cells[inside_[m]];
    for (size_t m = t.border_begin; m < t.border_end; m++) sum += level.at(border_[m].x() + i, border_[m].y() + j);
    return sum;
  }
  /** The sums of the four blocks at offsets (i, j), (i, j + s), (i + s, j) and (i + s, j + s),
   * in that order, in one pass over the points (all four within [-n, n]). */
  std::array<int32_t, 4> sums(const ScoreGrid& level, int k, int i, int j, int s) const
  {
    const Terms& t = terms_[k];
    const ptrdiff_t row = level.width, up = s * row;
    const int16_t* cells = level.cells.data() + (static_cast<ptrdiff_t>(j) * row + i);
    int32_t a = 0, b = 0, c = 0, d = 0;
    for (size_t m = t.inside_begin; m < t.inside_end; m++)
    {
      const int16_t* p = cells + inside_[m];
      a += p[0];
      b += p[up];
      c += p[s];
      d += p[up + s];
    }
    for (size_t m = t.border_begin; m < t.border_end; m++)
    {
      const Eigen::Vector2i& q = border_[m];
      const int x = q.x() + i, y = q.y() + j;
      a += level.at(x, y);
      b += level.at(x, y + s);
      c += level.at(x + s, y);
      d += level.at(x + s, y + s);
    }
    return {a, b, c, d};
  }
  /** The objective with cell sum `sum` at the best pose of the block of offsets [i0, i1] x
   * [j0, j1] (its point nearest the centre): an upper bound over the block when `sum` bounds
   * the block's sums, the exact objective of a single pose. */
  double objective(int32_t sum, int k, int i0, int i1, int j0, int j1) const
  {
    auto gap = [](int lo, int hi) { return lo > 0 ? lo : (hi < 0 ? -hi : 0); };
    return sum / norm_ - angle_cost_[k] - gap_cost_[gap(i0, i1) * (n_ + 1) + gap(j0, j1)];
  }
  SearchResult result(int k, int i, int j, int32_t sum, size_t evaluated) const
  {
    SearchResult r;
    r.pose = {w_.centre.x() + i * res_, w_.centre.y() + j * res_, angles_[k]};
    r.score = sum / norm_;
    r.objective = objective(sum, k, i, i, j, j);
    r.bounds_evaluated = evaluated;
    return r;
  }

 private:
  SearchWindow w_;
  double res_;
  int n_;
  std::vector<double> angles_;
  double norm_;
  std::vector<double> angle_cost_;  ///< the rotation's cost, per angle
  std::vector<double> gap_cost_;    ///< the translation's cost, at gap (gi, gj) cells
  std::vector<int> inside_;              ///< y * width + x of cells always inside the grid
  std::vector<Eigen::Vector2i> border_;  ///< cells sometimes inside
  struct Terms  ///< an angle's ranges of inside_ and border_
  {
    size_t inside_begin, inside_end, border_begin, border_end;
  };
  std::vector<Terms> terms_;  ///< per angle
};

struct Candidate
{
  int k, i, j;    ///< angle index, lowest translation offset of the block (cells)
  int32_t sum;   ///< sum of the level's cells: bounds the sums of the block's poses
  double bound;   ///< objective bound of the block
};

/** Depth-first branch and bound (Hess et al. 2016, alg. 3): best bound first, and prune
 * what cannot beat the best objective found. */
class BranchAndBound
{
 public:
  BranchAndBound(const ScorePyramid& p, const Lattice& lattice, int32_t needed, double floor, int top)
      : evaluated_by_level_(static_cast<size_t>(top) + 1, 0), expanded_by_level_(static_cast<size_t>(top) + 1, 0),
        pyramid_(p), lattice_(lattice), needed_(needed), floor_(floor)
  {
  }
  Candidate bounded(int k, int i, int j, int h)
  {
    return withSum(k, i, j, h, lattice_.sum(pyramid_.levels[h], k, i, j));
  }
  Candidate withSum(int k, int i, int j, int h, int32_t sum)
  {
    evaluated_by_level_[h]++;
    const int last = lattice_.n(), side = (1 << h) - 1;
    return {k, i, j, sum, lattice_.objective(sum, k, i, std::min(i + side, last), j, std::min(j + side, last))};
  }
  void descend(Candidate* first, Candidate* last, int h)
  {
    auto before = [](const Candidate& a, const Candidate& b) {
      return a.bound != b.bound ? a.bound > b.bound
                                : std::tie(a.k, a.i, a.j) < std::tie(b.k, b.i, b.j);
    };
    if (last - first > 4)
      std::sort(first, last, before);
    else  // a block's children: insertion sort, no allocation
      for (Candidate* it = first + 1; it < last; ++it)
        for (Candidate* p = it; p > first && before(*p, *(p - 1)); --p) std::swap(*p, *(p - 1));
    for (const Candidate* it = first; it != last; ++it)
    {
      const Candidate& c = *it;
      if (best_ && c.bound <= best_->bound) return;  // sorted: nothing later does better
      if (c.bound <= floor_) return;  // nor better than the caller's floor
      if (c.sum < needed_) continue;  // no pose of the block reaches min_score
      if (h == 0)
      {
        if (lattice_.excluded(c.i, c.j)) continue;
        best_ = c;
        continue;
      }
      expanded_by_level_[h]++;
      const int s = 1 << (h - 1);
      std::array<Candidate, 4> children;
      int count = 0;
      if (c.i + s <= lattice_.n() && c.j + s <= lattice_.n())
      {
        const auto sums = lattice_.sums(pyramid_.levels[h - 1], c.k, c.i, c.j, s);
        for (int di : {0, 1})
          for (int dj : {0, 1})
            children[count++] = withSum(c.k, c.i + di * s, c.j + dj * s, h - 1, sums[2 * di + dj]);
      }
      else
        for (int di : {0, s})
          for (int dj : {0, s})
            if (c.i + di <= lattice_.n() && c.j + dj <= lattice_.n())
              children[count++] = bounded(c.k, c.i + di, c.j + dj, h - 1);
      descend(children.data(), children.data() + count, h - 1);
    }
  }
  std::optional<Candidate> best_;
  std::vector<size_t> evaluated_by_level_, expanded_by_level_;

 private:
  const ScorePyramid& pyramid_;
  const Lattice& lattice_;
  int32_t needed_;
  double floor_;
};
}  // namespace

double objective(const SearchWindow& w, double score, const Eigen::Vector3d& pose)
{
  return score - translationCost(w, (pose.head<2>() - w.centre.head<2>()).norm()) -
         w.cost_per_rad * std::abs(std::remainder(pose.z() - w.centre.z(), 2 * M_PI));
}

bool excluded(const SearchWindow& w, const Eigen::Vector2d& t)
{
  return w.exclude_radius >= 0 && (t - w.exclude_xy).norm() <= w.exclude_radius;
}

std::vector<double> windowAngles(const SearchWindow& w)
{
  // Counted in double and checked before any allocation (a step of 0 would be endless).
  const double full = std::ceil(2 * M_PI / w.theta_step - 1e-9);
  if (!(w.theta_step > 0) || !(full <= kMaxWindowAngles) || !(w.half_theta >= 0))
    throw std::invalid_argument("search window: a rotation step of " + std::to_string(w.theta_step) +
                                " rad (more than " + std::to_string(kMaxWindowAngles) +
                                " rotations in a turn) or a half width of " + std::to_string(w.half_theta) + " rad");
  std::vector<double> out;
  if (w.half_theta >= M_PI)
  {
    const int count = std::max(1, static_cast<int>(full));
    const double step = 2 * M_PI / count;
    for (int k = -count / 2; k < count - count / 2; k++) out.push_back(w.centre.z() + k * step);
    return out;
  }
  const int m = static_cast<int>(std::floor(w.half_theta / w.theta_step + 1e-9));
  for (int k = -m; k <= m; k++) out.push_back(w.centre.z() + k * w.theta_step);
  return out;
}

int depthForWindow(double half_xy, double resolution)
{
  const int span = 2 * halfCells(half_xy, resolution) + 1;
  int h = 0;
  while ((1 << h) < span) h++;
  return h;
}

std::optional<SearchResult> searchBranchAndBound(const ScorePyramid& pyramid,
                                                 const std::vector<Eigen::Vector2d>& points,
                                                 const SearchWindow& w, double min_score,
                                                 double min_objective)
{
  const ScoreGrid& base = pyramid.levels.front();
  if (points.empty() || base.cells.empty()) return std::nullopt;
  const Lattice lattice(base, points, w);
  const int top = std::min(pyramid.depth(), depthForWindow(w.half_xy, base.resolution));
  BranchAndBound bnb(pyramid, lattice, threshold(min_score, points.size()), min_objective, top);
  std::vector<Candidate> cands;
  const int n = lattice.n();
  for (int k = 0; k < lattice.angleCount(); k++)
    for (int i = -n; i <= n; i += 1 << top)
      for (int j = -n; j <= n; j += 1 << top) cands.push_back(bnb.bounded(k, i, j, top));
  bnb.descend(cands.data(), cands.data() + cands.size(), top);
  if (!bnb.best_) return std::nullopt;
  const Candidate& b = *bnb.best_;
  SearchResult r = lattice.result(b.k, b.i, b.j, b.sum,
                                  std::accumulate(bnb.evaluated_by_level_.begin(), bnb.evaluated_by_level_.end(), size_t{0}));
  r.evaluated_by_level = std::move(bnb.evaluated_by_level_);
  r.expanded_by_level = std::move(bnb.expanded_by_level_);
  return r;
}

std::optional<SearchResult> searchBruteForce(const ScoreGrid& grid,
                                             const std::vector<Eigen::Vector2d>& points,
                                             const SearchWindow& w, double min_score,
                                             double min_objective)
{
  if (points.empty() || grid.cells.empty()) return std::nullopt;
  const Lattice lattice(grid, points, w);
  const int32_t needed = threshold(min_score, points.size());
  std::optional<SearchResult> best;
  size_t evaluated = 0;
  for (int k = 0; k < lattice.angleCount(); k++)
    for (int i = -lattice.n(); i <= lattice.n(); i++)
      for (int j = -lattice.n(); j <= lattice.n(); j++)
      {
        evaluated++;
        const int32_t sum = lattice.sum(grid, k, i, j);
        if (sum < needed || lattice.excluded(i, j)) continue;
        const SearchResult r = lattice.result(k, i, j, sum, 0);
        if (r.objective <= min_objective) continue;
        if (!best || r.objective > best->objective) best = r;
      }
  if (best) best->bounds_evaluated = evaluated;
  return best;
}

double scoreAt(const ScoreGrid& grid, const std::vector<Eigen::Vector2d>& points,
               const Eigen::Vector3d& pose)
{
  if (points.empty()) return 0;
  const auto cells = rotatedCells(grid, points, pose.z(), pose.head<2>());
  return sumAt(grid, cells, 0, 0) / (255.0 * points.size());
}

CommonScores commonScores(const ScoreGrid& grid, const std::vector<Eigen::Vector2d>& points,
                          const Eigen::Vector3d& a, const Eigen::Vector3d& b, double goes_on_ratio)
{
  const auto ca = rotatedCells(grid, points, a.z(), a.head<2>());
  const auto cb = rotatedCells(grid, points, b.z(), b.head<2>());
  CommonScores out;
  int64_t sa = 0, sb = 0;
  for (size_t k = 0; k < points.size(); k++)
  {
    const int va = grid.at(ca[k].x(), ca[k].y()), vb = grid.at(cb[k].x(), cb[k].y());
    if (va == 0 && vb == 0) continue;
    if ((va == 0) != (vb == 0))
    {
      const Eigen::Vector2i known = va != 0 ? ca[k] : cb[k], unknown = va != 0 ? cb[k] : ca[k];
      const Eigen::Vector2i beyond = 2 * known - unknown;
      const int v = va != 0 ? va : vb;
      if (v > 0 && grid.at(beyond.x(), beyond.y()) >= goes_on_ratio * v) continue;
    }
    sa += va;
    sb += vb;
    out.points++;
  }
  if (out.points > 0)
  {
    out.a = sa / (255.0 * out.points);
    out.b = sb / (255.0 * out.points);
  }
  return out;
}

MatchComparison compareMatches(const ScoreGrid& grid, const std::vector<Eigen::Vector2d>& points,
                               const SearchWindow& w, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               double common_points_fraction, double goes_on_ratio)
{
  MatchComparison out;
  if (common_points_fraction > 0)
  {
    const CommonScores c = commonScores(grid, points, a, b, goes_on_ratio);
    if (c.points > 0 && c.points >= common_points_fraction * points.size())
    {
      out.a = objective(w, c.a, a);
      out.b = objective(w, c.b, b);
      out.common_points = c.points;
      return out;
    }
  }
  out.a = objective(w, scoreAt(grid, points, a), a);
  out.b = objective(w, scoreAt(grid, points, b), b);
  return out;
}

}  // namespace swslam::correlative
