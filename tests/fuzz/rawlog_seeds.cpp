// Writes the seeds of the rawlog harness into a folder: small, valid, uncompressed rawlogs of
// both formats (observation-only; action / sensory-frame pairs), a few rays per scan so that
// the fuzzer's mutations reach every field. Usage: fuzz_rawlog_seeds FOLDER

#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

namespace
{
mrpt::obs::CObservation2DRangeScan::Ptr scan(int k, size_t rays)
{
  auto s = mrpt::obs::CObservation2DRangeScan::Create();
  s->sensorLabel = "LIDAR";
  s->aperture = M_PI;
  s->maxRange = 30;
  s->timestamp = mrpt::Clock::fromDouble(100 + 0.1 * k);
  s->resizeScan(rays);
  for (size_t i = 0; i < rays; ++i)
  {
    s->setScanRange(i, 1.0f + 0.25f * static_cast<float>(i % 7));
    s->setScanRangeValidity(i, i % 5 != 4);
  }
  return s;
}

void write(const std::string& path, const std::function<void(mrpt::serialization::CArchive&)>& body)
{
  mrpt::io::CFileOutputStream f(path);
  auto arch = mrpt::serialization::archiveFrom(f);
  body(arch);
  std::printf("%s\n", path.c_str());
}
}  // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: %s FOLDER\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  write(dir + "/one_scan.rawlog", [](auto& a) { a << *scan(0, 8); });
  write(dir + "/observations.rawlog", [](auto& a) {
    for (int k = 0; k < 2; ++k)
    {
      a << *scan(k, 6);
      mrpt::obs::CObservationOdometry odo;
      odo.sensorLabel = "ODOMETRY";
      odo.odometry = mrpt::poses::CPose2D(0.1 * k, 0, 0.01 * k);
      odo.timestamp = mrpt::Clock::fromDouble(100.05 + 0.1 * k);
      a << odo;
    }
  });
  write(dir + "/action_sensory_frame.rawlog", [](auto& a) {
    mrpt::obs::CActionCollection acts;
    mrpt::obs::CActionRobotMovement2D mv;
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions opts;
    mv.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0.01), opts);
    acts.insert(mv);
    a << acts;
    mrpt::obs::CSensoryFrame sf;
    sf.insert(scan(1, 6));
    a << sf;
  });
  return 0;
}
