#pragma once
// The records of a scene's run (`wearsim scene-run`), one per window, each file rewritten
// atomically at every record: scene_series.csv (time, particles, inserted and removed, the
// mass each outlet took and the net mass through each flux plane so far, per wall the
// window-mean force and moment about the origin in the wall's frame and the window's Archard
// load-distance, the particles' mean and largest speed), scene_wear.csv (the window's Archard
// load-distance per wall and label: the wear per labelled surface group), particles_<k>.vtu
// at the records that write the particles (dem::snapshot_due: every record, or the Snapshot
// records),
// and the walls: walls/<name>.vtu once for a wall that does not move, walls_<k>/<name>.vtu
// at every record for one that moves (a wearing part's worn surfaces: the wear loop's
// surface/ series); with Scene/Fields, the window's binned solid fraction, velocity and
// occupancy per cell in fields/record_<k>.h5 (datasets nz x ny x nx; attributes time,
// samples and the grid's x_minimum ... z_maximum), indexed by fields.xdmf (a time series of
// rectilinear grids with cell data, for ParaView).
#include "dem/scene/scene_run.h"

#include <string>

namespace wear::coupling {

class SceneSeries {
public:
  /// Writes the walls that keep their place (fixed, or their surface moving in place) into
  /// `directory`/walls/ and starts the tables; a wall moving as a rigid body goes to
  /// walls_<k>/ at every record k.
  SceneSeries(std::string directory, const dem::SceneRun& run);
  /// Whether a resumed run's folder holds the tables of its earlier records: a run carried
  /// to another machine without them (cases/reference-study/keep_running.sh) starts them
  /// again at its next record.
  enum class EarlierRows { read, absent };
  /// Continues the records of a resumed run: the tables, whose first row is record
  /// `first_record`, as they stood after record `n_records` (later rows, written after the
  /// checkpoint, are dropped) and the fields files from first_record to n_records. Throws
  /// naming a table that holds fewer. With EarlierRows::absent the tables start with their
  /// header and record n_records + 1.
  SceneSeries(std::string directory, const dem::SceneRun& run, int n_records, int first_record,
              EarlierRows earlier = EarlierRows::read);
  /// The next record, of window w, with the run as it stands at the window's end and its
  /// `particles` then (the scene's own, or over ranks every rank's gathered) and the bodies
  /// of its clumps among them (nullptr: spheres), written to particles_<k>.vtu when
  /// `snapshot` (and there are particles).
  void add(const dem::SceneWindow& w, const dem::SceneRun& run, const dem::Particles& particles,
           const dem::Clumps* clumps, bool snapshot);
  int n_records() const { return n_records_; }
  /// The record the tables' first row holds.
  int first_record() const { return first_record_; }

private:
  std::string directory_;
  std::string series_, wear_; ///< the tables so far
  int n_records_ = 0;
  int first_record_ = 1;
  std::vector<bool> changing_;                        ///< per wall: written at every record
  std::vector<std::pair<int, double>> field_records_; ///< record and time of each fields file

  void write_fields(int k, const dem::SceneWindow& w, const dem::FieldGrid& grid);
};

/// "t = 0.1234 s: 512 particles, 600 in (1.2 kg), 88 out (0.2 kg), mean speed 0.81 m/s".
std::string window_summary(const dem::SceneWindow& w);

} // namespace wear::coupling
