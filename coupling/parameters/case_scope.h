#pragma once
// Which parameters a case uses: a scene (Scene/Walls lists walls) and a wear-tester case
// (whose scene its tester entries write, tester_scene_case.h) read different parts of the case
// file, and a parameter the case does not use is refused with its name rather than ignored.
#include "coupling/parameters/case_file_lines.h"
#include "coupling/parameters/case_parameters.h"

#include <string>
#include <vector>

namespace wear::coupling {

/// The reason `entry` (a case-file path, "DEM/Rotation rate") has no effect on the case `p`,
/// or "" when the case uses it. A scene uses neither the tester's own DEM entries
/// (dem::visit_tester_parameters), nor Deformation (the node-moving scheme runs in the
/// tester only), nor Geometry, except Geometry/Sample and Placement when a wall is the
/// tester's sample or holder (Source = sample, holder) and Geometry/Tester/Holder rim width
/// with a holder wall. The tester uses nothing of Scene but Scene/Walls.
std::string unused_because(const CaseParameters& p, const std::string& entry);

/// Throws std::invalid_argument listing every entry of `set` that `p` does not use
/// (unused_because), each with its file and line. read_case passes the entries the case file
/// sets to a value other than the default (a resolved parameters.prm sets every entry; one at
/// its default changes nothing).
void require_used_parameters(const CaseParameters& p, const std::vector<CaseFileEntry>& set);

} // namespace wear::coupling
