#include <swslam/map/params.h>
#include <swslam/map/summed_grid.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/core/bits_math.h>

#include <stdexcept>

namespace swslam::map
{
void MapParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
  MRPT_LOAD_CONFIG_VAR_CS(resolution, double);
  MRPT_LOAD_CONFIG_VAR_CS(initial_half_size, double);
  MRPT_LOAD_CONFIG_VAR_CS(grow_margin, double);
  MRPT_LOAD_CONFIG_VAR_CS(prob_occupied, double);
  MRPT_LOAD_CONFIG_VAR_CS(prob_free, double);
  MRPT_LOAD_CONFIG_VAR_CS(max_insertion_range, double);
  horizontal_tolerance = mrpt::DEG2RAD(
      c.read_double(s, "horizontal_tolerance_DEG", mrpt::RAD2DEG(horizontal_tolerance)));
  reinsert.translation = c.read_double(s, "reinsert_translation", reinsert.translation);
  reinsert.rotation =
      mrpt::DEG2RAD(c.read_double(s, "reinsert_rotation_DEG", mrpt::RAD2DEG(reinsert.rotation)));
  MRPT_LOAD_CONFIG_VAR_CS(occupied_thresh, double);
  MRPT_LOAD_CONFIG_VAR_CS(free_thresh, double);

  check("config [" + s + "]");
}

void MapParams::check(const std::string& where) const
{
  auto require = [&](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(where + ": " + what);
  };
  require(resolution >= 0.005 && resolution <= 10, "resolution must be in [0.005, 10] m");
  require(initial_half_size > 0 && grow_margin >= 0, "initial_half_size must be > 0, grow_margin >= 0");
  require(initial_half_size / resolution <= SummedGrid::kMaxCellsPerLength &&
              grow_margin / resolution <= SummedGrid::kMaxCellsPerLength,
          "initial_half_size and grow_margin must be at most 8192 cells (resolution times 8192)");
  require(prob_occupied > 0.5 && prob_occupied < 1, "prob_occupied must be in (0.5, 1)");
  require(prob_free > 0 && prob_free < 0.5, "prob_free must be in (0, 0.5)");
  require(max_insertion_range > 0, "max_insertion_range must be > 0");
  require(horizontal_tolerance >= 0, "horizontal_tolerance_DEG must be >= 0");
  require(reinsert.translation >= 0 && reinsert.rotation >= 0, "reinsert_* must be >= 0");
  require(free_thresh > 0 && free_thresh < occupied_thresh && occupied_thresh < 1,
          "need 0 < free_thresh < occupied_thresh < 1");
}

void MapParams::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
  MRPT_SAVE_CONFIG_VAR_COMMENT(resolution, "[m] cell size");
  MRPT_SAVE_CONFIG_VAR_COMMENT(initial_half_size, "[m] the grid starts as [-s, s]^2 around the origin");
  MRPT_SAVE_CONFIG_VAR_COMMENT(grow_margin, "[m] room added beyond a scan that leaves the grid");
  MRPT_SAVE_CONFIG_VAR_COMMENT(prob_occupied, "eq. 16 prop_occupied: the cell at a ray's end");
  MRPT_SAVE_CONFIG_VAR_COMMENT(prob_free, "eq. 16 prop_free: the cells a ray crosses");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_insertion_range, "[m] rays are cut here");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("horizontal_tolerance_DEG", horizontal_tolerance,
                                       "[deg] a scan tilted more is an error");
  c.write(s, "reinsert_translation", reinsert.translation);
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("reinsert_rotation_DEG", reinsert.rotation,
                                       "[deg] re-insert a node's scan past this rotation");
  MRPT_SAVE_CONFIG_VAR_COMMENT(occupied_thresh, "Exports: occupancy above this is an obstacle");
  MRPT_SAVE_CONFIG_VAR_COMMENT(free_thresh, "Exports: occupancy below this is free");
}

mrpt::maps::COccupancyGridMap2D::TInsertionOptions MapParams::insertionOptions() const
{
  mrpt::maps::COccupancyGridMap2D::TInsertionOptions o;
  o.maxDistanceInsertion = static_cast<float>(max_insertion_range);
  o.maxOccupancyUpdateCertainty = static_cast<float>(prob_occupied);
  // MRPT's cells hold the log-odds of being free: its "freeness certainty" is 1 - prop_free.
  o.maxFreenessUpdateCertainty = static_cast<float>(1 - prob_free);
  o.considerInvalidRangesAsFreeSpace = false;  // a ray without a return tells nothing
  o.decimation = 1;
  o.horizontalTolerance = static_cast<float>(horizontal_tolerance);
  o.wideningBeamsWithDistance = false;  // plain Bresenham-like rays, as the paper
  return o;
}

}  // namespace swslam::map
