#pragma once
// The arrays a checkpoint is made of, each written and read back in its binary form: Vec3
// lists as n x 3, unsigned and 64-bit integers widened, the worn FEM sample, the stage
// records, a stage's summed loads. Each stateful part of a checkpoint (checkpoint.h,
// scene_checkpoint.h) composes them under its own group.
#include "coupling/loop/stage_record.h"
#include "coupling/output/hdf5_file.h"
#include "dem/evaluation/tester_evaluation.h"
#include "dem/wear/wall_loads.h"
#include "fem/worn_sample.h"
#include "meshes/vec3.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wear::coupling {

/// A stage stopped inside its DEM part: the loads it had summed so far, dem::WallLoads's
/// fields on the current part surface, in the part's frame.
struct OpenStage {
  std::vector<meshes::Vec3> impulse;          ///< [N s] per face
  std::vector<meshes::Vec3> traction_impulse; ///< [N s] per face, as the FEM receives it
  std::vector<double> normal_impulse, archard, sliding_work; ///< [N s], [N m], [J] per face
  std::vector<double> contact_steps, wear_volume;            ///< [-], [m^3] per face
  std::vector<double> impact_volume; ///< [m^3] per face (none in an older checkpoint: zeros)
  double duration = 0;               ///< [s] of the summed windows
};

/// An open stage holding `loads` (part frame).
OpenStage open_stage(const dem::WallLoads& loads);
/// The open stage's loads on `surface` (the current part surface); throws when the face
/// counts differ.
dem::WallLoads loads_of(const OpenStage& o, const meshes::SurfaceMesh& surface);

std::vector<double> flat(const std::vector<meshes::Vec3>& v);
/// Throws naming `name` when v is not n x 3.
std::vector<meshes::Vec3> vec3s(const std::vector<double>& v, const std::string& name);

template <typename T>
std::vector<std::int64_t> wide(const std::vector<T>& v) {
  return {v.begin(), v.end()};
}

template <typename T>
std::vector<T> narrow(const std::vector<std::int64_t>& v) {
  return {v.begin(), v.end()};
}

void write_vec3(Hdf5File& h5, const std::string& name, const std::vector<meshes::Vec3>& v);
void write_doubles(Hdf5File& h5, const std::string& name, const std::vector<double>& v);

/// The worn sample in group g: mesh arrays, surface (vertices, triangles, labels, attribute
/// revision), removed_volume, wear_depth, attribute n_remeshes.
void write_sample_state(Hdf5File& h5, const std::string& g, const fem::WornSampleState& s);
/// Throws when the arrays do not fit together.
fem::WornSampleState read_sample_state(const Hdf5Reader& h5, const std::string& g);

/// An open stage's per-face loads in group g (impulse, traction_impulse, normal_impulse,
/// archard, sliding_work, contact_steps, wear_volume); its duration and progress are the
/// caller's.
void write_load_arrays(Hdf5File& h5, const std::string& g, const OpenStage& o);
/// Fills o's per-face loads; throws when their lengths differ.
void read_load_arrays(const Hdf5Reader& h5, const std::string& g, OpenStage& o);

/// The stage records packed as numbers (pack()) in g/data, g/offsets, their distortions as
/// the text attribute g:distortions (checkpoint.cc, beside the record's field list).
void write_stage_records(Hdf5File& h5, const std::string& g, const std::vector<StageRecord>& r);
std::vector<StageRecord> read_stage_records(const Hdf5Reader& h5, const std::string& g);
/// The same for an evaluation's records, one per revolution (or period).
void write_revolution_records(Hdf5File& h5, const std::string& g,
                              const std::vector<dem::RevolutionRecord>& r);
std::vector<dem::RevolutionRecord> read_revolution_records(const Hdf5Reader& h5,
                                                           const std::string& g);
/// An open revolution's (or period's) samples in group g: scalars, the per-face sums at the
/// last sample, the per-sample series, column forces as n_columns x n_samples.
void write_revolution_samples(Hdf5File& h5, const std::string& g, const dem::RevolutionSamples& s);
dem::RevolutionSamples read_revolution_samples(const Hdf5Reader& h5, const std::string& g);

} // namespace wear::coupling
