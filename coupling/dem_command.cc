// `wearsim dem <case.prm>`: the circular wear tester in DEM (issue "DEM wear tester").
// Order: resolved parameters -> sample surface (gmsh, no volume mesh) -> bed filled and
// settled -> revolutions, each followed by the evaluation row and a rewrite of the output
// files (atomic), so a killed run leaves complete files of the revolutions it finished.
#include "coupling/dem_command.h"

#include "coupling/tester_output.h"
#include "meshes/atomic_file.h"
#include "meshes/sample_generator.h"
#include "meshes/vtu_writer.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <ostream>

namespace wear::coupling {

namespace {
std::string duration(double s) {
  char b[32];
  if (s < 60)
    std::snprintf(b, sizeof b, "%.0f s", s);
  else if (s < 3600)
    std::snprintf(b, sizeof b, "%.0f min %02.0f s", std::floor(s / 60), std::fmod(s, 60));
  else
    std::snprintf(b, sizeof b, "%.0f h %02.0f min", std::floor(s / 3600),
                  std::floor(std::fmod(s, 3600) / 60));
  return b;
}
} // namespace

void run_dem_command(const CaseParameters& p, std::ostream& log, const DemCommandOptions& options) {
  const std::string dir = p.output.directory;
  meshes::ensure_directory(dir);
  write_resolved_parameters(p, dir + "/parameters.prm");
  meshes::SampleGeometry sg = p.geometry.sample;
  sg.volume_mesh = false; // the DEM needs only the surface
  const auto sample = meshes::generate_sample(sg);
  char line[512];
  std::snprintf(line, sizeof line, "sample: %s, %zu surface triangles (%.1f s)\n",
                sg.convex ? "convex" : "plain", sample.surface.n_faces(), sample.seconds);
  log << line << std::flush;

  dem::WearTester tester(p.geometry, p.dem, p.wear_law, p.deformation, sample.surface);
  const bool live = options.progress && ::isatty(STDERR_FILENO);
  const int n_rev = p.dem.revolutions;
  double rev_seconds = 0; // mean wall time of finished revolutions
  const auto show = [&](const dem::TesterProgress& pr) {
    if (!live)
      return;
    double left = 0;
    if (pr.phase == "revolution" && pr.fraction > 0) {
      const double per_rev = rev_seconds > 0 ? rev_seconds
                                             : tester.steps_per_revolution() *
                                                   double(tester.system().particles.n_real) /
                                                   std::max(1.0, pr.particle_steps_per_second);
      left = (1 - pr.fraction) * per_rev + (n_rev - pr.revolution) * per_rev;
    }
    std::fprintf(stderr,
                 "\r%s %d/%d %5.1f %%  t = %.3f s  %.2e particle-steps/s  time left %s      ",
                 pr.phase.c_str(), pr.revolution, pr.phase == "revolution" ? n_rev : 0,
                 100 * pr.fraction, pr.time, pr.particle_steps_per_second,
                 pr.phase == "revolution" ? duration(left).c_str() : "-");
    std::fflush(stderr);
  };
  const auto fill = tester.fill_and_settle(show);
  if (live)
    std::fprintf(stderr, "\n");
  std::snprintf(line, sizeof line,
                "bed: %zu particles, height %.4f m, packing fraction %.3f, settled in %.3f s; "
                "time step %.3e s (%.0f %% of Rayleigh), %llu steps per revolution, %d threads\n",
                fill.n_particles, fill.bed_height, fill.packing_fraction, fill.settle_time,
                tester.system().time_step(),
                100 * tester.system().time_step() / tester.system().rayleigh_time(),
                static_cast<unsigned long long>(tester.steps_per_revolution()),
                tester.system().n_threads());
  log << line << std::flush;

  TesterOutput output(dir, tester.sample_mesh(), tester.evaluation().element_labels(),
                      tester.evaluation().n_columns());
  output.add_snapshot(tester, 0);
  output.write();
  log << "rev    time[s]  wear[mm^3]  cum[mm^3]  F_n[N]  v_bottom[m/s]  cv_v   cv_h   cv_rate "
         "steady  p-steps/s\n";
  double total_wall = 0;
  for (int r = 1; r <= n_rev; ++r) {
    const auto& rec = tester.run_revolution(show);
    if (live)
      std::fprintf(stderr, "\r%*s\r", 110, "");
    total_wall += rec.wall_seconds;
    rev_seconds = total_wall / r;
    const auto& snaps = p.dem.snapshot_revolutions;
    const bool snapshot = r == n_rev || std::find(snaps.begin(), snaps.end(), r) != snaps.end();
    output.add_revolution(tester, snapshot);
    output.write();
    std::snprintf(
        line, sizeof line, "%3d %10.3f %11.3f %10.3f %7.2f %14.3f %6.3f %6.3f %7.3f %6s %10.3e%s\n",
        r, rec.time, rec.wear_volume * 1e9, rec.wear_volume_cumulative * 1e9, rec.normal_force.mean,
        rec.bottom_speed.mean, rec.speed_over_sample.cv(), rec.bed_height.cv(), rec.wear_rate.cv(),
        rec.steady_revolution ? std::to_string(rec.steady_revolution).c_str() : "-",
        rec.particle_steps_per_second,
        rec.distortion.empty() ? "" : ("  DISTORTED: " + rec.distortion).c_str());
    log << line << std::flush;
    const int after = p.dem.revolutions_after_steady;
    if (after > 0 && rec.steady_revolution > 0 && r - rec.steady_revolution >= after) {
      log << "stopped " << after << " revolution(s) after steady state (revolution "
          << rec.steady_revolution << "), DEM/Revolutions after steady\n";
      break;
    }
  }
  const auto& last = tester.evaluation().history().back();
  std::snprintf(line, sizeof line,
                "fits from revolution %d (%d points): y = a x, a = %.4e m^3 (R^2 = %.4f); "
                "y = b x^2 + c x, b = %.4e, c = %.4e (R^2 = %.4f)\n",
                last.fits_from, last.fits.n_points, last.fits.a, last.fits.r2_linear, last.fits.b,
                last.fits.c, last.fits.r2_quadratic);
  log << line;
  log << "wrote " << output.h5_path() << ", " << output.xdmf_path() << ", " << output.csv_path()
      << " (" << duration(total_wall) << " of revolutions)\n";
}

} // namespace wear::coupling
