#pragma once
// Linear elasticity of the sample (docs/theory.md section 6.2): simplex P1 or P2 elements, clamped
// bottom face (and, in the holder, sides held at zero normal displacement), tractions from an
// extensive per-face force field on the labelled boundary.
#include "fem/boundary_face_map.h"
#include "fem/stress_measures.h"
#include "meshes/face_field.h"

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace wear::fem {

struct ElasticityParameters {
  double youngs_modulus = 700e6; ///< [Pa] PE1000
  double poisson_ratio = 0.40;
  double yield_stress = 20e6;        ///< [Pa] for the safety factor
  unsigned int degree = 1;           ///< 1 (P1) or 2 (P2)
  double relative_tolerance = 1e-10; ///< of the CG residual
  /// [m] radius of the ball the stress is averaged over (stress_measures.h); 0: no ball
  /// average (a coupled run sets the mean particle radius when the case file gives 0)
  double averaging_radius = 0;
};

struct ElasticityResult {
  unsigned int n_dofs = 0, iterations = 0;
  double setup_seconds = 0, assemble_seconds = 0, solve_seconds = 0;
  meshes::Vec3 applied_force; ///< [N] sum of the applied face forces
  /// [N] force the supports exert on the sample: the clamped bottom, and the holder's walls
  /// on the held faces (the sample's sides in a holder)
  meshes::Vec3 reaction_force;
  /// [Pa] largest von Mises over all quadrature points: mesh-dependent, it grows without
  /// bound under refinement near a contact load (docs/theory.md)
  double max_von_mises_qp = 0;
  /// [Pa] volume-weighted 99th percentile of the ball-averaged von Mises over the cells (of
  /// the quadrature points' own von Mises when the averaging radius is 0)
  double von_mises_p99 = 0;
  double von_mises_p999 = 0; ///< [Pa] the same, 99.9th percentile
  /// [Pa] largest von Mises of the stress averaged over a ball of radius averaging_radius,
  /// over the centres: the mesh vertices and the surface faces' centroids (0: no radius)
  double max_von_mises_ball = 0;
  meshes::Vec3 max_ball_centre; ///< [m] where that maximum is
  /// [Pa] per face of the map's surface: von Mises of the ball-averaged stress centred at the
  /// face's centroid (empty without a radius)
  std::vector<double> face_von_mises_ball;
  double measures_seconds = 0; ///< [s] percentiles and ball averages
  double safety_factor = 0;    ///< yield stress / max_von_mises_qp
  double max_displacement = 0; ///< [m] largest displacement component
  /// Max von Mises [Pa] over the cells touching each boundary label's faces.
  std::map<int, double> max_von_mises_per_label;
};

/// Linear elasticity solved as in deal.II's tutorials: run() = setup_system, assemble_system,
/// solve, compute_stresses. Requires MPI to be initialised (Trilinos AMG).
class ElasticitySolver {
public:
  ElasticitySolver(const dealii::Triangulation<3>& tria, const BoundaryFaceMap& faces,
                   const ElasticityParameters& p);

  /// Tractions from forces per surface face (extensive, [N]); throws when the field is not
  /// of the surface the map was built on (revision and face count).
  ElasticityResult run(const meshes::FaceField<meshes::Vec3>& forces);

  const dealii::DoFHandler<3>& dof_handler() const { return dof_handler_; }
  const dealii::Vector<double>& displacement() const { return solution_; }
  /// Cell-averaged von Mises stress [Pa] of the last run (one value per active cell).
  const dealii::Vector<double>& von_mises() const { return von_mises_; }
  /// Cell-averaged principal stresses [Pa], largest first (3 vectors of one value per cell).
  const std::array<dealii::Vector<double>, 3>& principal_stresses() const { return principal_; }
  const dealii::Mapping<3>& mapping() const { return mapping_; }

private:
  void setup_system();
  /// u . n = 0 on the faces whose role is held (the sample's sides in its holder: they keep
  /// zero normal displacement and slide along the holder's walls, docs/theory.md section 6),
  /// into constraints_.
  void constrain_held_faces();
  void assemble_system(const meshes::FaceField<meshes::Vec3>& forces, ElasticityResult& r);
  void solve(ElasticityResult& r);
  /// The stress at every quadrature point; fills the cell fields and r's qp maxima.
  StressSamples compute_stresses(ElasticityResult& r);
  /// Percentiles and ball averages of `samples` into r.
  void compute_measures(const StressSamples& samples, ElasticityResult& r) const;

  const dealii::Triangulation<3>& tria_;
  const BoundaryFaceMap& faces_;
  ElasticityParameters p_;
  dealii::FESystem<3> fe_;
  dealii::MappingFE<3> mapping_;
  dealii::DoFHandler<3> dof_handler_;
  dealii::AffineConstraints<double> constraints_;
  dealii::TrilinosWrappers::SparseMatrix matrix_;
  dealii::Vector<double> rhs_, solution_, unconstrained_rhs_;
  dealii::Vector<double> von_mises_;
  std::array<dealii::Vector<double>, 3> principal_;
  std::vector<double> null_space_; ///< rigid-body modes for ML, alive while it is set up
};

} // namespace wear::fem
