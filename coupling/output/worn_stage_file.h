#pragma once
// A worn sample with one stage's wear, as a file: the test data and benchmark workload of the
// worn-geometry evolution (tests/data/wear-out/stage23.h5, written by extract.py beside it).
#include "fem/worn_sample.h"

#include <string>
#include <vector>

namespace wear::coupling {

struct WornStage {
  fem::WornSampleState state;         ///< the sample before the stage, no wear accumulated
  std::vector<double> removed_volume; ///< [m^3] the stage's wear per surface face
};

/// Reads `path` (HDF5): `vertices` [m] (n x 3, sample frame), `tetrahedra` (n x 4),
/// `triangles` (the boundary faces, m x 3 indices into vertices), `labels` (one per face, the
/// labels of meshes::label) and `removed_volume` [m^3] per face. The surface is the boundary's
/// triangles on their own vertices in the file's face order; the sample stands in its holder
/// (meshes::sample_roles(true)). Throws std::runtime_error naming the file and what is wrong.
WornStage read_worn_stage(const std::string& path);

/// Writes `state` (its volume mesh and surface) with one stage's `removed_volume` per surface
/// face to `path` in the layout read_worn_stage reads, atomically: the surface's triangles in
/// volume-vertex numbers (each surface vertex is a volume vertex, the same doubles). Throws
/// std::runtime_error naming the file where a surface vertex is not a volume vertex.
void write_worn_stage(const std::string& path, const fem::WornSampleState& state,
                      const std::vector<double>& removed_volume);

} // namespace wear::coupling
