// `wearsim scene-run <case.prm>`: a scene's DEM run with its records.
//
// The series table has one row per record: time, particles in the system, inserted and
// removed so far (count and mass), the mass each outlet took so far, and per wall the
// window-mean force and moment about the origin (in the wall's frame: a moving wall's body
// frame) and the window's Archard load-distance; the net mass through each flux plane so
// far. The mass flow through an outlet or a plane is the difference of its column between
// rows over the interval. scene_wear.csv gives the window's Archard load-distance per wall
// and label (per CAD surface), the wear per labelled surface group.
#include "coupling/app/scene_run_command.h"

#include "dem/engine/snapshot.h"
#include "dem/scene/scene_run.h"
#include "meshes/atomic_file.h"
#include "meshes/vtu_writer.h"

#include <cstdio>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace wear::coupling {

namespace {

std::string series_header(const dem::SceneRun& run) {
  std::ostringstream h;
  h << "time_s,n_particles,n_inserted,n_removed,inserted_mass_kg";
  for (const auto& o : run.outlets())
    h << ",outlet_" << o.name << "_mass_kg";
  for (const auto& f : run.flux_planes())
    h << ",flux_" << f.name() << "_mass_kg";
  for (const auto& w : run.walls()) {
    const std::string& n = w.parameters.name;
    h << ",wall_" << n << "_fx_N,wall_" << n << "_fy_N,wall_" << n << "_fz_N,wall_" << n
      << "_mx_Nm,wall_" << n << "_my_Nm,wall_" << n << "_mz_Nm,wall_" << n << "_archard_Nm";
  }
  h << ",mean_speed_m_s,max_speed_m_s\n";
  return h.str();
}

std::string series_row(const dem::SceneWindow& w) {
  std::ostringstream r;
  r.precision(9);
  r << w.t_end << "," << w.n_particles << "," << w.n_inserted << "," << w.n_removed << ","
    << w.inserted_mass;
  for (double m : w.outlet_mass)
    r << "," << m;
  for (double m : w.flux_mass)
    r << "," << m;
  for (const auto& l : w.walls)
    r << "," << l.force.x << "," << l.force.y << "," << l.force.z << "," << l.torque.x << ","
      << l.torque.y << "," << l.torque.z << "," << l.archard;
  r << "," << w.mean_speed << "," << w.max_speed << "\n";
  return r.str();
}

/// The window's Archard load-distance per wall and label (the wear per labelled surface
/// group: a CAD file's surfaces, a primitive's faces).
std::string wear_rows(const dem::SceneRun& run, const dem::SceneWindow& w) {
  std::ostringstream r;
  r.precision(9);
  for (std::size_t k = 0; k < w.walls.size(); ++k)
    for (const auto& [label, archard] : w.walls[k].archard_label)
      r << w.t_end << "," << run.walls()[k].parameters.name << "," << label << "," << archard
        << "\n";
  return r.str();
}

/// The scene's walls where they are now (moving walls at their current pose).
void write_walls(const dem::SceneRun& run, const std::string& dir) {
  meshes::ensure_directory(dir);
  const auto& s = run.system();
  for (int k = 0; k < s.n_walls(); ++k) {
    meshes::SurfaceMesh m = s.wall(k).mesh();
    m.vertices = s.wall(k).world_vertices();
    meshes::write_vtu(m, dir + "/" + s.wall(k).name() + ".vtu");
  }
}

} // namespace

void run_scene_run_command(const CaseParameters& p, std::ostream& log) {
  if (p.scene.walls.empty())
    throw std::invalid_argument("case file '" + p.case_file +
                                "': Scene/Walls is empty: there is no scene to run");
  const std::string& dir = p.output.directory;
  meshes::ensure_directory(dir);
  write_resolved_parameters(p, dir + "/parameters.prm");
  dem::SceneRun run(p.scene, p.dem, dem::build_scene_walls(p.scene));
  run.setup([&](const std::string& text) { log << "scene: " << text << "\n" << std::flush; });
  log << "scene: " << run.walls().size() << " walls, " << run.inlets().size() << " inlets, "
      << run.outlets().size() << " outlets; batches and outlets every " << run.exchange_interval()
      << " s; time step " << (run.system().n_rebuilds() > 0 ? run.system().time_step() : 0.0)
      << " s\n";
  std::string table = series_header(run), wear = "time_s,wall,label,archard_window_Nm\n";
  const double end = p.scene.end_time, every = p.scene.output_interval;
  int record = 0;
  char line[256];
  while (run.time() < end - 1e-9 * every) {
    const dem::SceneWindow w = run.advance(std::min(end, run.time() + every));
    ++record;
    table += series_row(w);
    meshes::write_atomically(dir + "/scene_series.csv", [&](std::ostream& out) { out << table; });
    wear += wear_rows(run, w);
    meshes::write_atomically(dir + "/scene_wear.csv", [&](std::ostream& out) { out << wear; });
    if (w.n_particles > 0)
      dem::write_particles_vtu(run.system().particles,
                               dir + "/particles_" + std::to_string(record) + ".vtu");
    write_walls(run, dir + "/walls_" + std::to_string(record));
    double out_mass = 0;
    for (double m : w.outlet_mass)
      out_mass += m;
    std::snprintf(line, sizeof line,
                  "t = %.4f s: %zu particles, %llu in (%.4g kg), %llu out (%.4g kg), mean speed "
                  "%.3g m/s\n",
                  w.t_end, w.n_particles, static_cast<unsigned long long>(w.n_inserted),
                  w.inserted_mass, static_cast<unsigned long long>(w.n_removed), out_mass,
                  w.mean_speed);
    log << line << std::flush;
  }
  log << "written to " << dir
      << "/ (scene_series.csv, scene_wear.csv, particles_<k>.vtu, walls_<k>/)\n";
}

} // namespace wear::coupling
