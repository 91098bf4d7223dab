#pragma once
// The parameters of the system's modules, one .ini section each, loaded strictly (unknown
// sections and keys are errors naming them). A program's whole file (app/config.h) also
// holds the input's sections.

#include <swslam/correlative/params.h>
#include <swslam/graph/optimizer_params.h>
#include <swslam/loop/final_refinement_params.h>
#include <swslam/loop/params.h>
#include <swslam/map/params.h>
#include <swslam/plicp/params.h>
#include <swslam/system/options.h>
#include <swslam/tracking/params.h>

#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

namespace swslam::system
{
struct SystemParams
{
  plicp::PlicpParams plicp;    ///< [plicp]
  tracking::TrackingParams tracking;  ///< [tracking]
  correlative::CorrelativeParams correlative;  ///< [correlative]
  graph::GraphOptimizerParams graph_optimizer;  ///< [graph_optimizer]
  loop::LoopClosureParams loop_closure;  ///< [loop_closure]
  loop::FinalRefinementParams final_refinement;  ///< [final_refinement]
  map::MapParams map;        ///< [map]
  SystemOptions system;  ///< [system]

  /** Calls visit(table, parameters) for each section, in file order: the one list every
   * load, save, check and written file goes through. */
  template <class Params, class Visit>
  static void forEachSection(Params& p, Visit visit)
  {
    visit(plicp::PlicpParams::table(), p.plicp);
    visit(tracking::TrackingParams::table(), p.tracking);
    visit(correlative::CorrelativeParams::table(), p.correlative);
    visit(graph::GraphOptimizerParams::table(), p.graph_optimizer);
    visit(loop::LoopClosureParams::table(), p.loop_closure);
    visit(loop::FinalRefinementParams::table(), p.final_refinement);
    visit(map::MapParams::table(), p.map);
    visit(SystemOptions::table(), p.system);
  }

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

/** Writes every section with its current values. */
void saveSystemParams(const SystemParams& params, mrpt::config::CConfigFileBase& cfg);

}  // namespace swslam::system
