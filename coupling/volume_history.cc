// Per-stage volume output.
//
// stage_NNNN.h5: /points (n x 3) [m], /tetrahedra (m x 4), /point/<name> (n x c),
// /cell/<name> (m x c), with the stage and time as root attributes. Array names keep their
// spaces in XDMF and become underscores in HDF5 paths.
#include "coupling/volume_history.h"

#include "coupling/hdf5_file.h"
#include "meshes/atomic_file.h"

#include <algorithm>
#include <cstdio>
#include <iomanip>

namespace wear::coupling {

namespace {
std::string dataset_name(std::string name) {
  std::replace(name.begin(), name.end(), ' ', '_');
  return name;
}
} // namespace

VolumeHistory::VolumeHistory(std::string directory) : directory_(std::move(directory)) {
  meshes::ensure_directory(directory_ + "/volume");
}

std::string VolumeHistory::stage_path(int stage, const std::string& extension) const {
  char b[32];
  std::snprintf(b, sizeof b, "stage_%04d", stage);
  return directory_ + "/volume/" + b + extension;
}

void VolumeHistory::add_stage(int stage, double time, const meshes::VtuGrid& grid) {
  if (grid.cell_type != meshes::VtkCell::tetra)
    throw std::invalid_argument("volume history: stage " + std::to_string(stage) +
                                " is not a tetrahedral grid");
  meshes::write_vtu(grid, stage_path(stage, ".vtu"));
  Hdf5File h5(stage_path(stage, ".h5"));
  std::vector<double> points;
  points.reserve(3 * grid.points.size());
  for (const auto& p : grid.points) {
    points.push_back(p.x);
    points.push_back(p.y);
    points.push_back(p.z);
  }
  Entry e;
  e.stage = stage;
  e.time = time;
  e.n_points = grid.points.size();
  e.n_cells = grid.connectivity.size() / 4;
  h5.write("/points", points, {e.n_points, 3});
  h5.write("/tetrahedra",
           std::vector<std::int64_t>(grid.connectivity.begin(), grid.connectivity.end()),
           {e.n_cells, 4});
  for (const auto& a : grid.point_data) {
    h5.write("/point/" + dataset_name(a.name), a.values,
             {e.n_points, static_cast<std::size_t>(a.n_components)});
    e.point_arrays.push_back({a.name, a.n_components});
  }
  for (const auto& a : grid.cell_data) {
    h5.write("/cell/" + dataset_name(a.name), a.values,
             {e.n_cells, static_cast<std::size_t>(a.n_components)});
    e.cell_arrays.push_back({a.name, a.n_components});
  }
  h5.attribute("/", "stage", double(stage));
  h5.attribute("/", "time [s]", time);
  h5.commit();
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                [&](const Entry& x) { return x.stage == stage; }),
                 entries_.end());
  entries_.push_back(std::move(e));
  write_xdmf();
}

void VolumeHistory::write_xdmf() const {
  meshes::write_atomically(xdmf_path(), [&](std::ostream& x) {
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n";
    x << "  <Grid Name=\"volume\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& e : entries_) {
      char b[32];
      std::snprintf(b, sizeof b, "volume/stage_%04d.h5", e.stage);
      const std::string file = b;
      const auto item = [&](std::size_t n, int c, const std::string& type, const std::string& p) {
        x << "        <DataItem Dimensions=\"" << n;
        if (c > 1)
          x << " " << c;
        x << "\" NumberType=\"" << type << "\" Precision=\"8\" Format=\"HDF\">" << file << ":" << p
          << "</DataItem>\n";
      };
      const auto attribute = [&](const std::pair<std::string, int>& a, std::size_t n,
                                 const char* centre, const std::string& group) {
        x << "      <Attribute Name=\"" << a.first << "\" AttributeType=\""
          << (a.second == 1 ? "Scalar" : "Vector") << "\" Center=\"" << centre << "\">\n";
        item(n, a.second, "Float", group + dataset_name(a.first));
        x << "      </Attribute>\n";
      };
      x << "    <Grid Name=\"stage_" << e.stage << "\" GridType=\"Uniform\">\n"
        << "      <Time Value=\"" << std::setprecision(10) << e.time << "\"/>\n"
        << "      <Topology TopologyType=\"Tetrahedron\" NumberOfElements=\"" << e.n_cells
        << "\">\n";
      item(e.n_cells, 4, "Int", "/tetrahedra");
      x << "      </Topology>\n      <Geometry GeometryType=\"XYZ\">\n";
      item(e.n_points, 3, "Float", "/points");
      x << "      </Geometry>\n";
      for (const auto& a : e.point_arrays)
        attribute(a, e.n_points, "Node", "/point/");
      for (const auto& a : e.cell_arrays)
        attribute(a, e.n_cells, "Cell", "/cell/");
      x << "    </Grid>\n";
    }
    x << "  </Grid>\n</Domain>\n</Xdmf>\n";
  });
}

} // namespace wear::coupling
