// The parameters a case uses (case_scope.h). The tester's own DEM entries are the ones its
// visit function names (dem::visit_tester_parameters, collected by meshes::ParameterPaths),
// so a parameter added there is refused in a scene without a list to keep in step; the other
// rules are whole subsections.
#include "coupling/parameters/case_scope.h"

#include "dem/scene/wall_catalogue.h"

#include <algorithm>
#include <stdexcept>

namespace wear::coupling {

namespace {

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

bool has_wall_source(const CaseParameters& p, dem::WallSource source) {
  return std::any_of(
      p.scene.walls.begin(), p.scene.walls.end(),
      [&](const dem::SceneWallParameters& w) { return dem::wall_source_of(w).source == source; });
}

std::vector<std::string> tester_dem_paths() {
  dem::TesterDemParameters d;
  meshes::ParameterPaths v;
  v.enter("DEM");
  dem::visit_tester_parameters(d, v);
  v.leave();
  return v.paths;
}

/// The schedule has a reference (node-moving) stage; false for a schedule that does not read
/// (its own check names it).
bool has_reference_stage(const CaseParameters& p) {
  try {
    for (const auto& item : parse_schedule(p.coupling.schedule))
      if (item.scheme == Scheme::reference)
        return true;
  } catch (const std::invalid_argument&) {
  }
  return false;
}

} // namespace

std::string unused_because(const CaseParameters& p, const std::string& entry) {
  const bool scene = !p.scene.walls.empty();
  if (!scene) {
    if (starts_with(entry, "Scene/") && entry != "Scene/Walls")
      return "a parameter of a scene, and this case is a wear-tester case (Scene/Walls is "
             "empty): its scene is written from its Geometry and DEM subsections";
    return "";
  }
  const std::string is_scene = "this case is a scene (Scene/Walls = " + p.scene.wall_names + ")";
  static const std::vector<std::string> tester_dem = tester_dem_paths();
  if (std::find(tester_dem.begin(), tester_dem.end(), entry) != tester_dem.end())
    return "a wear-tester case's own, and " + is_scene +
           ": a scene's bed is Scene/Fill, its walls' motions their own, its length Scene/End "
           "time or its stages";
  if (entry == "Deformation/Update interval")
    return has_reference_stage(p) ? ""
                                  : "the node-moving reference scheme's, and Coupling/Schedule "
                                    "has no reference stage";
  if (starts_with(entry, "Deformation/"))
    return "`wearsim dem`'s switch for a wear-tester case, and " + is_scene +
           ": its reference stages are Coupling/Schedule's, amplified by Coupling/Amplification";
  if (starts_with(entry, "Geometry/")) {
    const bool sample = has_wall_source(p, dem::WallSource::sample),
               holder = has_wall_source(p, dem::WallSource::holder);
    if ((sample || holder) &&
        (starts_with(entry, "Geometry/Sample/") || starts_with(entry, "Geometry/Placement/")))
      return "";
    if (holder && entry == "Geometry/Tester/Holder rim width")
      return "";
    return "a wear-tester case's geometry, and " + is_scene +
           (sample || holder ? " whose tester parts (Source = sample, holder) use only "
                               "Geometry/Sample, Geometry/Placement and, for a holder, "
                               "Geometry/Tester/Holder rim width"
                             : " without the tester's sample or holder (Source = sample, "
                               "holder)");
  }
  return "";
}

void require_used_parameters(const CaseParameters& p, const std::vector<CaseFileEntry>& set) {
  std::string refused;
  int n = 0;
  for (const auto& e : set) {
    const std::string why = unused_because(p, e.path);
    if (why.empty())
      continue;
    refused += "\n  " + e.path + " (line " + std::to_string(e.line) + " of " + e.file + "): " + why;
    ++n;
  }
  if (n > 0)
    throw std::invalid_argument(
        std::string(n == 1 ? "a parameter this case does not use is set"
                           : std::to_string(n) + " parameters this case does not use are set") +
        "; remove " + (n == 1 ? "it" : "them") + refused);
}

} // namespace wear::coupling
