#pragma once
// What a coupled run over MPI ranks (`mpirun -np N wearsim ...`) shares among its ranks, for
// the tester's run and a scene's alike: every rank runs the same loop, rank 0 writes and
// prints, the others keep what their FEM writes in a scratch folder; decisions (a stop, a
// checkpoint) are agreed, and every rank's worn surfaces must be the same bit for bit.
#include "coupling/loop/stop_signals.h"
#include "coupling/output/checkpoint.h"
#include "dem/engine/rank_link.h"
#include "meshes/surface_mesh.h"

#include <string>

namespace wear::coupling {

class RunRanks {
public:
  /// `link`: the ranks (null: one process, every call a no-op or the process's own answer).
  explicit RunRanks(dem::RankLink* link) : link_(link) {}
  RunRanks(const RunRanks&) = delete;
  RunRanks& operator=(const RunRanks&) = delete;
  /// Removes the scratch folder.
  ~RunRanks();

  dem::RankLink* link() const { return link_; }
  /// True on the rank that writes the output and prints (rank 0, or the one process).
  bool writer() const { return !link_ || link_->rank() == 0; }
  /// Every rank waits until rank 0 has its output folder ready (call after rank 0 prepared
  /// it); the other ranks then get a scratch folder of their own.
  void wait_for_folder();
  /// This rank's scratch folder (ranks after the first, after wait_for_folder); empty on the
  /// writer.
  const std::string& scratch() const { return scratch_; }
  /// The signal any rank received (the largest number), 0 if none: every rank stops together.
  int agreed_signal(const StopSignals& signals) const;
  /// True on every rank when `mine` is true on any.
  bool any(bool mine) const;
  /// Which part of a checkpoint's DEM state this rank reads (read_checkpoint).
  DemPart dem_part() const { return {link_ ? link_->rank() : 0, link_ ? link_->n_ranks() : 1}; }
  /// Writes checkpoint c to `path`: over ranks every rank's DEM state is gathered to rank 0,
  /// which writes them side by side (every rank calls it together).
  void write(const std::string& path, const Checkpoint& c) const;
  /// Throws when `surface` is not the same, bit for bit, on every rank; `what` names it and
  /// when (e.g. "the sample surfaces ... after the FEM part of stage 3").
  void require_same(const meshes::SurfaceMesh& surface, const std::string& what) const;

private:
  dem::RankLink* link_;
  std::string scratch_;
};

} // namespace wear::coupling
