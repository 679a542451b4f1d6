// Output of a coupled run.
//
// summary.csv: the wear tester's per-revolution columns (summary_columns.h), then the columns
// of the stage the revolution belongs to: stage, scheme, amplification, the volume the stage
// asked of the geometry and the change the geometry made, remeshes so far, the smallest
// scaled Jacobian handed on, the peak von Mises stress (ball-averaged, then at a quadrature
// point: mesh-dependent) and safety factor, pushed particles.
// stages.csv: every StageRecord field (stage_columns()) plus the scheme name and distortion.
// history.h5: /revolutions/<column> and /stages/<column>, one value per row, for scripts.
#include "coupling/output/run_output.h"

#include "coupling/output/hdf5_file.h"
#include "coupling/output/summary_columns.h"
#include "coupling/parameters/coupling_parameters.h"
#include "meshes/atomic_file.h"

#include <fstream>
#include <iomanip>

namespace wear::coupling {

RunOutput::RunOutput(std::string directory, bool writes)
    : directory_(std::move(directory)), writes_(writes), surface_(directory_, "surface"),
      volume_(directory_, "volume") {}

void RunOutput::add_surface(int stage, double time, const meshes::SurfaceMesh& surface,
                            const std::vector<meshes::VtuArray>& cell_fields) {
  if (!writes_)
    return;
  meshes::VtuGrid g;
  g.points = surface.vertices;
  g.cell_type = meshes::VtkCell::triangle;
  for (const auto& t : surface.triangles)
    g.connectivity.insert(g.connectivity.end(), t.begin(), t.end());
  g.cell_data = cell_fields;
  g.cell_data.push_back({"label", 1, {surface.face_labels.begin(), surface.face_labels.end()}});
  surface_.add_stage(stage, time, g);
  write_index();
}

void RunOutput::add_volume(int stage, double time, const meshes::VtuGrid& grid) {
  if (!writes_)
    return;
  volume_.add_stage(stage, time, grid);
  write_index();
}

void RunOutput::reload(const std::vector<StageRecord>& stages) {
  if (!writes_)
    return;
  surface_.reload_stage(0);
  for (const auto& s : stages) {
    surface_.reload_stage(s.stage);
    if (s.volume_cells > 0)
      volume_.reload_stage(s.stage);
  }
  write_index();
}

void RunOutput::write_index() const {
  meshes::write_atomically(xdmf_path(), [&](std::ostream& x) {
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n";
    surface_.write_collection(x);
    volume_.write_collection(x);
    x << "</Domain>\n</Xdmf>\n";
  });
}

void RunOutput::write_tables(const std::vector<dem::RevolutionRecord>& revolutions,
                             const std::vector<StageRecord>& stages, int n_columns,
                             const std::vector<int>& element_labels) const {
  if (!writes_)
    return;
  const auto stage_of = [&](int revolution) -> const StageRecord* {
    for (const auto& s : stages)
      if (revolution >= s.first_revolution && revolution <= s.last_revolution)
        return &s;
    return nullptr;
  };
  meshes::write_atomically(summary_path(), [&](std::ostream& c) {
    write_summary_header(c, n_columns, element_labels);
    c << ",stage,scheme,amplification,stage_applied_volume_m3,stage_geometry_volume_change_m3,"
         "total_remeshes,min_scaled_jacobian,max_von_mises_ball_Pa,max_von_mises_qp_Pa,"
         "safety_factor,pushed_particles\n";
    for (const auto& r : revolutions) {
      write_summary_row(c, r, element_labels);
      if (const StageRecord* s = stage_of(r.revolution))
        c << "," << s->stage << "," << scheme_name(s->scheme) << "," << s->amplification << ","
          << s->applied_volume << "," << s->geometry_volume_change << "," << s->total_remeshes
          << "," << s->min_scaled_jacobian << "," << s->max_von_mises_ball << ","
          << s->max_von_mises_qp << "," << s->safety_factor << "," << s->n_pushed << "\n";
      else
        c << ",0,settling,1,0,0,0,0,0,0,0,0\n";
    }
  });
  const auto columns = stage_columns();
  std::vector<std::vector<double>> packed;
  for (const auto& s : stages)
    packed.push_back(pack(s));
  meshes::write_atomically(stages_path(), [&](std::ostream& c) {
    for (const auto& name : columns)
      c << name << ",";
    c << "scheme_name,distortion\n" << std::setprecision(10);
    for (std::size_t k = 0; k < stages.size(); ++k) {
      for (double v : packed[k])
        c << v << ",";
      c << scheme_name(stages[k].scheme) << ",\"" << stages[k].distortion << "\"\n";
    }
  });
  Hdf5File h5(h5_path());
  const std::size_t n = revolutions.size();
  const auto column = [&](const std::string& name, auto get) {
    std::vector<double> v;
    for (const auto& r : revolutions)
      v.push_back(get(r));
    h5.write("/revolutions/" + name, v, {n});
  };
  column("revolution", [](const auto& r) { return double(r.revolution); });
  column("time_s", [](const auto& r) { return r.time; });
  column("wear_volume_m3", [](const auto& r) { return r.wear_volume; });
  column("wear_volume_cumulative_m3", [](const auto& r) { return r.wear_volume_cumulative; });
  column("normal_force_mean_N", [](const auto& r) { return r.normal_force.mean; });
  column("normal_force_std_N", [](const auto& r) { return r.normal_force.std; });
  column("bottom_speed_mean_m_s", [](const auto& r) { return r.bottom_speed.mean; });
  column("bottom_spin_mean_rad_s", [](const auto& r) { return r.bottom_spin.mean; });
  column("cv_speed", [](const auto& r) { return r.speed_over_sample.cv(); });
  column("cv_bed_height", [](const auto& r) { return r.bed_height.cv(); });
  column("cv_wear_rate", [](const auto& r) { return r.wear_rate.cv(); });
  std::vector<double> col, elem;
  for (const auto& r : revolutions) {
    for (int k = 0; k < n_columns; ++k)
      col.push_back(k < int(r.column_wear.size()) ? r.column_wear[k] : 0.0);
    for (int l : element_labels) {
      const auto it = r.element_wear.find(l);
      elem.push_back(it == r.element_wear.end() ? 0.0 : it->second);
    }
  }
  h5.write("/revolutions/column_wear_m3", col, {n, std::size_t(n_columns)});
  if (!element_labels.empty())
    h5.write("/revolutions/element_wear_m3", elem, {n, element_labels.size()});
  h5.write("/revolutions/element_labels", element_labels, {element_labels.size()});
  for (std::size_t k = 0; k < columns.size(); ++k) {
    std::vector<double> v;
    for (const auto& row : packed)
      v.push_back(row[k]);
    h5.write("/stages/" + columns[k], v, {stages.size()});
  }
  h5.commit();
}

} // namespace wear::coupling
