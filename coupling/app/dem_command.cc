// `wearsim dem <case.prm>`: the circular wear tester in DEM (issue "DEM wear tester").
// Order: resolved parameters -> sample surface (gmsh, no volume mesh) -> bed filled and
// settled -> revolutions, each followed by the evaluation row and a rewrite of the output
// files (atomic), so a killed run leaves complete files of the revolutions it finished.
// Under mpirun every rank runs the same command on its slab of the bed (WearTester over
// ranks); the records are the same on every rank and rank 0 alone writes and logs.
#include "coupling/app/dem_command.h"

#include "coupling/output/progress_line.h"
#include "coupling/output/tester_output.h"
#include "dem/tester/wear_tester.h"
#include "meshes/atomic_file.h"
#include "meshes/sample_generator.h"

#include <algorithm>
#include <ostream>

namespace wear::coupling {

namespace {

// The live line of a tester run: phase, progress, simulated time, speed and the time left,
// from the mean wall time of the finished revolutions or, before the first, from the speed.
class TesterProgressLine {
public:
  TesterProgressLine(bool enabled, const dem::WearTester& tester, int n_revolutions)
      : line_(enabled), tester_(tester), n_revolutions_(n_revolutions) {}

  void show(const dem::TesterProgress& pr) {
    if (!line_.live())
      return;
    const bool revolving = pr.phase == "revolution";
    line_.show(format("%s %d/%d %5.1f %%  t = %.3f s  %.2e particle-steps/s  time left %s",
                      pr.phase.c_str(), pr.revolution, revolving ? n_revolutions_ : 0,
                      100 * pr.fraction, pr.time, pr.particle_steps_per_second,
                      revolving ? human_duration(seconds_left(pr)).c_str() : "-"));
  }
  /// `n_done` revolutions have finished in `total_seconds` of wall time.
  void finished(double total_seconds, int n_done) { revolution_seconds_ = total_seconds / n_done; }
  ProgressLine& line() { return line_; }

private:
  double seconds_left(const dem::TesterProgress& pr) const {
    if (pr.fraction <= 0)
      return 0;
    const double per_rev = revolution_seconds_ > 0
                               ? revolution_seconds_
                               : tester_.steps_per_revolution() *
                                     double(tester_.system().particles.n_real) /
                                     std::max(1.0, pr.particle_steps_per_second);
    return (1 - pr.fraction) * per_rev + (n_revolutions_ - pr.revolution) * per_rev;
  }

