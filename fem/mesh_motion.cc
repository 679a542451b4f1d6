// Surface relaxation before a recession, interior mesh motion and tetrahedron quality.
//
// The recession itself (docs/theory.md section 6.3) is in meshes/recession.cc.
// Relaxation: a vertex moves by a weight times the offset to the mean of its edge neighbours,
// restricted to its tangent plane (worn region), its flat face group or crease (unworn
// surface), or the chord between its crease neighbours (where the wear face meets a side).
// Mesh motion: for each component, -div(gamma grad d) = 0 with gamma = 1 / |K| per cell
// (Jasak & Tukovic: small cells near the worn surface stiffen and move rigidly), P1 on the
// current mesh, d prescribed on every boundary vertex (the recession on the wear face, zero
// elsewhere); CG with SSOR.
// Quality of a tetrahedron with signed volume V, edges l_k, face areas S_k:
//   scaled Jacobian = min over corners of sqrt(2) 6 V / (l_a l_b l_c)   (1 regular, <= 0 inverted)
//   aspect ratio    = l_max / (2 sqrt(6) r_in),  r_in = 3 |V| / sum S_k  (1 regular)
//   dihedral angle at edge (i, j) = pi - angle between the outward normals of its two faces.
#include "fem/mesh_motion.h"

#include "meshes/constants.h"
#include "meshes/sliding_constraint.h"
#include "meshes/stopwatch.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace wear::fem {

using meshes::Vec3;

namespace {

Vec3 point(const dealii::Point<3>& p) {
  return {p[0], p[1], p[2]};
}

double signed_volume(const Vec3 v[4]) {
  return meshes::dot(v[1] - v[0], meshes::cross(v[2] - v[0], v[3] - v[0])) / 6.0;
}
// Per vertex, the mean of its edge neighbours minus its position; each interior edge is seen
// from both of its faces, so every neighbour counts twice.
std::vector<Vec3> neighbour_offsets(const meshes::SurfaceMesh& surface) {
  const std::size_t nv = surface.n_vertices();
  std::vector<Vec3> sum(nv);
  std::vector<int> count(nv, 0);
  for (const auto& t : surface.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto a = t[k], b = t[(k + 1) % 3];
      sum[a] += surface.vertices[b];
      sum[b] += surface.vertices[a];
      ++count[a];
      ++count[b];
    }
  for (std::size_t v = 0; v < nv; ++v)
    sum[v] = count[v] > 0 ? sum[v] * (1.0 / count[v]) - surface.vertices[v] : Vec3{};
  return sum;
}

// Adds factor * d[v] to every vertex v of the triangulation (each once, though cells share it).
void displace_vertices(dealii::Triangulation<3>& tria, const std::vector<Vec3>& d, double factor) {
  std::vector<char> done(tria.n_vertices(), 0);
  for (const auto& cell : tria.active_cell_iterators())
    for (unsigned int k = 0; k < 4; ++k) {
      const auto v = cell->vertex_index(k);
      if (done[v])
        continue;
      done[v] = 1;
      for (unsigned int c = 0; c < 3; ++c)
        cell->vertex(k)[c] += factor * d[v][c];
    }
}

// The first cell with a non-positive signed volume, or -1.
long first_invalid_cell(const dealii::Triangulation<3>& tria) {
  for (const auto& cell : tria.active_cell_iterators()) {
    Vec3 v[4];
    for (unsigned int k = 0; k < 4; ++k)
      v[k] = point(cell->vertex(k));
    if (!(signed_volume(v) > 0))
      return long(cell->active_cell_index());
  }
  return -1;
}

// One sub-step of the interior motion: the boundary moves by `fraction` of its displacement.
// The mesh must be valid (the stiffness 1 / |K| of a flat cell is infinite).
unsigned int laplace_step(dealii::Triangulation<3>& tria, const std::vector<Vec3>& boundary,
                          const std::vector<char>& on_boundary, double fraction) {
  using namespace dealii;
  unsigned int iterations = 0;
  const FE_SimplexP<3> fe(1);
  const MappingFE<3> mapping(FE_SimplexP<3>(1));
  DoFHandler<3> dof(tria);
  dof.distribute_dofs(fe);
  std::vector<unsigned int> vertex_of_dof(dof.n_dofs());
  for (const auto& cell : dof.active_cell_iterators())
    for (unsigned int k = 0; k < 4; ++k)
      vertex_of_dof[cell->vertex_dof_index(k, 0)] = cell->vertex_index(k);
  DynamicSparsityPattern dsp(dof.n_dofs());
  DoFTools::make_sparsity_pattern(dof, dsp);
  SparsityPattern sp;
  sp.copy_from(dsp);
  const QGaussSimplex<3> quadrature(1);
  FEValues<3> fv(mapping, fe, quadrature, update_gradients | update_JxW_values);
  FullMatrix<double> cell_matrix(4, 4);
  Vector<double> cell_rhs(4);
  std::vector<types::global_dof_index> dofs(4);
  std::vector<Vec3> moved(tria.n_vertices());
  for (unsigned int c = 0; c < 3; ++c) {
    AffineConstraints<double> constraints;
    for (types::global_dof_index i = 0; i < dof.n_dofs(); ++i)
      if (on_boundary[vertex_of_dof[i]]) {
        constraints.add_line(i);
        constraints.set_inhomogeneity(i, fraction * boundary[vertex_of_dof[i]][c]);
      }
    constraints.close();
    SparseMatrix<double> matrix(sp);
    Vector<double> rhs(dof.n_dofs()), d(dof.n_dofs());
    for (const auto& cell : dof.active_cell_iterators()) {
      fv.reinit(cell);
      double volume = 0;
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        volume += fv.JxW(q);
      cell_matrix = 0;
      cell_rhs = 0;
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = 0; j < 4; ++j)
            cell_matrix(i, j) += fv.shape_grad(i, q) * fv.shape_grad(j, q) * fv.JxW(q) / volume;
      cell->get_dof_indices(dofs);
      constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, matrix, rhs);
    }
    SolverControl control(5000, 1e-12 * std::max(1e-300, rhs.l2_norm()));
    SolverCG<Vector<double>> cg(control);
    PreconditionSSOR<SparseMatrix<double>> ssor;
    ssor.initialize(matrix, 1.2);
    if (rhs.l2_norm() > 0)
      cg.solve(matrix, d, rhs, ssor);
    constraints.distribute(d);
    iterations += control.last_step();
    for (types::global_dof_index i = 0; i < dof.n_dofs(); ++i)
      moved[vertex_of_dof[i]][c] = d(i);
  }
  displace_vertices(tria, moved, 1.0);
  return iterations;
}

} // namespace

