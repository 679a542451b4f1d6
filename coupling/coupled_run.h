#pragma once
// `wearsim run`: the coupled DEM-FEM wear loop of model.md section 6, one stage at a time.
// run() reads as the algorithm: per stage run_dem, compute_wear, solve_stress,
// update_geometry, output_results, checkpoint.
#include "coupling/case_parameters.h"
#include "coupling/checkpoint.h"
#include "coupling/run_output.h"
#include "dem/wear_tester.h"
#include "fem/worn_sample.h"

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

struct RunOptions {
  bool resume = false;  ///< continue from <output>/checkpoint.h5
  bool progress = true; ///< live line on a terminal (stderr)
  int stop_after = 0;   ///< stop after this many stages of this invocation (0: run all)
};

class CoupledRun {
public:
  /// Checks the case and the output folder; nothing runs yet.
  CoupledRun(const CaseParameters& p, std::ostream& log, const RunOptions& options = {});

  /// The whole schedule (or what is left of it when resuming).
  void run();

  const std::vector<StageRecord>& stages() const { return stages_; }
  const dem::WearTester& tester() const { return *tester_; }
  const fem::WornSample* sample() const { return sample_.get(); }
  std::string checkpoint_path() const { return p_.output.directory + "/checkpoint.h5"; }

private:
  void setup();
  void run_dem(StageRecord& r);
  meshes::FaceField<double> compute_wear(StageRecord& r);
  void solve_stress(StageRecord& r);
  void update_geometry(const meshes::FaceField<double>& removed, StageRecord& r);
  void output_results(StageRecord& r);
  void checkpoint();
  void restore(const Checkpoint& c);
  void print_stage(const StageRecord& r) const;
  void print_timing() const;

  const meshes::SurfaceMesh& sample_surface() const; ///< current, sample frame
  fem::WornSampleParameters worn_parameters() const;

  CaseParameters p_;
  std::ostream& log_;
  RunOptions options_;
  std::string parameters_text_;
  std::vector<int> plan_; ///< Scheme of each stage
  bool staged_ = false, reference_ = false;
  bool worn_through_reported_ = false;  ///< the first worn-through stage was logged
  meshes::SurfaceMesh initial_surface_; ///< sample frame, as generated
  std::unique_ptr<dem::WearTester> tester_;
  std::unique_ptr<fem::WornSample> sample_;
  std::unique_ptr<RunOutput> output_;
  std::vector<StageRecord> stages_;
  // The current stage: DEM sums per face of the sample surface, and the loads' stress.
  std::vector<double> stage_removed_, stage_normal_impulse_; ///< [m^3], [N s]
  std::vector<meshes::Vec3> stage_impulse_;                  ///< [N s], sample frame
  meshes::FaceField<double> stage_applied_;                  ///< [m^3] asked of the geometry
  std::vector<double> stage_von_mises_; ///< [Pa] per face, this stage's loads (pre-update)
  std::vector<double> face_von_mises_;  ///< [Pa] per face of the current surface (last stage)
  double stage_wall_ = 0;               ///< [s] mean wall time of the stages run so far
  std::vector<double> dem_cumulative_;  ///< [m^3] wear-law volume per face (no FEM sample)
};

/// `wearsim run [--resume] <case.prm>`; returns the exit code.
int run_run_command(const std::vector<std::string>& args, std::ostream& log);

} // namespace wear::coupling
