// A coupled run's ranks (run_ranks.h). The surfaces are compared by a hash: FNV-1a over the
// bits of the vertices, triangles and labels, split into two 32-bit halves that travel
// exactly as doubles; the largest of (h, -h) over the ranks equals -(smallest) only when every
// rank has the same h.
#include "coupling/loop/run_ranks.h"

#include "dem/engine/rank_states.h"
#include "meshes/atomic_file.h"

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace wear::coupling {

RunRanks::~RunRanks() {
  if (!scratch_.empty()) {
    std::error_code ec; // a folder left behind is no reason to fail
    std::filesystem::remove_all(scratch_, ec);
  }
}

void RunRanks::wait_for_folder() {
  if (!link_)
    return;
  double ready = 1;
  link_->max_over_ranks(&ready, 1);
  if (!writer() && scratch_.empty()) {
    scratch_ = (std::filesystem::temp_directory_path() /
                ("wearsim-" + std::to_string(::getpid()) + "-rank" + std::to_string(link_->rank())))
                   .string();
    meshes::ensure_directory(scratch_);
  }
}

int RunRanks::agreed_signal(const StopSignals& signals) const {
  double v = signals.requested();
  if (link_)
    link_->max_over_ranks(&v, 1);
  return int(v);
}

bool RunRanks::any(bool mine) const {
  double v = mine ? 1 : 0;
  if (link_)
    link_->max_over_ranks(&v, 1);
  return v != 0;
}

void RunRanks::write(const std::string& path, const Checkpoint& c) const {
  if (!link_) {
    write_checkpoint(path, c);
    return;
  }
  const std::vector<dem::SystemState> parts = dem::gather_rank_states(c.dem, *link_);
  if (writer())
    write_checkpoint(path, c, parts);
}

void RunRanks::require_same(const meshes::SurfaceMesh& surface, const std::string& what) const {
  if (!link_)
    return;
  std::uint64_t h = 1469598103934665603ull;
  const auto add = [&h](const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < n; ++k)
      h = (h ^ b[k]) * 1099511628211ull;
  };
  add(surface.vertices.data(), surface.vertices.size() * sizeof(meshes::Vec3));
  add(surface.triangles.data(), surface.triangles.size() * sizeof(surface.triangles[0]));
  add(surface.face_labels.data(), surface.face_labels.size() * sizeof(int));
  const double hi = double(h >> 32), lo = double(h & 0xffffffffull);
  double v[4] = {hi, lo, -hi, -lo};
  link_->max_over_ranks(v, 4);
  if (v[0] != -v[2] || v[1] != -v[3])
    throw std::runtime_error(
        "coupled run over " + std::to_string(link_->n_ranks()) + " ranks: " + what +
        " differ between the ranks (each rank runs the same FEM stage and must get the same "
        "surface bit for bit; a library that is not deterministic, such as gmsh or deal.II with "
        "threads, would do this: run the coupled case as one process)");
}

} // namespace wear::coupling
