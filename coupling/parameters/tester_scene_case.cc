// A wear-tester case as a scene case (tester_scene_case.h). The values the tester reads from
// its own entries (fill height, rotation rate, samples per revolution, steady state, sector,
// walls, consolidator) go into the scene's walls, fill, stages and evaluation; the entries
// themselves return to their defaults, so that the scene case sets nothing a scene does not use
// (case_scope.h refuses those) and reads back as the same case.
#include "coupling/parameters/tester_scene_case.h"

#include "coupling/parameters/engine_version.h"
#include "dem/tester/tester_scene.h"

#include <algorithm>
#include <stdexcept>

namespace wear::coupling {

CaseParameters tester_scene_case(const CaseParameters& tester) {
  if (!tester.scene.walls.empty())
    throw std::invalid_argument("case file '" + tester.case_file +
                                "' is a scene already (Scene/Walls = " + tester.scene.wall_names +
                                "); `wearsim tester-scene` writes a wear-tester case as a scene");
  const dem::ReferenceDeformationParameters deformation_defaults;
  if (tester.deformation.enabled ||
      tester.deformation.amplification != deformation_defaults.amplification)
    throw std::invalid_argument("Deformation/Reference method and Deformation/Amplification: "
                                "`wearsim dem`'s switch to the node-moving method; a run's "
                                "reference stages are Coupling/Schedule's (for example "
                                "\"6 reference\"), amplified by Coupling/Amplification");
  CaseParameters s = tester;
  s.scene = dem::tester_scene(tester.geometry, tester.dem, tester.coupling.revolutions_per_stage);
  const dem::TesterDemParameters tester_defaults; // the tester's own entries back to them
  s.dem = tester_defaults;
  static_cast<dem::DemParameters&>(s.dem) = tester.dem;
  s.geometry.tester = meshes::TesterGeometry{};
  if (tester.geometry.tester.holder) // the scene's holder reads its rim width there
    s.geometry.tester.holder_rim_width = tester.geometry.tester.holder_rim_width;
  s.deformation = dem::ReferenceDeformationParameters{}; // a scene reads only the interval
  int n_stages = 0;
  for (const auto& item : parse_schedule(tester.coupling.schedule)) {
    n_stages += item.n_stages;
    if (item.scheme == Scheme::reference)
      s.deformation.update_interval = tester.deformation.update_interval;
  }
  // DEM/Snapshot revolutions' "plus the last": the particles at the end of the last stage too
  const int last =
      n_stages * tester.coupling.revolutions_per_stage * tester.dem.samples_per_revolution;
  auto& records = s.scene.snapshot_records;
  if (std::find(records.begin(), records.end(), last) == records.end())
    records.push_back(last);
  s.coupling.revolutions_per_stage = CouplingParameters{}.revolutions_per_stage;
  return s;
}

CaseParameters run_case_of(const CaseParameters& p) {
  return p.scene.walls.empty() ? tester_scene_case(p) : p;
}

CaseParameters dem_case_of(const CaseParameters& p) {
  if (!p.scene.walls.empty())
    throw std::invalid_argument("wearsim dem runs a wear-tester case; case file '" + p.case_file +
                                "' is a scene (Scene/Walls = " + p.scene.wall_names +
                                "): run it with `wearsim run` and a dem-only Coupling/Schedule");
  // The node-moving method (Deformation/Reference method) as reference stages, amplified as
  // its Deformation/Amplification says.
  CaseParameters d = p;
  const bool moves = p.deformation.enabled;
  d.coupling.schedule = std::to_string(p.dem.revolutions) + (moves ? " reference" : " dem-only");
  d.coupling.revolutions_per_stage = 1;
  if (moves)
    d.coupling.amplification = p.deformation.amplification;
  d.deformation.enabled = false;
  d.deformation.amplification = dem::ReferenceDeformationParameters{}.amplification;
  return tester_scene_case(d);
}

std::string tester_scene_text(const CaseParameters& scene, const std::string& tester_file) {
  return "# The wear tester of " + tester_file + " written as a scene by `wearsim tester-scene`\n" +
         "# (engine " + engine_version() +
         "): its walls, sector, consolidator, holder, sample, fill and stages\n"
         "# in the Scene subsection (docs/wear-tester.md, \"The tester as a scene\"). Run it "
         "with\n# `wearsim scene-run`.\n" +
         changed_parameters(scene);
}

} // namespace wear::coupling
