#pragma once
// Small synthetic worlds and helpers shared by the tests.

#include <swslam/sensor/scan.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <functional>
#include <random>
#include <string>
#include <vector>

namespace swslam::test
{
/** A world of line segments and circles, ray-cast exactly. */
struct World
{
  struct Segment { double x0, y0, x1, y1; };
  struct Circle { double cx, cy, r; };
  std::vector<Segment> segments;
  std::vector<Circle> circles;

  /** Range along the ray from (x, y) with heading `a`, or +inf if nothing is hit. */
  double cast(double x, double y, double a) const;
};

/** A 20 x 12 m room with a few pillars and a wall jog: well constrained in x, y and yaw. */
World roomWorld();
/** A long straight corridor along x (2 m wide): x is unobservable from a short-range scan. */
World corridorWorld();
/** A cluttered natural-like scene: irregular bank polyline plus many tree trunks. */
World clutteredWorld(unsigned seed);

/** Simulates an MRPT observation from `sensor_pose` in `world`; rays that hit nothing
 * read `max_range` and are flagged invalid. Gaussian noise of `sigma` on ranges. */
mrpt::obs::CObservation2DRangeScan simulateObservation(const World& world,
                                                       const mrpt::poses::CPose2D& sensor_pose,
                                                       size_t beams, double aperture,
                                                       double max_range, double sigma,
                                                       std::mt19937& rng);

/** Unique path of a fresh temporary directory for one test. */
std::string tempDir(const std::string& name);

/** Runs `f` with the process's file size limit (RLIMIT_FSIZE) at `bytes` and SIGXFSZ ignored,
 * both restored after it (also when it throws): a write past the limit fails with EFBIG, as a
 * full disk refuses data with ENOSPC, without privileges. */
void withFileSizeLimit(size_t bytes, const std::function<void()>& f);

/** What `f` threw (its std::exception's what()); "" if it threw nothing. */
std::string errorOf(const std::function<void()>& f);

}  // namespace swslam::test
