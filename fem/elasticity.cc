// Linear elasticity on the sample (docs/theory.md section 6.2).
//
//   -div sigma(u) = 0,  sigma = lambda tr(eps) I + 2 mu eps,  eps = sym grad u
//   u = 0 on the faces whose role is clamped (the sample's bottom, a part's clamped surfaces);
//   sigma n = t_f = F_f / A_f on surface face f; on the held faces (the sample's sides in its
//   holder) u . n = 0 and zero tangential traction
// with F_f the extensive force field (window-averaged face loads), so the applied total
// force equals sum_f F_f exactly (the traction is constant on each face and integrated
// exactly). FE_SimplexP of degree 1 or 2 per component, Gauss simplex quadrature of
// degree + 1, affine mapping. Solver: CG with Trilinos ML AMG, the six rigid-body
// modes as near null space. Reaction: the nodal residual K u - f of the unconstrained
// system summed over the constrained DoFs per component (bottom and, held, sides).
// Held faces: their support (the holder's walls, normal to x or y in the sample frame; a
// part's frame) is normal to an axis, so u . n = 0 constrains one displacement component of
// each DoF of the face to zero (both at an edge between two held faces, all three where a
// held face meets a clamped one), the axis nearest the face's normal; a held face more than
// 30 degrees off every axis stops the solve.
// Stresses: von Mises sqrt(3/2 s:s) (s deviatoric) and principal stresses (eigenvalues of
// the symmetric tensor), averaged over each cell's quadrature points for output; the
// maxima use every quadrature point. The measures that converge under refinement
// (stress_measures.h) are taken over the same quadrature points: volume-weighted
// percentiles 99 and 99.9 of von Mises; the ball average over the cells' means, at every
// mesh vertex and every surface face's centroid (vertices: spaced by the cell size, below
// the radius in use, and on the surface, where contact loads put the largest averages;
// about a fifth of the cells' count, so the cost stays a small part of the solve).
#include "fem/elasticity.h"

#include "meshes/stopwatch.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/numerics/vector_tools.h>

#include <Epetra_Map.h>
#include <Teuchos_ParameterList.hpp>

#include <cmath>
#include <stdexcept>

namespace wear::fem {

using namespace dealii;

namespace {

SymmetricTensor<4, 3> stiffness(double E, double nu) {
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  SymmetricTensor<4, 3> C;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = 0; l < 3; ++l)
          C[i][j][k][l] = (i == j && k == l ? lambda : 0) + (i == k && j == l ? mu : 0) +
                          (i == l && j == k ? mu : 0);
  return C;
}

// Checked before the finite element is built: FE_SimplexP offers degrees 1 and 2 only.
unsigned int checked_degree(unsigned int degree) {
  if (degree != 1 && degree != 2)
    throw std::invalid_argument("FEM/Degree: must be 1 or 2, got " + std::to_string(degree));
  return degree;
}

// Adds the nodal residual K_c u_c of one cell (K_c its stiffness matrix, fv reinitialised on
// it, `dofs` its DoFs) to `residual`.
void add_cell_residual(const FEValues<3>& fv, const SymmetricTensor<4, 3>& C,
                       const std::vector<types::global_dof_index>& dofs, const Vector<double>& u,
                       Vector<double>& residual) {
  const unsigned int n = dofs.size();
  const FEValuesExtractors::Vector displacement(0);
  FullMatrix<double> cell_matrix(n, n);
  Vector<double> u_local(n), ku(n);
  for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
    for (unsigned int i = 0; i < n; ++i) {
      const auto Ce = C * fv[displacement].symmetric_gradient(i, q);
      for (unsigned int j = 0; j < n; ++j)
        cell_matrix(i, j) += (Ce * fv[displacement].symmetric_gradient(j, q)) * fv.JxW(q);
    }
  for (unsigned int i = 0; i < n; ++i)
    u_local(i) = u(dofs[i]);
  cell_matrix.vmult(ku, u_local);
  for (unsigned int i = 0; i < n; ++i)
    residual(dofs[i]) += ku(i);
}

// Adds the force the clamped face exerts on the sample [N] to `reaction`: the nodal residual
// K u - f of the unconstrained system (`residual` = K u), summed per component over the
// clamped DoFs.
void add_reaction_force(const DoFHandler<3>& dof_handler, const FESystem<3>& fe,
                        const AffineConstraints<double>& constraints,
                        const Vector<double>& residual, const Vector<double>& unconstrained_rhs,
                        meshes::Vec3& reaction) {
  // Component of each DoF from the finite element (robust to DoF numbering).
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  std::vector<unsigned int> component(dof_handler.n_dofs(), 0);
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    cell->get_dof_indices(dofs);
    for (unsigned int i = 0; i < dofs.size(); ++i)
      component[dofs[i]] = fe.system_to_component_index(i).first;
  }
  for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
    if (constraints.is_constrained(i))
      reaction[component[i]] += residual(i) - unconstrained_rhs(i);
}
} // namespace

