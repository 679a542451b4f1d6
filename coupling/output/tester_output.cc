// Wear-tester output files.
//
// history.h5 layout:
//   /mesh/vertices (nv x 3) [m], /mesh/triangles (nf x 3), /mesh/labels (nf)
//   /revolution_NNNN/ with attributes time [s] and revolution, datasets
//     vertices (nv x 3, only when the surface moved), impulse (nf x 3) [N s],
//     traction_impulse (nf x 3) [N s] (the impulse as the FEM receives it, coarse-grained
//     unless DEM/Wall traction = per face), normal_impulse [N s], archard [N m],
//     sliding_work [J], contact_steps [-], removed_volume [m^3] (this revolution),
//     cumulative_removed_volume [m^3], and, for viewing only, wear_depth =
//     cumulative_removed_volume / area [m], mean_pressure = normal_impulse / (revolution
//     time x area) [Pa] and traction = traction_impulse / (revolution time x area) (nf x 3) [Pa]
//   /particles/revolution_NNNN/ position, velocity, angular_velocity (n x 3), radius, id
// history.xdmf: a temporal collection of the sample surface (cell data per revolution) and
// one of the particle snapshots (point data), both reading the datasets above.
#include "coupling/output/tester_output.h"

#include "coupling/output/hdf5_file.h"
#include "meshes/atomic_file.h"

#include <cstdio>
#include <iomanip>
#include <sstream>

namespace wear::coupling {

namespace {
std::string revolution_group(int r) {
  char b[32];
  std::snprintf(b, sizeof b, "revolution_%04d", r);
  return b;
}

std::vector<double> flatten(const std::vector<meshes::Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const auto& x : v) {
    out.push_back(x.x);
    out.push_back(x.y);
    out.push_back(x.z);
  }
  return out;
}
} // namespace

TesterOutput::TesterOutput(std::string directory, const meshes::SurfaceMesh& initial_surface,
                           const std::vector<int>& element_labels, int n_columns)
    : directory_(std::move(directory)), initial_(initial_surface), element_labels_(element_labels),
      n_columns_(n_columns) {}

void TesterOutput::add_revolution(dem::WearTester& tester, bool snapshot) {
  const auto& loads = tester.last_loads();
  const auto& mesh = tester.sample_mesh();
  Revolution r;
  r.revolution = tester.n_revolutions_done();
  r.time = tester.system().time();
  if (mesh.revision() != initial_.revision() || mesh.vertices != initial_.vertices)
    r.vertices = flatten(mesh.vertices);
  loads.impulse.check_matches(mesh);
  r.impulse = flatten(loads.impulse.values());
  r.traction_impulse = flatten(loads.traction_impulse.values());
  r.normal_impulse = loads.normal_impulse.values();
  r.archard = loads.archard.values();
  r.sliding_work = loads.sliding_work.values();
  r.contact_steps = loads.contact_steps.values();
  r.removed_volume = loads.wear_volume.values();
  r.cumulative_removed_volume = tester.cumulative_removed_volume();
  const auto area = meshes::face_areas(mesh);
  const std::size_t nf = area.size();
  r.wear_depth.resize(nf);
  r.mean_pressure.resize(nf);
  r.traction.resize(3 * nf);
  for (std::size_t f = 0; f < nf; ++f) {
    r.wear_depth[f] = r.cumulative_removed_volume[f] / area[f];
    r.mean_pressure[f] = loads.normal_impulse[f] / (tester.revolution_time() * area[f]);
    for (int k = 0; k < 3; ++k)
      r.traction[3 * f + k] = r.traction_impulse[3 * f + k] / (tester.revolution_time() * area[f]);
  }
  revolutions_.push_back(std::move(r));
  records_ = tester.evaluation().history();
  if (snapshot)
    add_snapshot(tester, tester.n_revolutions_done());
}

void TesterOutput::add_snapshot(dem::WearTester& tester, int revolution) {
  {
    const dem::Particles& p = tester.bed_particles(); // over ranks: every rank's
    Snapshot s;
    s.revolution = revolution;
    s.time = tester.system().time();
    const std::size_t n = p.n_real;
    s.position = flatten({p.position.begin(), p.position.begin() + n});
    s.velocity = flatten({p.velocity.begin(), p.velocity.begin() + n});
    s.angular_velocity = flatten({p.angular_velocity.begin(), p.angular_velocity.begin() + n});
    s.radius.assign(p.radius.begin(), p.radius.begin() + n);
    s.id.assign(p.id.begin(), p.id.begin() + n);
    snapshots_.push_back(std::move(s));
  }
}

void TesterOutput::write() const {
  write_h5();
  write_xdmf();
  write_csv();
}

