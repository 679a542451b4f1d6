// Isotropic remeshing of a labelled, closed surface with CGAL's Polygon Mesh Processing
// (Botsch and Kobbelt, "A remeshing approach to multiresolution modeling", 2004).
//
// Each round: edges longer than 4/3 L are split at their midpoint, edges shorter than 4/5 L
// collapsed (unless that makes an edge longer than 4/3 L or folds a face), edges flipped where
// that brings the valences of their four vertices closer to 6, and every free vertex moved
// to the centroid of its neighbours in its tangent plane, then projected back onto the input
// surface (an AABB tree of the input's triangles of its patch). The result's triangles are
// close to equilateral with edges near L, and every vertex lies on the input.
//
// The rounds are CGAL's remesher's steps, driven here; the relaxation is ours, the same as
// CGAL's (uniform weights, the vertex normal's tangent plane, all moves computed and then
// made, a move halved up to five times while it turns a face against its neighbour across a
// free edge, else not made), except that a vertex none of whose faces has a normal left (all
// degenerate) does not move. CGAL 5.5's own relaxation dereferences a null half-edge there
// (CGAL issue 7345), a segmentation fault the wear-out's zero sets reach.
//
// Labels: each label is a patch; the edges between patches are constraints, split and
// collapsed only along the polyline they form, their vertices relaxed only along it (halfway
// to the middle of their two neighbours on it, where it turns by less than 60 degrees); a
// vertex where three or more patches meet is a corner and never moves. Unlike CGAL, a vertex
// on the boundary between two patches is put back onto the input's boundary between them after
// that move (CGAL projects it onto the surface of one patch only, which leaves it inside the
// chord of a curved boundary, such as a worn element's foot, where the faces beside it turn
// over: the wear-out's stage 6). A new face keeps its
// patch, so the label boundaries, and the volume to the order of the chords the input
// already has, are what they were. The input must be a closed 2-manifold.
#include "meshes/isotropic_remeshing.h"

#include "meshes/mesh_quality.h"
#include "meshes/stopwatch.h"
#include "meshes/surface_restoration.h"

