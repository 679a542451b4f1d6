#pragma once
// The parts of a bed decomposed over ranks as one state: the checkpoints of a run over ranks
// gather every rank's part (gather_rank_states) and write them side by side; a run on another
// rank count merges them (merge_rank_states) into the bed as one process would hold it and
// decomposes that again (System::import_state). docs/dem.md, "A bed decomposed over ranks".
#include "dem/engine/rank_link.h"
#include "dem/engine/system.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace wear::dem {

/// Every field of s one after another, sizes first, as doubles (ids and counts are exact below
/// 2^53): a rank's part in one message.
std::vector<double> pack_state(const SystemState& s);
/// The state pack_state() made of `n` values at `values`; throws std::invalid_argument when
/// they do not make one.
SystemState unpack_state(const double* values, std::size_t n);

/// Every rank's state on rank 0, in rank order (empty on the other ranks). Every rank calls it
/// together.
std::vector<SystemState> gather_rank_states(const SystemState& mine, RankLink& link);

/// The bed of `parts` (every rank's export_state() of one decomposed run, in rank order, or
/// the one state of a single process) as one process holds it: the particles one rank after
/// the other, each pair listed once with its history as its rank listed it (a partner held as
/// a ghost of the rank below becomes that particle; one across the periodic seam, its image),
/// the wall-contact slots, the clock. The open wear window is summed over the ranks and their
/// threads into the layout of one thread (n_threads = 1); the continuation part (what the last
/// rebuild decided) is left out: the merged state is imported, not resumed, and its window
/// added (System::add_wear_window). Throws std::invalid_argument naming the part when the
/// parts do not fit together (ranks missing or out of order, different clocks, a ghost whose
/// particle no rank holds).
SystemState merge_rank_states(const std::vector<SystemState>& parts);

/// True when `s` continues bit for bit (System::resume_state) on rank `rank` of `n_ranks`:
/// written by that rank of that many, with its continuation part.
bool continues_exactly(const SystemState& s, int rank, int n_ranks);

/// The whole bed of every rank's `mine` on every rank: the parts gathered to rank 0, merged
/// there (merge_rank_states) and sent to all. Every rank calls it together.
SystemState whole_state_on_every_rank(const SystemState& mine, RankLink& link);

/// Adds the real particles of `s` to `p` (before System::setup; resume_state or import_state
/// then takes the rest of the state), with their masses, inertias and ids: where the state's
/// last rebuild had them when `own_part` (a rank's part taken back on as many ranks, so that
/// the set-up moves none), else where they are. `density` [kg/m^3] only seeds
/// Particles::add.
void add_state_particles(Particles& p, const SystemState& s, bool own_part, double density);

/// Where gather_particles() puts the particles.
enum class GatherTo {
  every_rank, ///< every rank gets them all (an evaluation every rank makes alike)
  first_rank  ///< rank 0 gets them all, the others none (a snapshot rank 0 writes)
};

/// The real particles of `p` for which `keep(i)` holds (all when `keep` is empty), every
/// rank's in rank order (one process: its own) with position, velocity, spin, radius, mass,
/// id and material; inertias are not carried (Particles::add's of the radius and `density`
/// [kg/m^3]). Every rank calls it together. For evaluations, snapshots and inlets, not the
/// step loop.
Particles gather_particles(const Particles& p, RankLink* link, GatherTo to,
                           const std::function<bool(std::size_t)>& keep = {}, double density = 1);

/// Every rank's bodies on rank 0 in rank order (the others get none; one process: a copy of
/// its own), their members indexed in `gathered`, rank 0's particles of gather_particles()
/// with GatherTo::first_rank. Every rank calls it together. For snapshots.
Clumps gather_clumps(const Clumps& mine, const Particles& gathered, RankLink* link);

} // namespace wear::dem