void TesterOutput::write_h5() const {
  Hdf5File h5(h5_path());
  const std::size_t nf = initial_.n_faces(), nv = initial_.n_vertices();
  h5.write("/mesh/vertices", flatten(initial_.vertices), {nv, 3});
  std::vector<std::int64_t> tri;
  tri.reserve(3 * nf);
  for (const auto& t : initial_.triangles)
    for (int k = 0; k < 3; ++k)
      tri.push_back(t[k]);
  h5.write("/mesh/triangles", tri, {nf, 3});
  h5.write("/mesh/labels", initial_.face_labels, {nf});
  for (const auto& r : revolutions_) {
    const std::string g = "/" + revolution_group(r.revolution);
    if (!r.vertices.empty())
      h5.write(g + "/vertices", r.vertices, {nv, 3});
    h5.write(g + "/impulse", r.impulse, {nf, 3});
    h5.write(g + "/traction_impulse", r.traction_impulse, {nf, 3});
    h5.write(g + "/traction", r.traction, {nf, 3});
    h5.write(g + "/normal_impulse", r.normal_impulse, {nf});
    h5.write(g + "/archard", r.archard, {nf});
    h5.write(g + "/sliding_work", r.sliding_work, {nf});
    h5.write(g + "/contact_steps", r.contact_steps, {nf});
    h5.write(g + "/removed_volume", r.removed_volume, {nf});
    h5.write(g + "/cumulative_removed_volume", r.cumulative_removed_volume, {nf});
    h5.write(g + "/wear_depth", r.wear_depth, {nf});
    h5.write(g + "/mean_pressure", r.mean_pressure, {nf});
    h5.attribute(g, "time", r.time);
    h5.attribute(g, "revolution", double(r.revolution));
  }
  for (const auto& s : snapshots_) {
    const std::string g = "/particles/" + revolution_group(s.revolution);
    const std::size_t n = s.radius.size();
    h5.write(g + "/position", s.position, {n, 3});
    h5.write(g + "/velocity", s.velocity, {n, 3});
    h5.write(g + "/angular_velocity", s.angular_velocity, {n, 3});
    h5.write(g + "/radius", s.radius, {n});
    h5.write(g + "/id", s.id, {n});
    h5.attribute(g, "time", s.time);
  }
  h5.commit();
}

void TesterOutput::write_xdmf() const {
  const std::size_t nf = initial_.n_faces(), nv = initial_.n_vertices();
  const std::string file = "history.h5";
  meshes::write_atomically(xdmf_path(), [&](std::ostream& x) {
    const auto item = [&](const std::string& dims, const std::string& type,
                          const std::string& path) {
      x << "        <DataItem Dimensions=\"" << dims << "\" NumberType=\"" << type
        << "\" Precision=\"8\" Format=\"HDF\">" << file << ":" << path << "</DataItem>\n";
    };
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n";
    x << "  <Grid Name=\"sample\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    std::string geometry = "/mesh/vertices";
    for (const auto& r : revolutions_) {
      const std::string g = "/" + revolution_group(r.revolution);
      if (!r.vertices.empty())
        geometry = g + "/vertices";
      x << "    <Grid Name=\"" << revolution_group(r.revolution) << "\" GridType=\"Uniform\">\n"
        << "      <Time Value=\"" << std::setprecision(10) << r.time << "\"/>\n"
        << "      <Topology TopologyType=\"Triangle\" NumberOfElements=\"" << nf << "\">\n";
      item(std::to_string(nf) + " 3", "Int", "/mesh/triangles");
      x << "      </Topology>\n      <Geometry GeometryType=\"XYZ\">\n";
      item(std::to_string(nv) + " 3", "Float", geometry);
      x << "      </Geometry>\n";
      x << "      <Attribute Name=\"label\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
      x << "        <DataItem Dimensions=\"" << nf
        << "\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" << file
        << ":/mesh/labels</DataItem>\n      </Attribute>\n";
      for (const char* name : {"impulse", "traction_impulse", "traction"}) {
        x << "      <Attribute Name=\"" << name << "\" AttributeType=\"Vector\" Center=\"Cell\">\n";
        item(std::to_string(nf) + " 3", "Float", g + "/" + name);
        x << "      </Attribute>\n";
      }
      for (const char* name :
           {"normal_impulse", "archard", "sliding_work", "contact_steps", "removed_volume",
            "cumulative_removed_volume", "wear_depth", "mean_pressure"}) {
        x << "      <Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
        item(std::to_string(nf), "Float", g + "/" + name);
        x << "      </Attribute>\n";
      }
      x << "    </Grid>\n";
    }
    x << "  </Grid>\n";
    if (!snapshots_.empty()) {
      x << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (const auto& s : snapshots_) {
        const std::string g = "/particles/" + revolution_group(s.revolution);
        const std::size_t n = s.radius.size();
        x << "    <Grid Name=\"particles_" << s.revolution << "\" GridType=\"Uniform\">\n"
          << "      <Time Value=\"" << std::setprecision(10) << s.time << "\"/>\n"
          << "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\"/>\n"
          << "      <Geometry GeometryType=\"XYZ\">\n";
        item(std::to_string(n) + " 3", "Float", g + "/position");
        x << "      </Geometry>\n";
        for (const char* name : {"velocity", "angular_velocity"}) {
          x << "      <Attribute Name=\"" << name
            << "\" AttributeType=\"Vector\" Center=\"Node\">\n";
          item(std::to_string(n) + " 3", "Float", g + "/" + name);
          x << "      </Attribute>\n";
        }
        x << "      <Attribute Name=\"radius\" AttributeType=\"Scalar\" Center=\"Node\">\n";
        item(std::to_string(n), "Float", g + "/radius");
        x << "      </Attribute>\n    </Grid>\n";
      }
      x << "  </Grid>\n";
    }
    x << "</Domain>\n</Xdmf>\n";
  });
}

