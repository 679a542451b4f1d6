// A wear-tester case as a scene case (tester_scene_case.h). The values the tester reads from
// its own entries (fill height, rotation rate, samples per revolution, steady state, sector,
// walls, consolidator) go into the scene's walls, fill, stages and evaluation; the entries
// themselves return to their defaults, so that the scene case sets nothing a scene does not use
// (case_scope.h refuses those) and reads back as the same case.
#include "coupling/parameters/tester_scene_case.h"

#include "coupling/parameters/engine_version.h"
#include "dem/tester/tester_scene.h"

#include <stdexcept>

namespace wear::coupling {

CaseParameters tester_scene_case(const CaseParameters& tester) {
  if (!tester.scene.walls.empty())
    throw std::invalid_argument("case file '" + tester.case_file +
                                "' is a scene already (Scene/Walls = " + tester.scene.wall_names +
                                "); `wearsim tester-scene` writes a wear-tester case as a scene");
  CaseParameters s = tester;
  s.scene = dem::tester_scene(tester.geometry, tester.dem, tester.coupling.revolutions_per_stage);
  const dem::TesterDemParameters tester_defaults; // the tester's own entries back to them
  s.dem = tester_defaults;
  static_cast<dem::DemParameters&>(s.dem) = tester.dem;
  s.geometry.tester = meshes::TesterGeometry{};
  if (tester.geometry.tester.holder) // the scene's holder reads its rim width there
    s.geometry.tester.holder_rim_width = tester.geometry.tester.holder_rim_width;
  s.deformation = dem::ReferenceDeformationParameters{}; // a scene reads only the interval
  for (const auto& item : parse_schedule(tester.coupling.schedule))
    if (item.scheme == Scheme::reference)
      s.deformation.update_interval = tester.deformation.update_interval;
  s.coupling.revolutions_per_stage = CouplingParameters{}.revolutions_per_stage;
  s.output.directory = tester.output.directory + "-scene";
  return s;
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
