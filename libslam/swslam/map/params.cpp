#include <swslam/map/params.h>
#include <swslam/map/summed_grid.h>


namespace swslam::map
{
const common::ParamTable<MapParams>& MapParams::table()
{
  using P = MapParams;
  using common::Tier;
  using common::above, common::atLeast, common::between, common::strictlyBetween;
  constexpr double kMaxCells = SummedGrid::kMaxCellsPerLength;
  static const auto t =
      common::ParamTable<P>("map", "Occupancy grid map (paper sec. IV), log-odds; moved nodes' scans re-inserted.")
          .real("resolution", &P::resolution, "m", between(0.005, 10), "cell size", Tier::User)
          .real("max_insertion_range", &P::max_insertion_range, "m", above(0), "rays are cut here (no hit inserted beyond)",
                Tier::User)
          .real("occupied_thresh", &P::occupied_thresh, "", strictlyBetween(0, 1),
                "exports (map.yaml/pgm, map.bt): occupancy above this is an obstacle...", Tier::User)
          .real("free_thresh", &P::free_thresh, "", strictlyBetween(0, 1), "...and below this is free", Tier::User)
          .real("initial_half_size", &P::initial_half_size, "m", above(0), "the grid starts as [-s, s]^2 around the origin...")
          .real("grow_margin", &P::grow_margin, "m", atLeast(0),
                "...and grows by this much beyond a scan that leaves it (each at most 8192 cells)")
          .real("prob_occupied", &P::prob_occupied, "", strictlyBetween(0.5, 1), "eq. 16 prop_occupied: the cell at a ray's end")
          .real("prob_free", &P::prob_free, "", strictlyBetween(0, 0.5), "eq. 16 prop_free: the cells a ray crosses")
          .angle("horizontal_tolerance_DEG", &P::horizontal_tolerance, atLeast(0), "a scan tilted more than this is an error")
          .real("reinsert_translation", &P::reinsert_translation, "m", atLeast(0),
                "after an optimization, a node's scan is re-inserted if it moved more than this...")
          .angle("reinsert_rotation_DEG", &P::reinsert_rotation, atLeast(0), "...or turned more than this")
          .rule([=](const P& p) { return p.initial_half_size / p.resolution <= kMaxCells && p.grow_margin / p.resolution <= kMaxCells; },
                "initial_half_size and grow_margin must be at most 8192 cells (resolution times 8192)")
          .rule([](const P& p) { return p.free_thresh < p.occupied_thresh; }, "need free_thresh < occupied_thresh");
  return t;
}

}  // namespace swslam::map