ElasticitySolver::ElasticitySolver(const Triangulation<3>& tria, const BoundaryFaceMap& faces,
                                   const ElasticityParameters& p)
    : tria_(tria), faces_(faces), p_(p), fe_(FE_SimplexP<3>(checked_degree(p.degree)), 3),
      mapping_(FE_SimplexP<3>(1)), dof_handler_(tria) {
  if (!(p.youngs_modulus > 0))
    throw std::invalid_argument("FEM/Young's modulus: must be positive [Pa]");
  if (!(p.poisson_ratio > -1 && p.poisson_ratio < 0.5))
    throw std::invalid_argument("FEM/Poisson ratio: must lie in (-1, 0.5)");
  if (!(p.yield_stress > 0))
    throw std::invalid_argument("FEM/Yield stress: must be positive [Pa]");
  if (!(p.averaging_radius >= 0) || !std::isfinite(p.averaging_radius))
    throw std::invalid_argument("FEM/Stress averaging radius: must be 0 or positive [m]");
}

ElasticityResult ElasticitySolver::run(const meshes::FaceField<meshes::Vec3>& forces) {
  forces.check_matches(faces_.surface());
  if (!forces.extensive())
    throw std::invalid_argument("face field '" + forces.name() +
                                "' must be extensive (forces per face, not tractions)");
  ElasticityResult r;
  meshes::Stopwatch clock;
  setup_system();
  r.setup_seconds = clock.seconds();
  r.n_dofs = dof_handler_.n_dofs();
  clock.restart();
  assemble_system(forces, r);
  r.assemble_seconds = clock.seconds();
  clock.restart();
  solve(r);
  r.solve_seconds = clock.seconds();
  const auto samples = compute_stresses(r);
  clock.restart();
  compute_measures(samples, r);
  r.measures_seconds = clock.seconds();
  return r;
}

void ElasticitySolver::setup_system() {
  dof_handler_.distribute_dofs(fe_);
  constraints_.clear();
  DoFTools::make_hanging_node_constraints(dof_handler_, constraints_);
  const Functions::ZeroFunction<3> zero(3);
  const meshes::LabelRoles& roles = faces_.surface().roles;
  for (const auto id : tria_.get_boundary_ids())
    if (roles.clamped(int(id)))
      VectorTools::interpolate_boundary_values(mapping_, dof_handler_, id, zero, constraints_);
  if (roles.any(meshes::FaceRole::held))
    constrain_held_faces();
  constraints_.close();
  if (constraints_.n_constraints() == 0)
    throw std::runtime_error("FEM: no degree of freedom lies on a clamped face (the sample's "
                             "bottom, or a part's clamped surfaces)");
  DynamicSparsityPattern dsp(dof_handler_.n_dofs());
  DoFTools::make_sparsity_pattern(dof_handler_, dsp, constraints_, false);
  matrix_.reinit(dsp);
  rhs_.reinit(dof_handler_.n_dofs());
  unconstrained_rhs_.reinit(dof_handler_.n_dofs());
  solution_.reinit(dof_handler_.n_dofs());
}