std::vector<Vec3> tangential_relaxation(const meshes::SurfaceMesh& surface,
                                        const std::vector<char>& moving, double weight,
                                        double spike_cos) {
  const std::size_t nv = surface.n_vertices();
  if (moving.size() != nv)
    throw std::invalid_argument("tangential relaxation: mask of the wrong size");
  // A vertex qualifies when every face around it has the same wearing label.
  std::vector<int> label(nv, -1);
  std::vector<char> free(nv, 1);
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    for (const auto v : surface.triangles[f]) {
      const int l = surface.face_labels[f];
      if (!surface.roles.wears(l) || (label[v] >= 0 && label[v] != l))
        free[v] = 0;
      label[v] = l;
    }
  // A crease nearly folded flat inside one label is a spike that wear sharpened, not the
  // element's shape (the tip of a coarse element turns its normals by less: cos -0.66 at
  // 3 mm): its vertices take the full offset (normal part too), which cuts the spike; the
  // caller gives the volume back in the recession.
  std::vector<char> sharp(nv, 0);
  const auto face_normal = meshes::face_normals(surface);
  for (const auto& [edge, faces] : meshes::edge_faces(surface))
    if (faces.size() == 2 && surface.face_labels[faces[0]] == surface.face_labels[faces[1]] &&
        meshes::dot(face_normal[faces[0]], face_normal[faces[1]]) < spike_cos)
      for (const auto f : faces)
        for (const auto v : surface.triangles[f])
          sharp[v] = 1;
  const auto offset = neighbour_offsets(surface);
  const auto normal = meshes::vertex_normals(surface);
  std::vector<Vec3> out(nv);
  for (std::size_t v = 0; v < nv; ++v)
    if (moving[v] && free[v]) {
      const Vec3& d = offset[v];
      out[v] = (sharp[v] ? d : d - normal[v] * meshes::dot(d, normal[v])) * weight;
    }
  return out;
}

