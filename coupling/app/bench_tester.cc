// The `tester` workload of `wearsim bench dem`: what users run, timed. The case's sample
// surface is generated (surface only, as `wearsim dem` does), the tester is assembled with
// the sample as its wearing wall, the bed is filled from the PSD and settled with the walls
// at rest (dem::WearTester::fill_and_settle, the same call as `wearsim dem`), and a
// revolution is opened without running any step: the floor and cylinders turn and the
// engine accumulates the per-face wear integrals in its wall pass from there on. The timed
// steps are then plain System::run steps; the evaluation samples and output files of a real
// revolution (a few per revolution) are not part of the figure.
// A revolution is T = Theta / omega and round(T / dt) steps, so at a median rate R
// [particle-steps/s] it takes steps x N / R seconds.
#include "coupling/app/bench_tester.h"

#include "coupling/output/checkpoint.h"
#include "coupling/output/progress_line.h"
#include "meshes/sample_generator.h"
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

// The state of `tester` with its open revolution, as an in-stage checkpoint of a run of p.
Checkpoint bench_state(const dem::WearTester& tester, const CaseParameters& p) {
  Checkpoint c;
  c.parameters = resolved_parameters(p);
  c.dem = tester.system().export_state();
  const auto n_faces = tester.sample_mesh().n_faces();
  c.face_von_mises.assign(n_faces, 0.0);
  c.dem_cumulative.assign(n_faces, 0.0);
  c.open_stage = open_stage(dem::WallLoads{}, 0, 0, *tester.open_revolution());
  return c;
}
} // namespace

std::unique_ptr<dem::WearTester> tester_workload(const TesterBenchOptions& o, bool settle,
                                                 int threads, double& seconds, std::ostream& out) {
  const meshes::Stopwatch clock;
  CaseParameters p = tester_bench_case(o);
  p.dem.n_threads = threads;
  // fill_to_height runs at least one settling check (0.02 s) whatever its longest time.
  if (!settle)
    p.dem.settle_time = 1e-12;
  meshes::SampleGeometry sg = p.geometry.sample;
  sg.volume_mesh = false;
  const auto sample = meshes::generate_sample(sg);
  out << format("workload tester: %s; %zu sample triangles (%.1f s)\n", case_name(o, p).c_str(),
                sample.surface.n_faces(), sample.seconds)
      << std::flush;
  auto tester = std::make_unique<dem::WearTester>(p.geometry, p.dem, p.wear_law, p.deformation,
                                                  sample.surface);
  const bool from_state = !o.state_file.empty() && std::filesystem::exists(o.state_file);
  if (from_state) {
    const Checkpoint c = read_checkpoint(o.state_file);
    if (c.parameters != resolved_parameters(p) || !c.open_stage)
      throw std::invalid_argument("wearsim bench: --state '" + o.state_file +
                                  "' was written by another case or thread count; remove it "
                                  "to write a new one");
    tester->restore(c.dem, 0, {}, c.open_stage->revolution);
    out << format("state from %s: t = %.4f s, %llu steps of the revolution done\n",
                  o.state_file.c_str(), c.dem.time,
                  (unsigned long long)c.open_stage->revolution.steps_done);
  } else {
    const auto fill = tester->fill_and_settle();
    out << format("bed height %.4f m, packing fraction %.3f, %s %.3f s simulated\n",
                  fill.bed_height, fill.packing_fraction,
                  settle ? "settled in" : "settling skipped after", fill.settle_time);
    // Opens a revolution (rotation on, wear window open) and runs it, evaluation samples
    // included, for the flow steps (rounded up to the revolution's stop checks).
    if (o.flow_steps >= tester->steps_per_revolution())
      throw std::invalid_argument(format("wearsim bench: --flow %llu is not below the %llu "
                                         "steps of a revolution",
                                         (unsigned long long)o.flow_steps,
                                         (unsigned long long)tester->steps_per_revolution()));
    const std::uint64_t n0 = tester->system().n_steps();
    tester->advance_revolution({}, [&] { return tester->system().n_steps() - n0 >= o.flow_steps; });
  }
  const auto& s = tester->system();
  out << format("%zu particles, %d walls, dt %.4e s (%.0f %% of Rayleigh), %d threads, %llu "
                "steps of the revolution done before the timing\n",
                s.particles.n_real, s.n_walls(), s.time_step(),
                100 * s.time_step() / s.rayleigh_time(), threads,
                (unsigned long long)tester->open_revolution()->steps_done)
      << std::flush;
  if (!from_state && !o.state_file.empty()) {
    write_checkpoint(o.state_file, bench_state(*tester, p));
    out << "state written to " << o.state_file << "\n";
  }
  seconds = clock.seconds();
  return tester;
}

void report_tester(const dem::WearTester& tester, const std::map<int, double>& median_rates,
                   std::ostream& out) {
  const auto steps = tester.steps_per_revolution();
  const double n = double(tester.system().particles.n_real);
  out << format("tester: %llu steps per revolution (%.3f s simulated)", (unsigned long long)steps,
                tester.revolution_time());
  for (const auto& [th, rate] : median_rates)
    out << format("; %.1f min per revolution with %d threads", double(steps) * n / rate / 60, th);
  out << "\n";
}

} // namespace wear::coupling
