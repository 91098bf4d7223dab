// Matches a scan against itself, shifted, through the installed library.
#include <swslam/plicp/plicp.h>

#include <cmath>
#include <cstdio>

int main()
{
  mrpt::obs::CObservation2DRangeScan obs;
  obs.aperture = static_cast<float>(M_PI);
  obs.maxRange = 20;
  obs.resizeScan(181);
  for (size_t i = 0; i < 181; i++)
  {
    // A square room of half-side 4 m seen from its centre.
    const double a = swslam::sensor::beamAngle(i, 181, M_PI);
    const double r = 4.0 / std::max(std::abs(std::cos(a)), std::abs(std::sin(a)));
    obs.setScanRange(i, static_cast<float>(r));
    obs.setScanRangeValidity(i, true);
  }
  const swslam::plicp::ReferenceScan ref(swslam::sensor::scanFromObservation(obs));
  const auto res = swslam::plicp::matchScans(ref, ref.scan, mrpt::poses::CPose2D(0.1, -0.05, 0.02),
                                      swslam::plicp::PlicpParams());
  std::printf("status=%s x=%.4f y=%.4f phi=%.5f\n", swslam::plicp::toString(res.status), res.pose.x(),
              res.pose.y(), res.pose.phi());
  return res.ok() && std::abs(res.pose.x()) < 1e-3 && std::abs(res.pose.phi()) < 1e-4 ? 0 : 1;
}
