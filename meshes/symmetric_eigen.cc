// Eigen-decomposition of a symmetric 3 x 3 matrix by cyclic Jacobi rotations: each rotation
// in a (p, q) plane zeroes a[p][q] (Golub & Van Loan, algorithm 8.4.2); sweeps go on until the
// off-diagonal part is below 1e-16 of the diagonal's norm. The columns of the accumulated
// rotations are the eigenvectors.
#include "meshes/symmetric_eigen.h"

#include <algorithm>
#include <cmath>

namespace wear::meshes {

void symmetric_eigen(const double a_in[3][3], Vec3& values, Vec3 vectors[3]) {
  double a[3][3], v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      a[i][j] = a_in[i][j];
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= 1e-32 * diag)
      break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0)
          continue;
        // The rotation in the (p, q) plane that zeroes a[p][q] (Golub & Van Loan 8.4.2).
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < 3; ++k) { // a <- a J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) { // a <- J^T a
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) { // v <- v J
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return a[i][i] < a[j][j]; });
  for (int k = 0; k < 3; ++k) {
    values[k] = a[order[k]][order[k]];
    vectors[k] = {v[0][order[k]], v[1][order[k]], v[2][order[k]]};
  }
  vectors[2] = meshes::cross(vectors[0], vectors[1]);
}

} // namespace wear::meshes