#include <CGAL/version.h>
// The remesher's rounds are driven through CGAL's internal Incremental_remesher, whose
// interface is CGAL 5.5's (Debian 12); another release must be checked before it is used.
#if CGAL_VERSION_NR < 1050500000 || CGAL_VERSION_NR >= 1050600000
#error "meshes/isotropic_remeshing.cc drives CGAL 5.5's internal remesher: check its interface"
#endif

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/internal/Isotropic_remeshing/remesh_impl.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace wear::meshes {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vector = Kernel::Vector_3;
using EdgeFlags = Mesh::Property_map<Mesh::Edge_index, bool>;
using FacePatches = Mesh::Property_map<Mesh::Face_index, int>;
namespace PMP = CGAL::Polygon_mesh_processing;

// One round of tangential relaxation of `mesh` (see the top of this file). An edge on a curve
// (`on_curve`) or between two patches is constrained.
void relax_tangentially(Mesh& mesh, const EdgeFlags& on_curve, const FacePatches& patch,
                        const PatchSeams& seams) {
  const auto constrained = [&](Mesh::Halfedge_index h) {
    return on_curve[mesh.edge(h)] || patch[mesh.face(h)] != patch[mesh.face(mesh.opposite(h))];
  };
  auto normal = mesh.add_property_map<Mesh::Vertex_index, Vector>("v:relax-normal").first;
  PMP::compute_vertex_normals(mesh, normal);
  std::vector<std::pair<Mesh::Vertex_index, Kernel::Point_3>> moves;
  std::vector<Mesh::Halfedge_index> along;
  for (const auto v : mesh.vertices()) {
    if (mesh.is_isolated(v))
      continue;
    const auto& x = mesh.point(v);
    along.clear();
    Vector sum = CGAL::NULL_VECTOR;
    unsigned n = 0;
    for (const auto h : CGAL::halfedges_around_target(v, mesh))
      if (constrained(h))
        along.push_back(h);
      else {
        sum = sum + (mesh.point(mesh.source(h)) - x);
        ++n;
      }
    if (along.empty()) {
      const Kernel::Point_3 centroid = x + sum / double(n);
      const Vector& u = normal[v];
      moves.emplace_back(v, centroid + (u * (x - centroid)) * u);
    } else if (along.size() == 2) {
      const auto& a = mesh.point(mesh.source(along[0]));
      const auto& b = mesh.point(mesh.source(along[1]));
      const double c = (a - x) * (b - x);
      if (c * c > 0.25 * CGAL::squared_distance(a, x) * CGAL::squared_distance(b, x)) {
        auto y = CGAL::barycenter(a, 0.25, b, 0.25, x, 0.5);
        // On a boundary between two patches (not a curve) y goes back onto the input's
        // boundary between them: across a curved one (an element's foot) the halfway move
        // cuts the chord, and the faces beside it turn over.
        const auto pair = [&](Mesh::Halfedge_index h) {
          const int p = patch[mesh.face(h)], q = patch[mesh.face(mesh.opposite(h))];
          return std::make_pair(std::min(p, q), std::max(p, q));
        };
        const auto [p, q] = pair(along[0]);
        if (p != q && pair(along[1]) == std::make_pair(p, q) && !on_curve[mesh.edge(along[0])] &&
            !on_curve[mesh.edge(along[1])]) {
          const auto [z, d] = seams.nearest(p, q, {y.x(), y.y(), y.z()});
          if (std::isfinite(d))
            y = {z.x, z.y, z.z};
        }
        moves.emplace_back(v, y);
      }
    }
  }
  mesh.remove_property_map(normal);
  // Whether no face of v turns against the one before it across a free edge; false where
  // every face of v is degenerate (no normal to compare).
  const auto faces_agree = [&](Mesh::Vertex_index v) {
    Vector first = CGAL::NULL_VECTOR, previous = CGAL::NULL_VECTOR;
    Mesh::Halfedge_index first_h;
    bool any = false;
    for (const auto h : CGAL::halfedges_around_target(v, mesh)) {
      const Vector u = PMP::compute_face_normal(mesh.face(h), mesh);
      if (u == CGAL::NULL_VECTOR)
        continue;
      if (!any) {
        any = true;
        first = u;
        first_h = h;
      } else if (!constrained(h) && u * previous <= 0)
        return false;
      previous = u;
    }
    return any && (constrained(first_h) || first * previous > 0);
  };
  for (const auto& [v, target] : moves) {
    const Kernel::Point_3 start = mesh.point(v);
    const Vector step = target - start;
    mesh.point(v) = target;
    double fraction = 1;
    while (fraction > 0.03 && !faces_agree(v)) {
      fraction *= 0.5;
      mesh.point(v) = start + fraction * step;
    }
    if (fraction <= 0.02)
      mesh.point(v) = start;
  }
}

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
  {
    auto points = mesh.points();
    const auto face_index = CGAL::get_initialized_face_index_map(mesh);
    PMP::internal::Incremental_remesher<Mesh, decltype(points), Kernel, EdgeFlags, decltype(corner),
                                        FacePatches, decltype(face_index)>
        remesher(mesh, points, Kernel(), false, on_curve, corner, patch, face_index, true);
    remesher.init_remeshing(faces(mesh));
    const PatchSeams seams(m, m.face_labels);
    const double low = 4. / 5. * p.target_edge, high = 4. / 3. * p.target_edge;
    for (int round = 0; round < p.n_iterations; ++round) {
      remesher.split_long_edges(high);
      remesher.collapse_short_edges(low, high, true);
      remesher.flip_edges_for_valence_and_shape();
      relax_tangentially(mesh, on_curve, patch, seams);
      remesher.project_to_surface(CGAL::internal_np::Param_not_found());
    }
  }
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
