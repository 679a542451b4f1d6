#pragma once
// Wear applied to the volume mesh: relaxation of the worn surface before its recession
// (meshes/recession.h), interior mesh motion, and volume-mesh quality.
#include "fem/boundary_face_map.h"
#include "meshes/sliding_constraint.h"
#include "meshes/surface_mesh.h"

#include <deal.II/grid/tria.h>

#include <vector>

namespace wear::fem {

/// Tangential relaxation of a worn region: every vertex with `moving[v]` whose faces all
/// carry one wearing label moves by `weight` times the tangential part (normal component
/// removed, area-weighted vertex normal) of the offset to the mean of its edge neighbours.
/// Recession along normals squeezes the triangles of a receding tip together; relaxing them
/// keeps the surface fit for mesh motion and remeshing. Label boundaries and the unworn
/// surface stay put. The vertices of an edge inside one label whose two faces' normals have
/// a cosine below `spike_cos` (nearly folded flat: a spike that wear sharpened) take the
/// full offset, normal part included, which cuts the spike (-2: never).
/// Returns the displacement per vertex [m].
std::vector<meshes::Vec3> tangential_relaxation(const meshes::SurfaceMesh& surface,
                                                const std::vector<char>& moving,
                                                double weight = 0.5, double spike_cos = -0.9);

/// Relaxation along the crease where the wear face meets a flat side: a vertex there moves by
/// `weight` times the part, along the chord between its two crease neighbours, of the offset
/// to their midpoint, kept in the side's plane. The recession moves crease vertices down the
/// side along the wear face's normals, which tilt along the crease beside a groove; uneven
/// there, neighbours close up and cross, and the crease doubles back (the wear-out case at
/// 100x, stage 29). Moving along the chord evens the spacing and leaves the crease's shape
/// unchanged to first order. Corners of the crease (three faces' planes) stay. Returns the
/// displacement per vertex [m]. `constraint`: meshes::sliding_constraints(surface) if the
/// caller has it already (computed here when null).
std::vector<meshes::Vec3>
crease_relaxation(const meshes::SurfaceMesh& surface, double weight = 0.5,
                  const std::vector<meshes::SlidingConstraint>* constraint = nullptr);

/// Relaxation of the unworn surface (sides, bottom) as the wear face recedes past it: every
/// vertex whose faces all do not wear moves by `weight` times the offset to the mean of its edge
/// neighbours, kept in its flat face group or along its crease (meshes::sliding_constraints),
/// so the unworn shape and the enclosed volume stay as they are. Without it, the strip of side
/// triangles under a receding wear face edge is squeezed until it folds. Returns the
/// displacement per vertex [m]. `constraint` as for crease_relaxation.
std::vector<meshes::Vec3>
unworn_relaxation(const meshes::SurfaceMesh& surface, double weight = 0.5,
                  const std::vector<meshes::SlidingConstraint>* constraint = nullptr);

struct VolumeQuality {
  double min_scaled_jacobian = 1; ///< [-] 1 for the regular tetrahedron, <= 0 inverted
  double min_dihedral_deg = 180;  ///< [deg]
  double max_dihedral_deg = 0;    ///< [deg]
  double max_aspect_ratio = 0;    ///< [-] longest edge / (2 sqrt(6) inradius); 1 regular
  std::size_t n_inverted = 0;     ///< cells with non-positive volume
  long worst_cell = -1;           ///< cell of the smallest scaled Jacobian
};
/// With `per_cell`, also the scaled Jacobian of every active cell (by active cell index).
VolumeQuality volume_quality(const dealii::Triangulation<3>& tria,
                             std::vector<double>* per_cell = nullptr);

struct MotionReport {
  unsigned int iterations = 0; ///< CG iterations, all components and sub-steps
  int substeps = 1;            ///< boundary moved in this many increments
  double seconds = 0;
  VolumeQuality quality;
};

/// Moves the boundary vertices of `tria` by the surface displacement (through the map of
/// the surface it was computed on) and the interior vertices by a vector Laplace problem
/// with stiffness 1 / cell volume (small cells move rigidly), P1 on the current mesh, every
/// other boundary vertex fixed; in increments that move no vertex by more than a quarter of
/// the surface edges at it (at most 50), each solved on the mesh the previous one produced.
/// Returns the new surface (same topology, new revision).
meshes::SurfaceMesh move_mesh(dealii::Triangulation<3>& tria, const BoundaryFaceMap& map,
                              const std::vector<meshes::Vec3>& surface_displacement,
                              MotionReport* report = nullptr);

} // namespace wear::fem
