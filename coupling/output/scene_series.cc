// A scene run's records (scene_series.h).
//
// The mass flow through an outlet or a plane is the difference of its column between rows
// over the interval; the force and moment columns are window means (impulse / duration).
#include "coupling/output/scene_series.h"

#include "coupling/output/hdf5_file.h"
#include "dem/engine/snapshot.h"
#include "dem/scene/wall_catalogue.h"
#include "meshes/atomic_file.h"
#include "meshes/vtu_writer.h"

#include <cstdio>
#include <fstream>
#include <iomanip>
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

std::string wear_rows(const dem::SceneRun& run, const dem::SceneWindow& w) {
  std::ostringstream r;
  r.precision(9);
  for (std::size_t k = 0; k < w.walls.size(); ++k)
    for (const auto& [label, archard] : w.walls[k].archard_label)
      // A part's surfaces by role (S6, S5-clamped); other walls' labels are their CAD
      // surface numbers as they are.
      r << w.t_end << "," << run.walls()[k].parameters.name << ","
        << (meshes::label::is_part_surface(label) ? meshes::label::name(label)
                                                  : std::to_string(label))
        << "," << archard << "\n";
  return r.str();
}

/// Wall k where it is now (a moving wall at its current pose; an exact surface of
/// revolution, which keeps its place, as its triangles).
void write_wall(const dem::SceneRun& run, int k, const std::string& dir) {
  const std::string path = dir + "/" + run.walls()[std::size_t(k)].parameters.name + ".vtu";
  if (run.system().wall_kind(k) == dem::WallKind::revolution) {
    meshes::write_vtu(run.walls()[std::size_t(k)].surface.mesh, path);
    return;
  }
  const auto& wall = run.system().wall(k);
  meshes::SurfaceMesh m = wall.mesh();
  m.vertices = wall.world_vertices();
  meshes::write_vtu(m, path);
}

} // namespace

SceneSeries::SceneSeries(std::string directory, const dem::SceneRun& run)
    : directory_(std::move(directory)), series_(series_header(run)),
      wear_("time_s,wall,label,archard_window_Nm\n") {
  meshes::ensure_directory(directory_ + "/walls");
  for (std::size_t k = 0; k < run.walls().size(); ++k) {
    const auto& p = run.walls()[k].parameters;
    // Only a wall moving as a rigid body changes its place between records; a fixed wall or
    // one whose surface moves in place (a belt, a turning floor) is written once. A wearing
    // part changes at stage ends only: the wear loop's surface series has it.
    changing_.push_back(dem::wall_motion_of(p).rigid);
    if (!changing_.back())
      write_wall(run, int(k), directory_ + "/walls");
  }
}

namespace {
/// The lines of `path` (without their line ends).
std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error("--resume: the run's table '" + path + "' is missing");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}
} // namespace

SceneSeries::SceneSeries(std::string directory, const dem::SceneRun& run, int n_records,
                         int first_record, EarlierRows earlier)
    : SceneSeries(std::move(directory), run) {
  n_records_ = n_records;
  first_record_ = earlier == EarlierRows::absent ? n_records + 1 : first_record;
  if (earlier == EarlierRows::absent)
    return;
  // The tables hold records first_record_ to n_records, one row each after the header.
  const int n_rows = n_records - first_record_ + 1;
  const auto series = lines_of(directory_ + "/scene_series.csv");
  if (int(series.size()) < n_rows + 1)
    throw std::runtime_error("--resume: '" + directory_ + "/scene_series.csv' holds " +
                             std::to_string(series.size() - 1) + " records, the checkpoint " +
                             std::to_string(n_rows) +
                             (first_record_ > 1 ? " (records " + std::to_string(first_record_) +
                                                      " to " + std::to_string(n_records) + ")"
                                                : std::string()));
  series_.clear();
  for (int k = 0; k <= n_rows; ++k)
    series_ += series[std::size_t(k)] + "\n";
  // scene_wear.csv: a record's rows share its time (the first column).
  const auto wear = lines_of(directory_ + "/scene_wear.csv");
  wear_ = wear.at(0) + "\n";
  std::string time;
  int records = 0;
  for (std::size_t k = 1; k < wear.size(); ++k) {
    const std::string t = wear[k].substr(0, wear[k].find(','));
    if (t != time && ++records > n_rows)
      break;
    time = t;
    wear_ += wear[k] + "\n";
  }
  for (int k = first_record_; run.fields() && k <= n_records; ++k) {
    char name[64];
    std::snprintf(name, sizeof name, "/fields/record_%04d.h5", k);
    const Hdf5Reader h5(directory_ + name);
    field_records_.emplace_back(k, h5.attribute("/", "time"));
  }
}

