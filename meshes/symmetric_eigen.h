#pragma once
// Eigen-decomposition of a symmetric 3 x 3 matrix (an inertia tensor, a patch's covariance).
#include "meshes/vec3.h"

namespace wear::meshes {

/// Eigenvalues (ascending) and unit eigenvectors of the symmetric 3 x 3 matrix a (cyclic
/// Jacobi rotations to round-off); the vectors form a right-handed triad.
void symmetric_eigen(const double a[3][3], Vec3& values, Vec3 vectors[3]);

} // namespace wear::meshes
