#pragma once
// The DEM performance workloads of shared/anchors/liggghts, rebuilt in this engine.
#include "dem/engine/slab_decomposition.h"
#include "dem/engine/system.h"

#include <string>

namespace wear::dem {

struct BenchmarkOptions {
  /// annulus | annulus-clumps | sector5k | sector20k | sector45k | sample45k
  std::string workload = "annulus";
  std::uint64_t settle_steps = 24000; ///< as the anchor's NSETTLE, floor rotating
  std::uint64_t warm_steps = 500;
  std::uint64_t timed_steps = 2000;
  int repeats = 1;
  /// Floor and cylinders as triangle meshes (the walls before issue 30) instead of revolution
  /// walls (`wearsim bench dem --walls mesh|analytic`).
  bool mesh_walls = false;
};

/// Builds the workload into `s` (not set up): monodisperse 7.95 mm spheres, E = 5e7 Pa,
/// nu = 0.25, e = 0.5, mu = 0.5, mu_r = 0.1, rho = 2650, dt = 20 % of the Rayleigh time,
/// skin 2 mm, simple cubic lattice a = 1.03 d with 0.1 mm jitter, floor rotating at 90 deg/s.
/// annulus: the full annulus 0.29..0.50 m with static cylinders (anchor annulus45k);
/// annulus-clumps: the same walls and as many spheres as members of 11,112 rigid clumps of
/// four (7.95 mm mean member diameter, random orientations, inserted loose and settled by the
/// settle steps);
/// sectorNk: the cylindrical periodic sector (our geometry for the anchor's periodic
/// channels monoNk), 14 lattice layers, angle chosen for about N particles, rotating walls;
/// sample45k: sector45k plus the anchor's 100 x 100 mm plate of 3200 triangles facing the flow.
/// The floor and cylinders are revolution walls (full circles, exact), or with `mesh_walls`
/// the triangle meshes of meshes::generate_tester_walls (21 mm; in a sector widened 0.02 rad
/// past both cuts); the plate is always a mesh.
void build_benchmark(System& s, const std::string& workload, bool mesh_walls = false);
/// The same from the options (workload, mesh_walls).
void build_benchmark(System& s, const BenchmarkOptions& o);

/// Equal angular slabs of a built workload for `n_ranks` ranks (a ring: the sector's periodic
/// seam or, for the annulus, the full circle), measured at the inner cylinder.
SlabDecomposition benchmark_slabs(const System& s, int n_ranks);

} // namespace wear::dem