void ElasticitySolver::constrain_held_faces() {
  const meshes::LabelRoles& roles = faces_.surface().roles;
  std::vector<types::global_dof_index> face_dofs;
  for (const auto& cell : dof_handler_.active_cell_iterators())
    for (const auto f : cell->face_indices()) {
      const auto face = cell->face(f);
      if (!face->at_boundary() || !roles.held(int(face->boundary_id())))
        continue;
      const Tensor<1, 3> n =
          cross_product_3d(face->vertex(1) - face->vertex(0), face->vertex(2) - face->vertex(0));
      const double norm = n.norm();
      // The support it rests on is normal to an axis of the frame (the holder's walls: x or
      // y). A worn side may tilt slightly (its top vertices recede with the wear face), the
      // support does not; a face more than 30 degrees off every axis has no such support.
      unsigned int axis = 0;
      for (unsigned int d = 1; d < 3; ++d)
        if (std::abs(n[d]) > std::abs(n[axis]))
          axis = d;
      if (!(std::abs(n[axis]) > std::cos(30 * numbers::PI / 180) * norm))
        throw std::runtime_error("FEM: a held face (label " +
                                 meshes::label::name(int(face->boundary_id())) +
                                 ") is not normal to x, y or z within 30 degrees; the support "
                                 "(u . n = 0) holds faces normal to an axis of the part's "
                                 "frame, as the box sample's sides in its holder");
      face_dofs.resize(fe_.n_dofs_per_face(f));
      face->get_dof_indices(face_dofs);
      for (unsigned int i = 0; i < face_dofs.size(); ++i)
        if (fe_.face_system_to_component_index(i, f).first == axis &&
            !constraints_.is_constrained(face_dofs[i]))
          constraints_.add_line(face_dofs[i]);
    }
}

void ElasticitySolver::assemble_system(const meshes::FaceField<meshes::Vec3>& forces,
                                       ElasticityResult& r) {
  const QGaussSimplex<3> quadrature(fe_.degree + 1);
  const QGaussSimplex<2> face_quadrature(fe_.degree + 1);
  FEValues<3> fv(mapping_, fe_, quadrature, update_gradients | update_JxW_values);
  FEFaceValues<3> ffv(mapping_, fe_, face_quadrature, update_values | update_JxW_values);
  const auto C = stiffness(p_.youngs_modulus, p_.poisson_ratio);
  const unsigned int n = fe_.n_dofs_per_cell();
  FullMatrix<double> cell_matrix(n, n);
  Vector<double> cell_rhs(n);
  std::vector<types::global_dof_index> dofs(n);
  std::vector<SymmetricTensor<2, 3>> eps(n);
  // Traction per cell face from the surface field.
  std::map<std::pair<unsigned int, unsigned int>, Tensor<1, 3>> traction;
  const auto area = meshes::face_areas(faces_.surface());
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto& F = forces[f];
    r.applied_force += F;
    if (F.x == 0 && F.y == 0 && F.z == 0)
      continue;
    Tensor<1, 3> t;
    for (unsigned int d = 0; d < 3; ++d)
      t[d] = F[d] / area[f];
    traction[{faces_[f].cell->active_cell_index(), faces_[f].face_no}] = t;
  }
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    fv.reinit(cell);
    cell_matrix = 0;
    cell_rhs = 0;
    for (unsigned int q = 0; q < quadrature.size(); ++q) {
      for (unsigned int i = 0; i < n; ++i)
        eps[i] = fv[FEValuesExtractors::Vector(0)].symmetric_gradient(i, q);
      for (unsigned int i = 0; i < n; ++i) {
        const auto Ce = C * eps[i];
        for (unsigned int j = i; j < n; ++j)
          cell_matrix(i, j) += (Ce * eps[j]) * fv.JxW(q);
      }
    }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < i; ++j)
        cell_matrix(i, j) = cell_matrix(j, i);
    for (const auto f : cell->face_indices()) {
      if (!cell->face(f)->at_boundary())
        continue;
      const auto it = traction.find({cell->active_cell_index(), f});
      if (it == traction.end())
        continue;
      ffv.reinit(cell, f);
      for (unsigned int q = 0; q < face_quadrature.size(); ++q)
        for (unsigned int i = 0; i < n; ++i) {
          const unsigned int c = fe_.system_to_component_index(i).first;
          cell_rhs(i) += it->second[c] * ffv.shape_value(i, q) * ffv.JxW(q);
        }
    }
    cell->get_dof_indices(dofs);
    unconstrained_rhs_.add(dofs, cell_rhs);
    constraints_.distribute_local_to_global(cell_matrix, cell_rhs, dofs, matrix_, rhs_);
  }
  matrix_.compress(VectorOperation::add);
}

