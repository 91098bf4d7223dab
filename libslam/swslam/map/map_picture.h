#pragma once
// map.png: the occupancy grid as a picture that reads alone: the observed part of the grid
// (k x k pixels per cell, k chosen so the plot is about 1000 px), the trajectory, its start and
// end, axes in metres, a scale bar and a legend.

#include <swslam/map/overlay.h>
#include <swslam/map/picture_annotations.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>

namespace swslam::map
{
/** What writeMapPicture drew, for checking the picture. */
struct MapPictureLayout
{
  PictureView view;
  int pixels_per_cell = 1;
  ScaleBar scale_bar;
  PixelBox legend;
};

/** The picture in memory: grey = 255 p(free) per cell, north (+y) up; the trajectory in orange
 * (colors::kTrajectory), a green disc at its start and a red square at its end. */
mrpt::img::CImage drawMapPicture(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay,
                                 MapPictureLayout* layout = nullptr);

/** Writes drawMapPicture() to `path` atomically (std::runtime_error naming the file if not). */
void writeMapPicture(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay, const std::string& path);

}  // namespace swslam::map
