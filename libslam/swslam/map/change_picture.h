#pragma once
// changes.png and changes.md: what detectChanges found, over the map (doc/sessions.md).

#include <swslam/map/change_detection.h>
#include <swslam/map/overlay.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>

namespace swslam::map
{
/** The map picture (map_picture.h, with `overlay`'s trajectory) with the changed cells
 * painted: appeared green, disappeared red, each region ringed in its colour so that a small
 * one shows. */
mrpt::img::CImage drawChangePicture(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay,
                                    const ChangeReport& report);

/** Writes drawChangePicture() to `path` atomically (std::runtime_error naming the file if not). */
void writeChangePicture(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay, const ChangeReport& report,
                        const std::string& path);

/** changes.md: the counts and areas of each kind, then one row per region (kind, centroid,
 * extent, area, cells). */
std::string formatChangeReport(const ChangeReport& report);

}  // namespace swslam::map