void ElasticitySolver::solve(ElasticityResult& r) {
  TrilinosWrappers::PreconditionAMG amg;
  TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic = true;
  data.higher_order_elements = fe_.degree > 1;
  data.smoother_sweeps = 2;
  data.aggregation_threshold = 0.02;
  // ML's near null space: the six rigid-body modes (three translations, three rotations
  // about the centroid of the DoFs) rather than only the translations; the rotations cut
  // the CG iterations of the clamped sample markedly, most for P2.
  Teuchos::ParameterList list;
  std::unique_ptr<Epetra_MultiVector> translations;
  data.set_parameters(list, translations, matrix_);
  std::vector<Point<3>> x(dof_handler_.n_dofs());
  DoFTools::map_dofs_to_support_points(mapping_, dof_handler_, x);
  std::vector<unsigned int> component(dof_handler_.n_dofs());
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    cell->get_dof_indices(dofs);
    for (unsigned int j = 0; j < dofs.size(); ++j)
      component[dofs[j]] = fe_.system_to_component_index(j).first;
  }
  Point<3> centre;
  for (const auto& p : x)
    centre += p / double(x.size());
  const Epetra_Map& rows = matrix_.trilinos_matrix().RowMap();
  const int n_local = rows.NumMyElements();
  null_space_.assign(6 * std::size_t(n_local), 0.0);
  for (int i = 0; i < n_local; ++i) {
    const auto g = types::global_dof_index(rows.GID(i));
    const unsigned int c = component[g];
    const Tensor<1, 3> d = x[g] - centre;
    double* mode = null_space_.data() + i;
    mode[c * std::size_t(n_local)] = 1;
    // Rotations about z, x, y: (-y, x, 0), (0, -z, y), (z, 0, -x).
    const double rz[3] = {-d[1], d[0], 0}, rx[3] = {0, -d[2], d[1]}, ry[3] = {d[2], 0, -d[0]};
    mode[3 * std::size_t(n_local)] = rz[c];
    mode[4 * std::size_t(n_local)] = rx[c];
    mode[5 * std::size_t(n_local)] = ry[c];
  }
  list.set("null space: type", "pre-computed");
  list.set("null space: dimension", 6);
  list.set("null space: vectors", null_space_.data());
  amg.initialize(matrix_, list);
  SolverControl control(10000, p_.relative_tolerance * rhs_.l2_norm());
  SolverCG<Vector<double>> cg(control);
  solution_ = 0;
  if (rhs_.l2_norm() > 0)
    cg.solve(matrix_, solution_, rhs_, amg);
  constraints_.distribute(solution_);
  r.iterations = control.last_step();
}