  ProgressLine line_;
  const dem::WearTester& tester_;
  int n_revolutions_;
  double revolution_seconds_ = 0; ///< [s] mean wall time of finished revolutions
};

meshes::GeneratedSample sample_surface(const meshes::SampleGeometry& geometry, std::ostream& log) {
  meshes::SampleGeometry sg = geometry;
  sg.volume_mesh = false; // the DEM needs only the surface
  auto sample = meshes::generate_sample(sg);
  log << format("sample: %s, %zu surface triangles (%.1f s)\n", sg.convex ? "convex" : "plain",
                sample.surface.n_faces(), sample.seconds)
      << std::flush;
  return sample;
}

void log_bed(const dem::FillReport& fill, const dem::WearTester& tester, std::ostream& log) {
  const auto& s = tester.system();
  log << format("bed: %zu particles, height %.4f m, packing fraction %.3f, settled in %.3f s; "
                "time step %.3e s (%.0f %% of Rayleigh), %llu steps per revolution, %d threads\n",
                fill.n_particles, fill.bed_height, fill.packing_fraction, fill.settle_time,
                s.time_step(), 100 * s.time_step() / s.rayleigh_time(),
                static_cast<unsigned long long>(tester.steps_per_revolution()), s.n_threads())
      << std::flush;
}

void log_revolution(int r, const dem::RevolutionRecord& rec, std::ostream& log) {
  log << format("%3d %10.3f %11.3f %10.3f %7.2f %14.3f %6.3f %6.3f %7.3f %6s %10.3e%s\n", r,
                rec.time, rec.wear_volume * 1e9, rec.wear_volume_cumulative * 1e9,
                rec.normal_force.mean, rec.bottom_speed.mean, rec.speed_over_sample.cv(),
                rec.bed_height.cv(), rec.wear_rate.cv(),
                rec.steady_revolution ? std::to_string(rec.steady_revolution).c_str() : "-",
                rec.particle_steps_per_second,
                rec.distortion.empty() ? "" : ("  DISTORTED: " + rec.distortion).c_str())
      << std::flush;
}

// DEM/Revolutions after steady: true (and says so) when the run is to stop after revolution r.
bool stop_after_steady(const dem::TesterDemParameters& d, int r, const dem::RevolutionRecord& rec,
                       std::ostream& log) {
  const int after = d.revolutions_after_steady;
  if (!(after > 0 && rec.steady_revolution > 0 && r - rec.steady_revolution >= after))
    return false;
  log << "stopped " << after << " revolution(s) after steady state (revolution "
      << rec.steady_revolution << "), DEM/Revolutions after steady\n";
  return true;
}

// The revolutions, each logged and written; returns their wall time [s].
double run_revolutions(const dem::TesterDemParameters& d, dem::WearTester& tester,
                       TesterOutput& output, TesterProgressLine& progress, std::ostream& log,
                       bool writer) {
  log << "rev    time[s]  wear[mm^3]  cum[mm^3]  F_n[N]  v_bottom[m/s]  cv_v   cv_h   cv_rate "
         "steady  p-steps/s\n";
  const auto show = [&](const dem::TesterProgress& pr) { progress.show(pr); };
  double total_wall = 0;
  for (int r = 1; r <= d.revolutions; ++r) {
    const auto& rec = tester.run_revolution(show);
    progress.line().clear();
    total_wall += rec.wall_seconds;
    progress.finished(total_wall, r);
    const auto& snaps = d.snapshot_revolutions;
    const bool snapshot =
        r == d.revolutions || std::find(snaps.begin(), snaps.end(), r) != snaps.end();
    output.add_revolution(tester, snapshot);
    if (writer)
      output.write();
    log_revolution(r, rec, log);
    if (stop_after_steady(d, r, rec, log))
      break;
  }
  return total_wall;
}

void log_fits(const dem::TesterEvaluation& evaluation, std::ostream& log) {
  const auto& last = evaluation.history().back();
  log << format("fits from revolution %d (%d points): y = a x, a = %.4e m^3 (R^2 = %.4f); "
                "y = b x^2 + c x, b = %.4e, c = %.4e (R^2 = %.4f)\n",
                last.fits_from, last.fits.n_points, last.fits.a, last.fits.r2_linear, last.fits.b,
                last.fits.c, last.fits.r2_quadratic);
}

} // namespace

void run_dem_command(const CaseParameters& p, std::ostream& log_to,
                     const DemCommandOptions& options) {
  const int rank = options.ranks ? options.ranks->rank() : 0;
  const int n_ranks = options.ranks ? options.ranks->n_ranks() : 1;
  const bool writer = rank == 0;
  std::ostream silent(nullptr); // the ranks after the first compute without a word
  std::ostream& log = writer ? log_to : silent;
  const std::string dir = p.output.directory;
  if (writer) {
    meshes::ensure_directory(dir);
    write_resolved_parameters(p, dir + "/parameters.prm");
  }
  const auto sample = sample_surface(p.geometry.sample, log);

  dem::WearTester tester(p.geometry, p.dem, p.wear_law, p.deformation, sample.surface);
  tester.set_rank_link(options.ranks);
  if (n_ranks > 1)
    log << tester.rank_layout() << std::endl;
  TesterProgressLine progress(options.progress && writer, tester, p.dem.revolutions);
  const auto fill =
      tester.fill_and_settle([&](const dem::TesterProgress& pr) { progress.show(pr); });
  progress.line().keep();
  log_bed(fill, tester, log);

  TesterOutput output(dir, tester.sample_mesh(), tester.evaluation().element_labels(),
                      tester.evaluation().n_columns());
  output.add_snapshot(tester, 0);
  if (writer)
    output.write();
  const double total_wall = run_revolutions(p.dem, tester, output, progress, log, writer);
  log_fits(tester.evaluation(), log);
  log << "wrote " << output.h5_path() << ", " << output.xdmf_path() << ", " << output.csv_path()
      << " (" << human_duration(total_wall) << " of revolutions)\n";
}

} // namespace wear::coupling
