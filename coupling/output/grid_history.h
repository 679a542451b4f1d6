#pragma once
// Fields of the sample per stage on a grid of one kind (kind "volume": tetrahedra; kind
// "surface": triangles): <dir>/<kind>/stage_NNNN.h5 and .vtu, and <dir>/<kind>.xdmf, a
// temporal collection over all stages for ParaView. Each stage's files are written once,
// atomically; the XDMF index is rewritten atomically after each stage.
#include "meshes/surface_mesh.h"
#include "meshes/vtu_writer.h"

#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

class GridHistory {
public:
  explicit GridHistory(std::string directory, std::string kind = "volume");

  /// Writes stage `stage` (its mesh may differ from the previous stage's after remeshing).
  void add_stage(int stage, double time, const meshes::VtuGrid& grid);
  /// Lists a stage written before (e.g. by a run now resumed) in the index again.
  void reload_stage(int stage);
  /// The temporal collection of all stages as an XDMF <Grid> (for a combined index).
  void write_collection(std::ostream& out) const;

  std::string xdmf_path() const { return directory_ + "/" + kind_ + ".xdmf"; }
  std::string stage_path(int stage, const std::string& extension) const;

private:
  std::string grid_xml(int stage, double time, const meshes::VtuGrid& grid) const;
  void set_entry(int stage, const std::string& xml);
  void write_xdmf() const;

  std::string directory_, kind_;
  std::vector<std::pair<int, std::string>> entries_; // stage, its XDMF grid
};

/// <directory>/<kind>/stage_NNNN<extension>: where a grid history keeps a stage's file.
std::string grid_stage_path(const std::string& directory, const std::string& kind, int stage,
                            const std::string& extension);

/// Whether a stage file holds its grid (a run continued from a kept checkpoint has stubs for
/// the stages before, holding only their XDMF entry).
bool holds_grid(const std::string& stage_h5);

/// The labelled surface a surface history's stage file holds (RunOutput::add_surface: the
/// cell array "label"); throws naming the file when it holds none.
meshes::SurfaceMesh read_surface_stage(const std::string& stage_h5);

} // namespace wear::coupling
