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

#include "coupling/output/progress_line.h"
#include "meshes/sample_generator.h"
#include "meshes/stopwatch.h"

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
  const auto fill = tester->fill_and_settle();
  // Opens a revolution and stops it before its first step: rotation on, wear window open.
  tester->advance_revolution({}, [] { return true; });
  const auto& s = tester->system();
  out << format("%zu particles, %d walls, dt %.4e s (%.0f %% of Rayleigh), %d threads; bed "
                "height %.4f m, packing fraction %.3f, %s %.3f s simulated\n",
                s.particles.n_real, s.n_walls(), s.time_step(),
                100 * s.time_step() / s.rayleigh_time(), threads, fill.bed_height,
                fill.packing_fraction, settle ? "settled in" : "settling skipped after",
                fill.settle_time)
      << std::flush;
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
