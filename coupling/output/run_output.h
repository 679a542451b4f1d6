#pragma once
// Results folder of `wearsim run`: per stage the sample surface (surface/stage_NNNN.h5, .vtu)
// and volume (volume/stage_NNNN.h5, .vtu) with their fields; history.xdmf indexing both for
// ParaView; history.h5 with the per-revolution and per-stage scalars; summary.csv (one row
// per revolution) and stages.csv (one row per stage). Every file is written atomically.
#include "coupling/output/checkpoint.h"
#include "coupling/output/grid_history.h"
#include "meshes/surface_mesh.h"

#include <string>
#include <vector>

namespace wear::coupling {

class RunOutput {
public:
  /// `writes` false: every call returns without writing (the ranks after the first of a run
  /// over ranks, whose results are rank 0's).
  explicit RunOutput(std::string directory, bool writes = true);
  bool writes() const { return writes_; }

  /// The sample surface at the end of stage `stage` (0: initial), sample frame, with
  /// per-face fields (one component each).
  void add_surface(int stage, double time, const meshes::SurfaceMesh& surface,
                   const std::vector<meshes::VtuArray>& cell_fields);
  void add_volume(int stage, double time, const meshes::VtuGrid& grid);
  /// Lists the grids of stages written by an earlier, interrupted invocation again.
  void reload(const std::vector<StageRecord>& stages);
  /// Rewrites history.h5, summary.csv and stages.csv from all records so far.
  void write_tables(const std::vector<dem::RevolutionRecord>& revolutions,
                    const std::vector<StageRecord>& stages, int n_columns,
                    const std::vector<int>& element_labels) const;

  std::string summary_path() const { return directory_ + "/summary.csv"; }
  std::string stages_path() const { return directory_ + "/stages.csv"; }
  std::string h5_path() const { return directory_ + "/history.h5"; }
  std::string xdmf_path() const { return directory_ + "/history.xdmf"; }

private:
  void write_index() const;
  std::string directory_;
  bool writes_ = true;
  GridHistory surface_, volume_;
};

} // namespace wear::coupling
