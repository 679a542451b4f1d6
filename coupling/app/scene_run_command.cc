// `wearsim scene-run <case.prm>`: a scene's run. Without stages the DEM runs to Scene/End
// time with a record every Output interval (coupling/output/scene_series.h); with a wearing
// wall and Scene/Stage duration the wear loop runs its stages (coupling/loop/scene_wear_run.h).
#include "coupling/app/scene_run_command.h"

#include "coupling/loop/scene_wear_run.h"
#include "coupling/output/scene_series.h"
#include "dem/scene/scene_run.h"
#include "meshes/atomic_file.h"

#include <ostream>
#include <stdexcept>

namespace wear::coupling {

int run_scene_run_command(const CaseParameters& p, std::ostream& log) {
  if (p.scene.walls.empty())
    throw std::invalid_argument("case file '" + p.case_file +
                                "': Scene/Walls is empty: there is no scene to run");
  if (p.scene.stage_duration > 0)
    return SceneWearRun(p, log).run();
  const std::string& dir = p.output.directory;
  meshes::ensure_directory(dir);
  write_resolved_parameters(p, dir + "/parameters.prm");
  dem::SceneRun run(p.scene, p.dem, dem::build_scene_walls(p.scene));
  run.setup([&](const std::string& text) { log << "scene: " << text << "\n" << std::flush; });
  log << "scene: " << run.walls().size() << " walls, " << run.inlets().size() << " inlets, "
      << run.outlets().size() << " outlets; batches and outlets every " << run.exchange_interval()
      << " s; time step " << (run.system().n_rebuilds() > 0 ? run.system().time_step() : 0.0)
      << " s\n";
  SceneSeries series(dir, run);
  const double end = p.scene.end_time, every = p.scene.output_interval;
  int record = 0;
  while (run.time() < end - 1e-9 * every) {
    const dem::SceneWindow w = run.advance(std::min(end, run.time() + every));
    series.add(++record, w, run);
    log << window_summary(w) << "\n" << std::flush;
  }
  log << "written to " << dir
      << "/ (scene_series.csv, scene_wear.csv, particles_<k>.vtu, walls/, walls_<k>/)\n";
  return 0;
}

} // namespace wear::coupling
