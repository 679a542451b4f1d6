// `wearsim mesh <case.prm>`: generates the sample and the tester walls.
//
// Per label it reports the face count, the surface area and, for convex elements, the
// element volume from the surface (divergence theorem over the element's faces relative to
// the base top plane). The whole-sample volume is reported from the surface and, when a
// volume mesh exists, from the tetrahedra; the elements' together against the CAD's, with a
// warning when the mesh cuts more than 5 % of them away (meshes::element_volume_warning).
#include "coupling/app/mesh_command.h"

#include "meshes/atomic_file.h"
#include "meshes/sample_frame.h"
#include "meshes/sample_generator.h"
#include "meshes/stl_io.h"
#include "meshes/tester_walls.h"
#include "meshes/vtu_writer.h"

#include <cstdio>
#include <ostream>

namespace wear::coupling {

void run_mesh_command(const CaseParameters& p, std::ostream& log) {
  const std::string dir = p.output.directory;
  meshes::ensure_directory(dir);
  write_resolved_parameters(p, dir + "/parameters.prm");
  const auto& s = p.geometry.sample;
  const auto g = meshes::generate_sample(s, dir + "/sample.msh");
  meshes::write_stl(g.surface, dir + "/sample.stl", meshes::StlFormat::binary);
  meshes::write_vtu(g.surface, dir + "/sample.vtu");
  const auto placed = meshes::SampleFrame(s, p.geometry.placement).place_in_tester(g.surface);
  meshes::write_stl(placed, dir + "/sample_in_tester.stl", meshes::StlFormat::binary);
  const auto walls = meshes::generate_tester_walls(p.geometry.tester);
  meshes::write_stl(walls.floor, dir + "/floor.stl", meshes::StlFormat::binary);
  meshes::write_stl(walls.inner, dir + "/inner_wall.stl", meshes::StlFormat::binary);
  meshes::write_stl(walls.outer, dir + "/outer_wall.stl", meshes::StlFormat::binary);
  if (walls.consolidator)
    meshes::write_stl(*walls.consolidator, dir + "/consolidator.stl", meshes::StlFormat::binary);
  const auto& t = p.geometry.tester;
  const auto holder = t.holder ? meshes::SampleFrame(s, p.geometry.placement)
                                     .place_in_tester(meshes::generate_holder(s, t))
                               : meshes::SurfaceMesh{};
  if (t.holder)
    meshes::write_stl(holder, dir + "/holder.stl", meshes::StlFormat::binary);

  char line[256];
  std::snprintf(line, sizeof line, "sample: %s, %zu tetrahedra, %zu surface triangles, %.2f s\n",
                s.convex ? "convex" : "plain", g.n_tetrahedra, g.surface.n_faces(), g.seconds);
  log << line;
  std::map<int, std::size_t> n_faces;
  for (int l : g.surface.face_labels)
    ++n_faces[l];
  const auto area = meshes::area_per_label(g.surface);
  for (const auto& [id, a] : area) {
    if (meshes::label::is_convex_element(id))
      std::snprintf(line, sizeof line, "%-7s faces %7zu  area %.6e m^2  volume %.6e m^3\n",
                    meshes::label::name(id).c_str(), n_faces[id], a,
                    meshes::volume_above_plane(g.surface, id, s.thickness));
    else
      std::snprintf(line, sizeof line, "%-7s faces %7zu  area %.6e m^2  volume -\n",
                    meshes::label::name(id).c_str(), n_faces[id], a);
    log << line;
  }
  std::snprintf(line, sizeof line,
                "total   faces %7zu  area %.6e m^2  volume %.6e m^3 (surface), %.6e m^3 "
                "(tetrahedra), %.6e m^3 (CAD)\n",
                g.surface.n_faces(), meshes::total_area(g.surface),
                meshes::enclosed_volume(g.surface), g.tetrahedral_volume, g.exact_volume);
  log << line;
  if (s.convex) {
    const auto v = meshes::element_volume(g, s);
    std::snprintf(line, sizeof line,
                  "elements: %.6e m^3 above the base top (surface), %.6e m^3 (CAD), %.1f %% "
                  "less\n",
                  v.meshed, v.exact, 100 * v.deficit());
    log << line;
    if (const auto warning = meshes::element_volume_warning(v, s); !warning.empty())
      log << "warning: " << warning << "\n";
  }
  std::snprintf(line, sizeof line,
                "walls: floor %zu, inner %zu, outer %zu, consolidator %zu, holder %zu triangles\n",
                walls.floor.n_faces(), walls.inner.n_faces(), walls.outer.n_faces(),
                walls.consolidator ? walls.consolidator->n_faces() : std::size_t(0),
                holder.n_faces());
  log << line << "written to " << dir << "/\n";
}

} // namespace wear::coupling
