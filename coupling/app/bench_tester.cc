// The `tester` workload of `wearsim bench dem`: what users run, timed. The case is written as
// the scene `wearsim run` runs (tester_scene_case: the floor and cylinders as exact turning
// surfaces of revolution, the sample a wearing wall), its walls built, the bed filled from
// the PSD and settled with the walls at rest (dem::SceneRun::setup, the same call as a run),
// and the flow steps run as a window does: the floor and cylinders turn and the engine
// accumulates the per-face wear integrals in its wall pass. The timed steps are then plain
// System::run steps, which is what a window of the tester runs between its records (the
// tester has no inlets, outlets or moving nodes); the records, evaluation samples and output
// files of a real run (a few per revolution) are not part of the figure.
// A revolution is T = Theta / omega and round(T / dt) steps, so at a median rate R
// [particle-steps/s] it takes steps x N / R seconds.
#include "coupling/app/bench_tester.h"

#include "coupling/output/checkpoint.h"
#include "coupling/output/text_format.h"
#include "coupling/parameters/tester_scene_case.h"
#include "dem/scene/scene_walls.h"
#include "meshes/constants.h"
#include "meshes/stopwatch.h"

#include <filesystem>
#include <ostream>

namespace wear::coupling {

CaseParameters reference_tester_case(bool convex, double scale) {
  CaseParameters p;
  p.geometry.sample.convex = convex;
  p.dem.psd.scaling_factor = scale;
  p.dem.time_step_fraction = 0.3;
  p.wear_law.model = "archard";
  p.wear_law.archard_coefficient = 5e-9;
  return p;
}

CaseParameters tester_bench_case(const TesterBenchOptions& o) {
  CaseParameters p = o.case_file.empty()
                         ? reference_tester_case(o.convex.value_or(true), o.scale.value_or(3))
                         : read_case(o.case_file);
  if (o.scale)
    p.dem.psd.scaling_factor = *o.scale;
  if (o.convex)
    p.geometry.sample.convex = *o.convex;
  return p;
}

namespace {
std::string case_name(const TesterBenchOptions& o, const CaseParameters& p) {
  const std::string sample = p.geometry.sample.convex ? "convex" : "plain";
  return (o.case_file.empty() ? "the reference " + sample + " sample (built in)"
                              : "case " + o.case_file + ", " + sample + " sample") +
         format(", s = %g", p.dem.psd.scaling_factor);
}
} // namespace

TesterWorkload tester_workload(const TesterBenchOptions& o, bool settle, int threads,
                               double& seconds, std::ostream& out) {
  const meshes::Stopwatch clock;
  CaseParameters p = tester_bench_case(o);
  p.dem.n_threads = threads;
  // The fill runs at least one settling check (0.02 s) whatever its longest time.
  if (!settle)
    p.dem.settle_time = 1e-12;
  const CaseParameters c = tester_scene_case(p);
  TesterWorkload w;
  w.revolution_time =
      p.geometry.tester.sector_angle_deg * pi / 180 / (p.dem.rotation_rate_deg * pi / 180);
  std::vector<dem::SceneWall> walls = dem::build_scene_walls(c.scene, c.geometry);
  out << format("workload tester: %s, as a scene of %zu walls\n", case_name(o, p).c_str(),
                walls.size())
      << std::flush;
  w.scene = std::make_unique<dem::SceneRun>(c.scene, c.dem, std::move(walls));
  auto& scene = *w.scene;
  const bool from_state = !o.state_file.empty() && std::filesystem::exists(o.state_file);
  if (from_state) {
    const Checkpoint k = read_checkpoint(o.state_file);
    if (k.parameters != resolved_parameters(c))
      throw std::invalid_argument("wearsim bench: --state '" + o.state_file +
                                  "' was written by another case or thread count; remove it "
                                  "to write a new one");
    scene.resume(scene_run_state(k.scene, k.dem));
    out << format("state from %s: t = %.4f s\n", o.state_file.c_str(), scene.time());
  } else {
    scene.setup([&](const std::string& text) { out << "scene: " << text << "\n" << std::flush; });
  }
  const double dt = scene.system().time_step();
  w.steps_per_revolution = std::uint64_t(std::llround(w.revolution_time / dt));
  if (!from_state) {
    // The flow steps as a window runs them: the walls turn, the wear integrals open.
    if (o.flow_steps >= w.steps_per_revolution)
      throw std::invalid_argument(format("wearsim bench: --flow %llu is not below the %llu "
                                         "steps of a revolution",
                                         (unsigned long long)o.flow_steps,
                                         (unsigned long long)w.steps_per_revolution));
    if (o.flow_steps > 0) // one window of flow_steps steps (advance rounds to whole steps)
      scene.advance(scene.time() + double(o.flow_steps) * dt);
    out << format("%llu steps of flow, t = %.4f s\n", (unsigned long long)o.flow_steps,
                  scene.time());
  }
  const auto& s = scene.system();
  out << format("%zu particles, %d walls, dt %.4e s (%.0f %% of Rayleigh), %d threads\n",
                s.particles.n_real, s.n_walls(), s.time_step(),
                100 * s.time_step() / s.rayleigh_time(), threads)
      << std::flush;
  if (!from_state && !o.state_file.empty()) {
    Checkpoint k;
    k.parameters = resolved_parameters(c);
    const dem::SceneRunState state = scene.state();
    k.dem = state.system;
    k.scene = scene_checkpoint(state, state.time, 0);
    write_checkpoint(o.state_file, k);
    out << "state written to " << o.state_file << "\n";
  }
  seconds = clock.seconds();
  return w;
}

void report_tester(const TesterWorkload& tester, const std::map<int, double>& median_rates,
                   std::ostream& out) {
  const auto steps = tester.steps_per_revolution;
  const double n = double(tester.scene->system().particles.n_real);
  out << format("tester: %llu steps per revolution (%.3f s simulated)", (unsigned long long)steps,
                tester.revolution_time);
  for (const auto& [th, rate] : median_rates)
    out << format("; %.1f min per revolution with %d threads", double(steps) * n / rate / 60, th);
  out << "\n";
}

} // namespace wear::coupling