void write_summary_header(std::ostream& c, int n_columns, const std::vector<int>& element_labels) {
  c << "revolution,time_s,wear_volume_m3,wear_volume_cumulative_m3,wear_volume_other_m3,"
       "contact_total_wear_volume_m3";
  for (int k = 1; k <= n_columns; ++k)
    c << ",column" << k << "_wear_m3";
  for (int l : element_labels)
    c << "," << meshes::label::name(l) << "_wear_m3";
  c << ",mean_element_increment_m3,normal_force_mean_N,normal_force_std_N";
  for (int k = 1; k <= n_columns; ++k)
    c << ",column" << k << "_force_mean_N,column" << k << "_force_std_N";
  c << ",bottom_speed_mean_m_s,bottom_speed_std_m_s,bottom_spin_mean_rad_s,"
       "bottom_spin_std_rad_s,bottom_count,speed_over_sample_mean_m_s,cv_speed,"
       "bed_height_mean_m,cv_bed_height,wear_rate_mean_m3_s,cv_wear_rate,steady,"
       "steady_revolution,fit_from_revolution,fit_linear_a_m3,fit_linear_r2,fit_quadratic_b_m3,"
       "fit_quadratic_c_m3,fit_quadratic_r2,swept_volume_m3,applied_volume_m3,"
       "enclosed_volume_loss_m3,min_angle_deg,distortion,wall_seconds,particle_steps_per_s";
}

void write_summary_row(std::ostream& c, const dem::RevolutionRecord& r,
                       const std::vector<int>& element_labels) {
  c << std::setprecision(10);
  c << r.revolution << "," << r.time << "," << r.wear_volume << "," << r.wear_volume_cumulative
    << "," << r.wear_volume_other << "," << r.contact_total_wear_volume;
  for (double v : r.column_wear)
    c << "," << v;
  for (int l : element_labels) {
    const auto it = r.element_wear.find(l);
    c << "," << (it == r.element_wear.end() ? 0.0 : it->second);
  }
  c << "," << r.mean_element_increment << "," << r.normal_force.mean << "," << r.normal_force.std;
  for (const auto& s : r.column_normal_force)
    c << "," << s.mean << "," << s.std;
  c << "," << r.bottom_speed.mean << "," << r.bottom_speed.std << "," << r.bottom_spin.mean << ","
    << r.bottom_spin.std << "," << r.bottom_count << "," << r.speed_over_sample.mean << ","
    << r.speed_over_sample.cv() << "," << r.bed_height.mean << "," << r.bed_height.cv() << ","
    << r.wear_rate.mean << "," << r.wear_rate.cv() << "," << (r.steady ? 1 : 0) << ","
    << r.steady_revolution << "," << r.fits_from << "," << r.fits.a << "," << r.fits.r2_linear
    << "," << r.fits.b << "," << r.fits.c << "," << r.fits.r2_quadratic << "," << r.swept_volume
    << "," << r.applied_volume << "," << r.enclosed_volume_loss << "," << r.min_angle_deg << ",\""
    << r.distortion << "\"," << r.wall_seconds << "," << r.particle_steps_per_second;
}

void TesterOutput::write_csv() const {
  meshes::write_atomically(csv_path(), [&](std::ostream& c) {
    write_summary_header(c, n_columns_, element_labels_);
    c << "\n";
    for (const auto& r : records_) {
      write_summary_row(c, r, element_labels_);
      c << "\n";
    }
  });
}

} // namespace wear::coupling
