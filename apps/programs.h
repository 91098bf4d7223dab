#pragma once
// The heavy programs' work, behind one C entry point each. Program X's entry point is in X-run.cpp,
// built into its own shared library libX-run.so with the modules X uses. X's executable parses its
// command line into X's options (plain values, declared in headers that include no MRPT
// observation, map or OpenGL header), then loads the library and calls the entry point
// (run_in_library.h): --help, --version and a bad command line are answered before any of MRPT's
// observation, map or OpenGL libraries, OpenCV, GDAL or ROS is loaded.

#include <swslam/app/bench_localize_run.h>
#include <swslam/app/bench_map_run.h>
#include <swslam/app/bench_matcher_run.h>
#include <swslam/app/carmen2rawlog_run.h>
#include <swslam/app/eval_command.h>
#include <swslam/app/live_run.h>
#include <swslam/app/localize_run.h>
#include <swslam/app/offline_run.h>
#include <swslam/app/rawlog2bag_run.h>
#include <swslam/app/regen_map_run.h>
#include <swslam/app/sim_run.h>

/** Each runs its program with the options and returns its exit code; what the program prints
 * goes to std::cout and std::cerr. */
extern "C"
{
  int swslam_run_offline(const swslam::app::OfflineRunOptions* options);
  int swslam_run_live(const swslam::app::LiveRunOptions* options);
  int swslam_run_eval(const swslam::app::EvalOptions* options);
  int swslam_run_regen_map(const swslam::app::RegenMapOptions* options);
  int swslam_run_localize(const swslam::app::LocalizeOptions* options);
  int swslam_run_bench_map(const swslam::app::BenchMapOptions* options);
  int swslam_run_bench_localize(const swslam::app::BenchLocalizeOptions* options);
  int swslam_run_bench_matcher(const swslam::app::BenchMatcherOptions* options);
  int swslam_run_sim(const swslam::app::SimOptions* options);
  int swslam_run_rawlog2bag(const swslam::app::Rawlog2BagRunOptions* options);
  int swslam_run_carmen2rawlog(const swslam::app::Carmen2RawlogRunOptions* options);
}
