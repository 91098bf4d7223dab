#pragma once
// The parameters of every module, loaded from one .ini file (config/default.ini): one
// section per module, strictly (unknown sections and keys are errors naming them).

#include <swslam/correlative/params.h>
#include <swslam/graph/optimizer_params.h>
#include <swslam/io/carmen_log.h>
#include <swslam/loop/final_refinement_params.h>
#include <swslam/loop/params.h>
#include <swslam/map/params.h>
#include <swslam/plicp/plicp.h>
#include <swslam/system/options.h>
#include <swslam/tracking/params.h>

#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <utility>
#include <vector>

namespace swslam::system
{
struct SystemParams
{
  plicp::PlicpParams plicp;    ///< [plicp]
  tracking::TrackingParams tracking;  ///< [tracking]
  correlative::CorrelativeParams correlative;  ///< [correlative]
  io::CarmenParams carmen;  ///< [carmen]
  graph::GraphOptimizerParams graph_optimizer;  ///< [graph_optimizer]
  loop::LoopClosureParams loop_closure;  ///< [loop_closure]
  loop::FinalRefinementParams final_refinement;  ///< [final_refinement]
  map::MapParams map;        ///< [map]
  SystemOptions system;  ///< [system]

  /** Each module's section name and parameters, in file order: the one list every load,
   * save and section check goes through. */
  std::vector<std::pair<std::string, mrpt::config::CLoadableOptions*>> modules();
  std::vector<std::pair<std::string, const mrpt::config::CLoadableOptions*>> modules() const;

  /** Section names, in file order. */
  static std::vector<std::string> sections();
};

/** Rules that span sections (each module checks its own keys when loading): throws
 * std::invalid_argument naming the keys. Called by loadSystemParams() and SlamSystem. */
void checkCrossSectionRules(const SystemParams& params);

/** Loads every section present; absent sections keep their defaults. Throws
 * std::invalid_argument naming the section or key that is wrong, or the keys of a broken
 * cross-section rule. */
SystemParams loadSystemParams(const mrpt::config::CConfigFileBase& cfg);
/** Same, in a file that also holds other programs' sections (e.g. a sensor's [LASER_2D]):
 * those are allowed, the swslam ones are still checked key by key. */
SystemParams loadSystemParams(const mrpt::config::CConfigFileBase& cfg,
                              const std::vector<std::string>& other_sections);
SystemParams loadSystemParams(const std::string& ini_path);

/** Writes every section with its current values (what default.ini documents). */
void saveSystemParams(const SystemParams& params, mrpt::config::CConfigFileBase& cfg);

}  // namespace swslam::system