StressSamples ElasticitySolver::compute_stresses(ElasticityResult& r) {
  const QGaussSimplex<3> quadrature(fe_.degree + 1);
  FEValues<3> fv(mapping_, fe_, quadrature,
                 update_gradients | update_JxW_values | update_quadrature_points);
  StressSamples samples;
  const std::size_t n_samples = std::size_t(tria_.n_active_cells()) * quadrature.size();
  samples.points.reserve(n_samples);
  samples.stress.reserve(n_samples);
  samples.weights.reserve(n_samples);
  const auto C = stiffness(p_.youngs_modulus, p_.poisson_ratio);
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  std::vector<SymmetricTensor<2, 3>> strain(quadrature.size());
  von_mises_.reinit(tria_.n_active_cells());
  for (auto& p : principal_)
    p.reinit(tria_.n_active_cells());
  std::vector<double> cell_max(tria_.n_active_cells(), 0);
  // Reaction: (K u - f) of the unconstrained system on the clamped DoFs.
  Vector<double> residual(dof_handler_.n_dofs());
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    fv.reinit(cell);
    fv[FEValuesExtractors::Vector(0)].get_function_symmetric_gradients(solution_, strain);
    double vm_sum = 0, vol = 0;
    std::array<double, 3> pr{0, 0, 0};
    for (unsigned int q = 0; q < quadrature.size(); ++q) {
      const auto s = C * strain[q];
      const double vm = fem::von_mises(s);
      samples.points.push_back(fv.quadrature_point(q));
      samples.stress.push_back(s);
      samples.weights.push_back(fv.JxW(q));
      vm_sum += vm * fv.JxW(q);
      const auto ev = eigenvalues(s);
      for (int k = 0; k < 3; ++k)
        pr[k] += ev[k] * fv.JxW(q);
      vol += fv.JxW(q);
      r.max_von_mises_qp = std::max(r.max_von_mises_qp, vm);
      cell_max[cell->active_cell_index()] = std::max(cell_max[cell->active_cell_index()], vm);
    }
    von_mises_[cell->active_cell_index()] = vm_sum / vol;
    for (int k = 0; k < 3; ++k)
      principal_[k][cell->active_cell_index()] = pr[k] / vol;
    bool clamped = false;
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary()) {
        const int id = int(cell->face(f)->boundary_id());
        auto& m = r.max_von_mises_per_label[id];
        m = std::max(m, cell_max[cell->active_cell_index()]);
        clamped = clamped || faces_.surface().roles.clamped(id);
      }
    // Vertices on the clamped face may belong to cells without a clamped face.
    cell->get_dof_indices(dofs);
    for (unsigned int i = 0; i < dofs.size() && !clamped; ++i)
      clamped = constraints_.is_constrained(dofs[i]);
    if (clamped)
      add_cell_residual(fv, C, dofs, solution_, residual);
  }
  add_reaction_force(dof_handler_, fe_, constraints_, residual, unconstrained_rhs_,
                     r.reaction_force);
  r.safety_factor = r.max_von_mises_qp > 0 ? p_.yield_stress / r.max_von_mises_qp : 0;
  r.max_displacement = solution_.linfty_norm();
  return samples;
}

void ElasticitySolver::compute_measures(const StressSamples& samples, ElasticityResult& r) const {
  std::vector<double> vm(samples.stress.size());
  for (std::size_t q = 0; q < vm.size(); ++q)
    vm[q] = fem::von_mises(samples.stress[q]);
  if (p_.averaging_radius == 0) {
    const auto pct = volume_percentiles(vm, samples.weights, {0.99, 0.999});
    r.von_mises_p99 = pct[0];
    r.von_mises_p999 = pct[1];
    return;
  }
  // The ball average with the samples grouped by cell: whole cells where the ball holds them,
  // single quadrature points only where the sphere cuts a cell (stress_measures.cc).
  const auto per_cell = unsigned(samples.points.size() / tria_.n_active_cells());
  const BallAverage ball(samples, p_.averaging_radius, per_cell);
  const auto& surface = faces_.surface();
  std::vector<Point<3>> centres;
  for (const auto& c : meshes::face_centroids(surface))
    centres.emplace_back(c.x, c.y, c.z);
  const auto& used = tria_.get_used_vertices();
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v])
      centres.push_back(tria_.get_vertices()[v]);
  const std::size_t n_extremum_centres = centres.size();
  centres.insert(centres.end(), ball.cell_centroids().begin(), ball.cell_centroids().end());
  const auto value = ball.von_mises_at(centres);
  r.face_von_mises_ball.assign(value.begin(), value.begin() + long(surface.n_faces()));
  // The first largest value over the surface and the vertices, in the fixed order of the
  // centres (where the largest ball average lies: under a load or at a corner).
  const auto end = value.begin() + long(n_extremum_centres);
  const auto top = std::max_element(value.begin(), end);
  r.max_von_mises_ball = *top;
  const auto& at = centres[std::size_t(top - value.begin())];
  r.max_ball_centre = {at[0], at[1], at[2]};
  // The percentiles of the ball-averaged field over the cells by volume: the quadrature
  // points' own von Mises would count the singular stress at re-entrant edges and the clamp,
  // whose share of the top 0.1 % grows under refinement (docs/fem.md, mesh independence).
  const std::vector<double> cell_value(end, value.end());
  const auto pct = volume_percentiles(cell_value, ball.cell_volumes(), {0.99, 0.999});
  r.von_mises_p99 = pct[0];
  r.von_mises_p999 = pct[1];
}

} // namespace wear::fem
