#pragma once
// Output of a wear-tester run: history.h5 (the sample surface and every per-face field per
// revolution, particle snapshots), history.xdmf beside it for ParaView, and summary.csv
// with one row per revolution. Every file is rewritten atomically after each revolution.
#include "dem/evaluation/tester_evaluation.h"
#include "dem/tester/wear_tester.h"

#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

/// The per-revolution columns of summary.csv (no line end), shared by `wearsim dem` and
/// `wearsim run`; units in the column names.
void write_summary_header(std::ostream& out, int n_columns, const std::vector<int>& element_labels);
/// One revolution's row of those columns (no line end).
void write_summary_row(std::ostream& out, const dem::RevolutionRecord& r,
                       const std::vector<int>& element_labels);

class TesterOutput {
public:
  TesterOutput(std::string directory, const meshes::SurfaceMesh& initial_surface,
               const std::vector<int>& element_labels, int n_columns);

  /// Stores the fields of the revolution just completed (and a particle snapshot if asked).
  void add_revolution(dem::WearTester& tester, bool snapshot);
  /// Stores the particles now, as revolution `revolution` (0: the settled bed).
  void add_snapshot(dem::WearTester& tester, int revolution);
  /// Rewrites history.h5, history.xdmf and summary.csv.
  void write() const;

  std::string h5_path() const { return directory_ + "/history.h5"; }
  std::string xdmf_path() const { return directory_ + "/history.xdmf"; }
  std::string csv_path() const { return directory_ + "/summary.csv"; }

private:
  struct Revolution {
    int revolution = 0;
    double time = 0;
    std::vector<double> vertices;         // nv x 3, empty when unchanged from the initial surface
    std::vector<double> impulse;          // nf x 3
    std::vector<double> traction_impulse; // nf x 3
    std::vector<double> traction;         // nf x 3, viewing only
    std::vector<double> normal_impulse, archard, sliding_work, contact_steps, removed_volume,
        cumulative_removed_volume, wear_depth, mean_pressure;
  };
  struct Snapshot {
    int revolution = 0;
    double time = 0;
    std::vector<double> position, velocity, angular_velocity, radius;
    std::vector<std::int64_t> id;
  };
  void write_h5() const;
  void write_xdmf() const;
  void write_csv() const;

  std::string directory_;
  meshes::SurfaceMesh initial_;
  std::vector<int> element_labels_;
  int n_columns_;
  std::vector<Revolution> revolutions_;
  std::vector<Snapshot> snapshots_;
  std::vector<dem::RevolutionRecord> records_;
};

} // namespace wear::coupling
