#pragma once
// The node displacement of a worn surface shared by the reference deformation (dem/) and the
// FEM boundary recession (fem/).
#include "meshes/surface_mesh.h"

#include <cstdint>
#include <vector>

namespace wear::meshes {

/// Per vertex: -n_v * sum_f V_f / sum_f A_f over the wearing faces f around the vertex
/// (labels base and C<j><k>), n_v the normalized area-weighted normal of those faces; zero
/// for vertices without wearing faces. `removed_volume` is per face [m^3], extensive.
std::vector<Vec3> area_weighted_recession(const SurfaceMesh& m,
                                          const std::vector<double>& removed_volume);

/// Per face: 1 for the seeds and the faces within `rings` vertex rings of them, else 0.
std::vector<char> faces_within_rings(const SurfaceMesh& m, const std::vector<std::uint32_t>& seeds,
                                     int rings);

/// Spreads removed volume [m^3 per face] around `seeds` (e.g. the faces where a recession
/// folds): within `rings` vertex rings of a seed, over wearing faces only, the depth V_f / A_f
/// diffuses between faces sharing an edge (rings^2 explicit steps, so about `rings` faces
/// far). The total is kept to round-off and no face goes negative. Returns the volume moved
/// between faces [m^3].
double spread_removed_volume(const SurfaceMesh& m, std::vector<double>& removed_volume,
                             const std::vector<std::uint32_t>& seeds, int rings);

} // namespace wear::meshes
