#pragma once
// A clump template fitted to a closed surface (the STL of a scanned or drawn stone): spheres
// inscribed in it, added greedily until their union's volume is within a stated error of the
// solid's.
#include "dem/engine/clump_shape.h"
#include "meshes/surface_mesh.h"

#include <string>

namespace wear::dem {

struct ClumpFitParameters {
  int max_spheres = 8;       ///< [-] members at most
  double volume_error = 0.1; ///< [-] stop once |V_union - V_solid| / V_solid is below it
  int cells_per_extent = 64; ///< [-] grid nodes along the solid's largest extent
};

struct ClumpFit {
  ClumpTemplate clump;     ///< in the surface's frame and unit
  double volume_error = 0; ///< [-] |V_union - V_solid| / V_solid reached
  double solid_volume = 0; ///< [m^3] enclosed by the surface
};

/// Fits a clump to the closed, outward-oriented surface s (named `what` in messages). Throws
/// std::invalid_argument when s encloses no volume or the parameters are out of range, and
/// std::runtime_error naming the error reached when max_spheres do not reach volume_error.
ClumpFit fit_clump(const meshes::SurfaceMesh& s, const ClumpFitParameters& p,
                   const std::string& what);

} // namespace wear::dem
