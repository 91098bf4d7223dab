#include <swslam/map/files.h>

#include <swslam/common/atomic_file.h>
#include <swslam/common/gzip_output.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace swslam::map
{
namespace
{
/** The shortest decimal that reads back as the same float (0.1f is "0.1"). */
std::string shortest(float v)
{
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, r.ptr);
}
}  // namespace

void writeGridmap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path)
{
  common::writeGzipAtomically(path, 1, [&](mrpt::io::CStream& out) { mrpt::serialization::archiveFrom(out) << grid; });
}

mrpt::maps::COccupancyGridMap2D readGridmap(const std::string& path)
{
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error("grid map '" + path + "' does not exist");
  mrpt::maps::COccupancyGridMap2D grid;
  try
  {
    mrpt::io::CFileGZInputStream in;
    if (!in.open(path)) throw std::runtime_error("cannot open it");
    mrpt::serialization::archiveFrom(in) >> grid;
  }
  catch (const std::exception& e)
  {
    throw std::runtime_error("'" + path + "' is not an MRPT grid map: " + e.what());
  }
  return grid;
}

void writeRosMap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& yaml_path,
                 const RosMapThresholds& thresholds)
{
  const std::filesystem::path yaml(yaml_path);
  if (yaml.extension() != ".yaml")
    throw std::invalid_argument("ROS map: '" + yaml_path + "' does not end in .yaml");
  const std::filesystem::path pgm = std::filesystem::path(yaml).replace_extension(".pgm");

  const unsigned w = grid.getSizeX(), h = grid.getSizeY();
  std::string image = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
  image.reserve(image.size() + size_t(w) * h);
  for (unsigned row = 0; row < h; row++)
  {
    const int cy = static_cast<int>(h - 1 - row);
    for (unsigned cx = 0; cx < w; cx++)
    {
      // getCell() is p(free) = 1 - p(occupied): with negate 0 the pixel is 255 * p(free).
      const long v = std::lround(255.0 * grid.getCell(static_cast<int>(cx), cy));
      image.push_back(static_cast<char>(static_cast<unsigned char>(std::clamp(v, 0L, 255L))));
    }
  }
  common::writeTextAtomically(pgm.string(), image);

  std::ostringstream y;
  y << "image: " << pgm.filename().string() << "\n"
    << "resolution: " << shortest(grid.getResolution()) << "\n"
    << "origin: [" << shortest(grid.getXMin()) << ", " << shortest(grid.getYMin()) << ", 0.0]\n"
    << "negate: 0\n"
    << "occupied_thresh: " << thresholds.occupied_thresh << "\n"
    << "free_thresh: " << thresholds.free_thresh << "\n";
  common::writeTextAtomically(yaml_path, y.str());
}

}  // namespace swslam::map