std::vector<Vec3> crease_relaxation(const meshes::SurfaceMesh& surface, double weight,
                                    const std::vector<meshes::SlidingConstraint>* constraint) {
  const std::size_t nv = surface.n_vertices();
  // The crease neighbours of each vertex: across edges between a wearing and an unworn face.
  std::vector<std::array<std::int64_t, 2>> along(nv, {-1, -1});
  std::vector<int> n_along(nv, 0);
  for (const auto& [edge, faces] : meshes::edge_faces(surface)) {
    if (faces.size() != 2 || surface.face_wears(faces[0]) == surface.face_wears(faces[1]))
      continue;
    for (const auto& [v, w] : {std::pair{edge.first, edge.second}, {edge.second, edge.first}}) {
      if (n_along[v] < 2)
        along[v][std::size_t(n_along[v])] = w;
      ++n_along[v];
    }
  }
  std::vector<meshes::SlidingConstraint> own;
  if (!constraint)
    constraint = &(own = meshes::sliding_constraints(surface));
  std::vector<Vec3> out(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    if (n_along[v] != 2 || (*constraint)[v].n_free != 2)
      continue; // a corner of the crease, or a vertex not on one flat side
    const Vec3& a = surface.vertices[std::size_t(along[v][0])];
    const Vec3& b = surface.vertices[std::size_t(along[v][1])];
    const Vec3 chord = b - a;
    const double length = meshes::norm(chord);
    if (!(length > 0))
      continue;
    const Vec3 t = chord * (1 / length);
    const Vec3 to_mean = (a + b) * 0.5 - surface.vertices[v];
    out[v] = (*constraint)[v].apply(t * (meshes::dot(to_mean, t) * weight));
  }
  return out;
}

std::vector<Vec3> unworn_relaxation(const meshes::SurfaceMesh& surface, double weight,
                                    const std::vector<meshes::SlidingConstraint>* constraint) {
  const std::size_t nv = surface.n_vertices();
  std::vector<char> unworn(nv, 1);
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    if (surface.face_wears(f))
      for (const auto v : surface.triangles[f])
        unworn[v] = 0;
  const auto offset = neighbour_offsets(surface);
  std::vector<meshes::SlidingConstraint> own;
  if (!constraint)
    constraint = &(own = meshes::sliding_constraints(surface));
  std::vector<Vec3> out(nv);
  for (std::size_t v = 0; v < nv; ++v)
    if (unworn[v])
      out[v] = (*constraint)[v].apply(offset[v]) * weight;
  return out;
}

