#include <swslam/map/octomap_export.h>

#include <swslam/common/atomic_file.h>

#include <octomap/OcTree.h>

#include <cmath>
#include <stdexcept>

namespace swslam::map
{
namespace
{
template <class F>
void forEachOccupied(const mrpt::maps::COccupancyGridMap2D& grid, double occupied_thresh, F f)
{
  for (unsigned cy = 0; cy < grid.getSizeY(); cy++)
    for (unsigned cx = 0; cx < grid.getSizeX(); cx++)
      if (1.0 - grid.getCell(static_cast<int>(cx), static_cast<int>(cy)) > occupied_thresh)
        f(cx, cy);
}
}  // namespace

size_t countOccupied(const mrpt::maps::COccupancyGridMap2D& grid, double occupied_thresh)
{
  size_t n = 0;
  forEachOccupied(grid, occupied_thresh, [&](unsigned, unsigned) { n++; });
  return n;
}

OctomapCounts writeOctomap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path,
                           double occupied_thresh, double free_thresh)
{
  // MRPT keeps the resolution as a float (0.1f = 0.100000001): give OctoMap the decimal.
  const double res = std::round(double(grid.getResolution()) * 1e7) / 1e7;
  octomap::OcTree tree(res);
  OctomapCounts n;
  // The grid's cells are aligned on multiples of the resolution, as OctoMap's voxels:
  // each cell centre falls in exactly one voxel of the layer z in [0, res).
  const auto z = static_cast<float>(0.5 * res);
  for (unsigned cy = 0; cy < grid.getSizeY(); cy++)
    for (unsigned cx = 0; cx < grid.getSizeX(); cx++)
    {
      const double p = 1.0 - grid.getCell(static_cast<int>(cx), static_cast<int>(cy));
      if (p > occupied_thresh || p < free_thresh)
      {
        tree.updateNode(octomap::point3d(grid.idx2x(cx), grid.idx2y(cy), z), p > occupied_thresh);
        (p > occupied_thresh ? n.occupied : n.free)++;
      }
    }
  common::writeStreamAtomically(path, [&](std::ostream& out) {
    if (!tree.writeBinary(out)) throw std::runtime_error("OctoMap could not write the tree");
  });
  return n;
}

}  // namespace swslam::map
