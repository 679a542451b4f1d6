#pragma once
// Volume fields of the sample per stage: <dir>/volume/stage_NNNN.h5 and .vtu, and
// <dir>/volume.xdmf, a temporal collection over all stages for ParaView. Each stage's files
// are written once, atomically; the XDMF index is rewritten atomically after each stage.
#include "meshes/vtu_writer.h"

#include <string>
#include <vector>

namespace wear::coupling {

class VolumeHistory {
public:
  explicit VolumeHistory(std::string directory);

  /// Writes stage `stage` (its mesh may differ from the previous stage's after remeshing).
  void add_stage(int stage, double time, const meshes::VtuGrid& grid);

  std::string xdmf_path() const { return directory_ + "/volume.xdmf"; }
  std::string stage_path(int stage, const std::string& extension) const;

private:
  struct Entry {
    int stage = 0;
    double time = 0;
    std::size_t n_points = 0, n_cells = 0;
    std::vector<std::pair<std::string, int>> point_arrays, cell_arrays; // name, components
  };
  void write_xdmf() const;

  std::string directory_;
  std::vector<Entry> entries_;
};

} // namespace wear::coupling
