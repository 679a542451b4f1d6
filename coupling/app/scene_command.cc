// `wearsim scene <case.prm>`: the user's walls as the DEM will see them, built and checked
// before any particle exists.
//
// Per wall it prints the source, triangle count, area, extent and, per label (each CAD
// surface), the triangles' area against the CAD kernel's exact one (their ratio shows the
// meshing error, and the labels' areas and centroids tell which surface is which, since
// gmsh reads no face names from STEP). A wearing part's surfaces show the label their role
// gives them (S<n> wearing, S<n>-free, S<n>-clamped). Every wall goes to scene/<name>.stl (ASCII,
// one solid per label) and scene/<name>.vtu for ParaView.
#include "coupling/app/scene_command.h"

#include "dem/scene/scene_walls.h"
#include "dem/scene/wall_catalogue.h"
#include "meshes/atomic_file.h"
#include "meshes/stl_io.h"
#include "meshes/vtu_writer.h"

#include <cstdio>
#include <ostream>
#include <stdexcept>

namespace wear::coupling {

void run_scene_command(const CaseParameters& p, std::ostream& log) {
  if (p.scene.walls.empty())
    throw std::invalid_argument("case file '" + p.case_file +
                                "': Scene/Walls is empty: there is no scene to build");
  const auto walls = dem::build_scene_walls(p.scene, p.geometry);
  const std::string dir = p.output.directory + "/scene";
  meshes::ensure_directory(p.output.directory);
  meshes::ensure_directory(dir);
  write_resolved_parameters(p, p.output.directory + "/parameters.prm");
  char line[512];
  for (const auto& w : walls) {
    const auto& m = w.surface.mesh;
    const auto box = meshes::bounding_box(m);
    const auto& q = w.parameters;
    const bool from_file = dem::wall_source_of(q).source == dem::WallSource::file;
    std::snprintf(line, sizeof line,
                  "wall %s: %s%s%s, %zu triangles, area %.6g m^2, x %.4g..%.4g y %.4g..%.4g "
                  "z %.4g..%.4g m, material %s, %s, motion %s\n",
                  q.name.c_str(), q.source.c_str(), from_file ? " " : "",
                  from_file ? q.file.c_str() : "", m.n_faces(), meshes::total_area(m), box.min.x,
                  box.max.x, box.min.y, box.max.y, box.min.z, box.max.z, q.material.c_str(),
                  q.wears ? "wears" : "does not wear", q.motion.c_str());
    log << line;
    if (w.surface.n_solids > 0) {
      std::snprintf(line, sizeof line,
                    "  %zu solid(s), volume %.6g m^3 (CAD), %.6g m^3 (triangles)\n",
                    w.surface.n_solids, w.surface.solid_volume, meshes::enclosed_volume(m));
      log << line;
    }
    const auto area = meshes::area_per_label(m);
    const auto centroid = meshes::face_centroids(m);
    const auto areas = meshes::face_areas(m);
    for (std::size_t k = 0; k < w.surface.surface_labels.size(); ++k) {
      const int label = w.surface.surface_labels[k];
      meshes::Vec3 c;
      double a = 0;
      for (std::size_t f = 0; f < m.n_faces(); ++f)
        if (m.face_labels[f] == label) {
          c += areas[f] * centroid[f];
          a += areas[f];
        }
      if (a > 0)
        c = c * (1 / a);
      // A wearing part's surfaces by their CAD number, with the label their role gives; the
      // tester's sample and holder by their labels' names.
      const bool tester = dem::wall_source_of(q).tester_part;
      const bool part = meshes::label::is_part_surface(label) || tester;
      std::snprintf(line, sizeof line,
                    "  surface %3d%s%s: area %.6g m^2 (CAD %.6g), centroid (%.4g, %.4g, %.4g) m\n",
                    part && !tester ? meshes::label::part_surface_number(label) : label,
                    part ? " " : "", part ? meshes::label::name(label).c_str() : "",
                    area.count(label) ? area.at(label) : 0.0, w.surface.surface_areas[k], c.x, c.y,
                    c.z);
      log << line;
    }
    meshes::write_stl(m, dir + "/" + q.name + ".stl", meshes::StlFormat::ascii);
    meshes::write_vtu(m, dir + "/" + q.name + ".vtu");
  }
  log << "written to " << dir << "/\n";
}

} // namespace wear::coupling