void SceneSeries::add(const dem::SceneWindow& w, const dem::SceneRun& run,
                      const dem::Particles& particles, const dem::Clumps* clumps, bool snapshot) {
  const int k = ++n_records_;
  series_ += series_row(w);
  meshes::write_atomically(directory_ + "/scene_series.csv",
                           [&](std::ostream& out) { out << series_; });
  wear_ += wear_rows(run, w);
  meshes::write_atomically(directory_ + "/scene_wear.csv",
                           [&](std::ostream& out) { out << wear_; });
  if (snapshot && w.n_particles > 0)
    dem::write_particles_vtu(particles, directory_ + "/particles_" + std::to_string(k) + ".vtu",
                             clumps);
  if (run.fields())
    write_fields(k, w, run.fields()->grid());
  const std::string dir = directory_ + "/walls_" + std::to_string(k);
  bool made = false;
  for (std::size_t j = 0; j < changing_.size(); ++j)
    if (changing_[j]) {
      if (!std::exchange(made, true))
        meshes::ensure_directory(dir);
      write_wall(run, int(j), dir);
    }
}

void SceneSeries::write_fields(int k, const dem::SceneWindow& w, const dem::FieldGrid& grid) {
  const std::size_t nx = std::size_t(grid.cells[0]), ny = std::size_t(grid.cells[1]),
                    nz = std::size_t(grid.cells[2]);
  char name[64];
  std::snprintf(name, sizeof name, "fields/record_%04d.h5", k);
  meshes::ensure_directory(directory_ + "/fields");
  Hdf5File h5(directory_ + "/" + name);
  std::vector<double> velocity;
  velocity.reserve(3 * w.fields.velocity.size());
  for (const auto& v : w.fields.velocity)
    velocity.insert(velocity.end(), {v.x, v.y, v.z});
  h5.write("solid_fraction", w.fields.solid_fraction, {nz, ny, nx});
  h5.write("velocity", velocity, {nz, ny, nx, 3});
  h5.write("occupancy", w.fields.occupancy, {nz, ny, nx});
  h5.attribute("/", "time", w.t_end);
  h5.attribute("/", "samples", double(w.fields.n_samples));
  const char* axis[3] = {"x", "y", "z"};
  for (int d = 0; d < 3; ++d) { // the grid, so that the file describes itself [m]
    h5.attribute("/", std::string(axis[d]) + "_minimum", grid.minimum[d]);
    h5.attribute("/", std::string(axis[d]) + "_maximum", grid.maximum[d]);
  }
  h5.commit();
  field_records_.emplace_back(k, w.t_end);
  // XDMF orders a co-rectilinear grid's dimensions, origin and spacing z, y, x.
  const dem::Vec3 h = grid.spacing();
  meshes::write_atomically(directory_ + "/fields.xdmf", [&](std::ostream& x) {
    x << std::setprecision(12);
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n"
      << "<Grid Name=\"fields\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& [record, time] : field_records_) {
      char file[64];
      std::snprintf(file, sizeof file, "fields/record_%04d.h5", record);
      x << "<Grid Name=\"record " << record << "\" GridType=\"Uniform\">\n"
        << "<Time Value=\"" << time << "\"/>\n"
        << "<Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << nz + 1 << " " << ny + 1 << " "
        << nx + 1 << "\"/>\n"
        << "<Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
        << "<DataItem Format=\"XML\" Dimensions=\"3\">" << grid.minimum.z << " " << grid.minimum.y
        << " " << grid.minimum.x << "</DataItem>\n"
        << "<DataItem Format=\"XML\" Dimensions=\"3\">" << h.z << " " << h.y << " " << h.x
        << "</DataItem>\n</Geometry>\n";
      const auto attribute = [&](const char* n, const char* type, const std::string& dims) {
        x << "<Attribute Name=\"" << n << "\" AttributeType=\"" << type
          << "\" Center=\"Cell\">\n<DataItem Format=\"HDF\" NumberType=\"Float\" "
             "Precision=\"8\" Dimensions=\""
          << dims << "\">" << file << ":/" << n << "</DataItem>\n</Attribute>\n";
      };
      const std::string cells =
          std::to_string(nz) + " " + std::to_string(ny) + " " + std::to_string(nx);
      attribute("solid_fraction", "Scalar", cells);
      attribute("velocity", "Vector", cells + " 3");
      attribute("occupancy", "Scalar", cells);
      x << "</Grid>\n";
    }
    x << "</Grid>\n</Domain>\n</Xdmf>\n";
  });
}

std::string window_summary(const dem::SceneWindow& w) {
  double out_mass = 0;
  for (double m : w.outlet_mass)
    out_mass += m;
  char line[256];
  std::snprintf(line, sizeof line,
                "t = %.4f s: %zu particles, %llu in (%.4g kg), %llu out (%.4g kg), mean speed "
                "%.3g m/s",
                w.t_end, w.n_particles, static_cast<unsigned long long>(w.n_inserted),
                w.inserted_mass, static_cast<unsigned long long>(w.n_removed), out_mass,
                w.mean_speed);
  return line;
}

} // namespace wear::coupling