VolumeQuality volume_quality(const dealii::Triangulation<3>& tria, std::vector<double>* per_cell) {
  VolumeQuality q;
  if (per_cell)
    per_cell->assign(tria.n_active_cells(), 0);
  // Edges and faces of a tetrahedron by local vertex index.
  static constexpr int edge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  static constexpr int face[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (const auto& cell : tria.active_cell_iterators()) {
    Vec3 v[4];
    for (unsigned int k = 0; k < 4; ++k)
      v[k] = point(cell->vertex(k));
    // deal.II numbers a tetrahedron with vertex 3 on the positive side of face 0-1-2, so a
    // valid cell has a positive signed volume.
    const double vol = signed_volume(v);
    double l[6], l_max = 0;
    for (int e = 0; e < 6; ++e) {
      l[e] = meshes::norm(v[edge[e][1]] - v[edge[e][0]]);
      l_max = std::max(l_max, l[e]);
    }
    const double corner[4] = {l[0] * l[1] * l[2], l[0] * l[3] * l[4], l[1] * l[3] * l[5],
                              l[2] * l[4] * l[5]};
    double sj = 1e300;
    for (double c : corner)
      sj = std::min(sj, std::sqrt(2.0) * 6 * vol / c);
    if (per_cell)
      (*per_cell)[cell->active_cell_index()] = sj;
    if (sj < q.min_scaled_jacobian || q.worst_cell < 0) {
      q.min_scaled_jacobian = std::min(q.min_scaled_jacobian, sj);
      q.worst_cell = long(cell->active_cell_index());
    }
    if (vol <= 0)
      ++q.n_inverted;
    Vec3 n[4];
    double s_sum = 0;
    for (int f = 0; f < 4; ++f) {
      n[f] = meshes::cross(v[face[f][1]] - v[face[f][0]], v[face[f][2]] - v[face[f][0]]);
      s_sum += 0.5 * meshes::norm(n[f]);
    }
    const double r_in = 3 * std::abs(vol) / s_sum;
    q.max_aspect_ratio = std::max(q.max_aspect_ratio, l_max / (2 * std::sqrt(6.0) * r_in));
    // Face f omits vertex f, normals outward; edge (a, b) joins the faces omitting the
    // other two vertices.
    for (int e = 0; e < 6; ++e) {
      int others[2], k = 0;
      for (int c = 0; c < 4; ++c)
        if (c != edge[e][0] && c != edge[e][1])
          others[k++] = c;
      const Vec3 &na = n[others[0]], &nb = n[others[1]];
      const double c = meshes::dot(na, nb) / (meshes::norm(na) * meshes::norm(nb));
      const double angle = 180 - std::acos(std::clamp(c, -1.0, 1.0)) * 180 / pi;
      q.min_dihedral_deg = std::min(q.min_dihedral_deg, angle);
      q.max_dihedral_deg = std::max(q.max_dihedral_deg, angle);
    }
  }
  return q;
}

meshes::SurfaceMesh move_mesh(dealii::Triangulation<3>& tria, const BoundaryFaceMap& map,
                              const std::vector<Vec3>& surface_displacement, MotionReport* report) {
  using namespace dealii;
  const meshes::Stopwatch start;
  const auto& surface = map.surface();
  if (surface_displacement.size() != surface.n_vertices())
    throw std::invalid_argument(
        "mesh motion: displacement of " + std::to_string(surface_displacement.size()) +
        " vertices for a surface of " + std::to_string(surface.n_vertices()));
  // Boundary vertex displacements by triangulation vertex index.
  std::vector<Vec3> boundary(tria.n_vertices());
  std::vector<char> on_boundary(tria.n_vertices(), 0);
  for (std::size_t v = 0; v < surface.n_vertices(); ++v) {
    boundary[map.vertex_map()[v]] = surface_displacement[v];
    on_boundary[map.vertex_map()[v]] = 1;
  }
  // Sub-steps: each moves the boundary by a fraction small against the boundary cells, and
  // the interior follows on the current (already moved) mesh with its current volumes.
  // The number of increments follows the largest displacement relative to the surface
  // edges at the moving vertices (a sliver far from the worn region does not count).
  double ratio = 0;
  for (const auto& t : surface.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto a = t[k], b = t[(k + 1) % 3];
      const double move =
          std::max(meshes::norm(surface_displacement[a]), meshes::norm(surface_displacement[b]));
      if (move > 0)
        ratio = std::max(ratio, move / meshes::norm(surface.vertices[b] - surface.vertices[a]));
    }
  const int n_sub = std::clamp(int(std::ceil(ratio / 0.25)), 1, 50);
  if (const long bad = first_invalid_cell(tria); bad >= 0)
    throw std::runtime_error("mesh motion: cell " + std::to_string(bad) +
                             " is flat or inverted before the motion; the mesh must be valid");
  unsigned int iterations = 0;
  for (int sub = 0; sub < n_sub; ++sub) {
    if (sub > 0 && first_invalid_cell(tria) >= 0) {
      // A sub-step inverted or flattened a cell: the interior cannot follow further, so the
      // boundary takes its remaining way directly and the caller sees the invalid cells
      // (and remeshes from the moved surface).
      // (boundary is zero at interior vertices, so only the boundary moves)
      displace_vertices(tria, boundary, double(n_sub - sub) / n_sub);
      break;
    }
    iterations += laplace_step(tria, boundary, on_boundary, 1.0 / n_sub);
  }
  meshes::SurfaceMesh out = surface;
  for (std::size_t v = 0; v < out.n_vertices(); ++v)
    out.vertices[v] += surface_displacement[v];
  out.bump_revision();
  if (report) {
    report->iterations = iterations;
    report->substeps = n_sub;
    report->quality = volume_quality(tria);
    report->seconds = start.seconds();
  }
  return out;
}

} // namespace wear::fem
