#pragma once
// A wear-tester case written as a scene case (`wearsim tester-scene`): the same machine,
// particles, wear law, coupling and FEM, its walls, sector, fill and stages in the Scene
// subsection (dem/tester/tester_scene.h) instead of the tester's own entries. `wearsim run` and
// `wearsim dem` run a wear-tester case as this scene.
#include "coupling/parameters/case_parameters.h"

#include <string>

namespace wear::coupling {

/// The scene case of tester case `tester`: Scene = dem::tester_scene of its geometry, DEM and
/// Coupling/Revolutions per stage; the tester's own entries (Geometry/Tester but the holder's
/// rim width, the DEM entries only the tester reads, Coupling/Revolutions per stage) back at
/// their defaults, since the scene now holds them; with reference stages the scene keeps
/// Deformation/Update interval. Throws std::invalid_argument naming the parameter when the case
/// is a scene already.
CaseParameters tester_scene_case(const CaseParameters& tester);

/// The case `wearsim run` runs: a scene's case as it is, a wear-tester case as its scene
/// (tester_scene_case): the tester is one scene among others.
CaseParameters run_case_of(const CaseParameters& p);

/// The case `wearsim dem` runs, the wear tester in DEM alone: tester case `p` with
/// DEM/Revolutions dem-only stages of one revolution each, as a scene; it stops
/// DEM/Revolutions after steady revolutions after the first steady one
/// (Scene/Evaluation/Periods after steady). Throws naming the file for a scene's case.
CaseParameters dem_case_of(const CaseParameters& p);

/// The text of that case file: a comment naming the tester case and the engine, then the
/// entries that differ from their defaults (changed_parameters).
std::string tester_scene_text(const CaseParameters& scene, const std::string& tester_file);

} // namespace wear::coupling
