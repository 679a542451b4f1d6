// Isotropic remeshing of a labelled, closed surface with CGAL's Polygon Mesh Processing
// (Botsch and Kobbelt, "A remeshing approach to multiresolution modeling", 2004).
//
// Each round: edges longer than 4/3 L are split at their midpoint, edges shorter than 4/5 L
// collapsed (unless that makes an edge longer than 4/3 L or folds a face), edges flipped where
// that brings the valences of their four vertices closer to 6, and every free vertex moved
// to the area-weighted centroid of its neighbours in its tangent plane, then projected back
// onto the input surface (an AABB tree of the input's triangles). The result's triangles are
// close to equilateral with edges near L, and every vertex lies on the input.
//
// Labels: each label is a patch; the edges between patches are constraints, split and
// collapsed only along the polyline they form, their vertices relaxed only along it; a
// vertex where three or more patches meet is a corner and never moves. A new face keeps its
// patch, so the label boundaries, and the volume to the order of the chords the input
// already has, are what they were. The input must be a closed 2-manifold.
#include "meshes/isotropic_remeshing.h"

#include "meshes/mesh_quality.h"
#include "meshes/stopwatch.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace wear::meshes {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

} // namespace

IsotropicRemeshReport isotropic_remesh(SurfaceMesh& m,
                                       std::vector<std::pair<std::uint32_t, std::uint32_t>>& curves,
                                       const IsotropicRemeshParameters& p) {
  const Stopwatch clock;
  if (!(p.target_edge > 0) || p.n_iterations < 1)
    throw std::invalid_argument("isotropic remeshing: the target edge must be positive and the "
                                "rounds at least one");
  m.validate("surface to remesh isotropically");
  IsotropicRemeshReport r;
  r.n_faces_before = m.n_faces();
  r.min_quality_before = min_triangle_quality(m);

  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertex(m.n_vertices());
  for (std::size_t v = 0; v < m.n_vertices(); ++v)
    vertex[v] = mesh.add_vertex({m.vertices[v].x, m.vertices[v].y, m.vertices[v].z});
  auto patch = mesh.add_property_map<Mesh::Face_index, int>("f:label", 0).first;
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    const auto& t = m.triangles[f];
    const auto face = mesh.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]);
    if (face == Mesh::null_face())
      throw std::runtime_error("isotropic remeshing: face " + std::to_string(f) +
                               " breaks the surface's manifold structure");
    patch[face] = m.face_labels[f];
  }
  if (!CGAL::is_closed(mesh))
    throw std::runtime_error("isotropic remeshing: the surface is not closed");

  auto on_curve = mesh.add_property_map<Mesh::Edge_index, bool>("e:curve", false).first;
  for (const auto& [a, b] : curves) {
    const auto h = mesh.halfedge(vertex[a], vertex[b]);
    if (h == Mesh::null_halfedge())
      throw std::invalid_argument("isotropic remeshing: curve edge (" + std::to_string(a) + ", " +
                                  std::to_string(b) + ") is no edge of the surface");
    on_curve[mesh.edge(h)] = true;
  }
  // Corners: vertices whose faces carry three or more labels, and vertices on a number of
  // curve or label-boundary edges other than 0 or 2 (a curve's end or branch).
  auto corner = mesh.add_property_map<Mesh::Vertex_index, bool>("v:corner", false).first;
  for (const auto v : mesh.vertices()) {
    int labels[3];
    int n = 0, n_curve_edges = 0;
    for (const auto h : CGAL::halfedges_around_target(v, mesh)) {
      const int l = patch[mesh.face(h)];
      if (on_curve[mesh.edge(h)] || l != patch[mesh.face(mesh.opposite(h))])
        ++n_curve_edges;
      if (std::find(labels, labels + n, l) == labels + n) {
        if (n == 2)
          corner[v] = true;
        else
          labels[n++] = l;
      }
    }
    if (n_curve_edges != 0 && n_curve_edges != 2)
      corner[v] = true;
  }
  namespace PMP = CGAL::Polygon_mesh_processing;
  PMP::isotropic_remeshing(faces(mesh), p.target_edge, mesh,
                           CGAL::parameters::number_of_iterations(unsigned(p.n_iterations))
                               .face_patch_map(patch)
                               .edge_is_constrained_map(on_curve)
                               .vertex_is_constrained_map(corner)
                               .protect_constraints(false)
                               .relax_constraints(true));
  mesh.collect_garbage();

  SurfaceMesh out;
  out.roles = m.roles;
  out.vertices.reserve(mesh.number_of_vertices());
  for (const auto v : mesh.vertices()) {
    const auto& x = mesh.point(v);
    out.vertices.push_back({x.x(), x.y(), x.z()});
  }
  for (const auto f : mesh.faces()) {
    Triangle t;
    int k = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      t[k++] = std::uint32_t(v.idx());
    out.triangles.push_back(t);
    out.face_labels.push_back(patch[f]);
  }
  curves.clear();
  for (const auto e : mesh.edges())
    if (on_curve[e]) {
      const auto a = std::uint32_t(mesh.vertex(e, 0).idx()),
                 b = std::uint32_t(mesh.vertex(e, 1).idx());
      curves.emplace_back(std::min(a, b), std::max(a, b));
    }
  out.set_revision(m.revision());
  m = std::move(out);
  r.n_faces_after = m.n_faces();
  r.min_quality_after = min_triangle_quality(m);
  r.seconds = clock.seconds();
  return r;
}

} // namespace wear::meshes
