// Per-stage grid output (volume or surface of the sample).
//
// stage_NNNN.h5: /points (n x 3) [m], /tetrahedra (m x 4) or /triangles (m x 3), /point/<name> (n x
// c), /cell/<name> (m x c), with the stage, the time and the stage's XDMF grid (text, so the index
// can be rebuilt from the files when a run resumes) as root attributes. Array names keep their
// spaces in XDMF and become underscores in HDF5 paths.
#include "coupling/output/grid_history.h"

#include "coupling/output/hdf5_file.h"
#include "meshes/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace wear::coupling {

namespace {
std::string dataset_name(std::string name) {
  std::replace(name.begin(), name.end(), ' ', '_');
  return name;
}
} // namespace

GridHistory::GridHistory(std::string directory, std::string kind)
    : directory_(std::move(directory)), kind_(std::move(kind)) {
  meshes::ensure_directory(directory_ + "/" + kind_);
}

std::string grid_stage_path(const std::string& directory, const std::string& kind, int stage,
                            const std::string& extension) {
  char b[32];
  std::snprintf(b, sizeof b, "stage_%04d", stage);
  return directory + "/" + kind + "/" + b + extension;
}

std::string GridHistory::stage_path(int stage, const std::string& extension) const {
  return grid_stage_path(directory_, kind_, stage, extension);
}

std::string GridHistory::grid_xml(int stage, double time, const meshes::VtuGrid& grid) const {
  char b[32];
  std::snprintf(b, sizeof b, "/stage_%04d.h5", stage);
  const std::string file = kind_ + b;
  const bool tetra = grid.cell_type == meshes::VtkCell::tetra;
  const int per_cell = tetra ? 4 : 3;
  const std::size_t n_points = grid.points.size(), n_cells = grid.connectivity.size() / per_cell;
  std::ostringstream x;
  const auto item = [&](std::size_t n, int c, const std::string& type, const std::string& p) {
    x << "        <DataItem Dimensions=\"" << n;
    if (c > 1)
      x << " " << c;
    x << "\" NumberType=\"" << type << "\" Precision=\"8\" Format=\"HDF\">" << file << ":" << p
      << "</DataItem>\n";
  };
  const auto attribute = [&](const meshes::VtuArray& a, std::size_t n, const char* centre,
                             const std::string& group) {
    x << "      <Attribute Name=\"" << a.name << "\" AttributeType=\""
      << (a.n_components == 1 ? "Scalar" : "Vector") << "\" Center=\"" << centre << "\">\n";
    item(n, a.n_components, "Float", group + dataset_name(a.name));
    x << "      </Attribute>\n";
  };
  x << "    <Grid Name=\"" << kind_ << "_" << stage << "\" GridType=\"Uniform\">\n"
    << "      <Time Value=\"" << std::setprecision(10) << time << "\"/>\n"
    << "      <Topology TopologyType=\"" << (tetra ? "Tetrahedron" : "Triangle")
    << "\" NumberOfElements=\"" << n_cells << "\">\n";
  item(n_cells, per_cell, "Int", tetra ? "/tetrahedra" : "/triangles");
  x << "      </Topology>\n      <Geometry GeometryType=\"XYZ\">\n";
  item(n_points, 3, "Float", "/points");
  x << "      </Geometry>\n";
  for (const auto& a : grid.point_data)
    attribute(a, n_points, "Node", "/point/");
  for (const auto& a : grid.cell_data)
    attribute(a, n_cells, "Cell", "/cell/");
  x << "    </Grid>\n";
  return x.str();
}

void GridHistory::add_stage(int stage, double time, const meshes::VtuGrid& grid) {
  const bool tetra = grid.cell_type == meshes::VtkCell::tetra;
  if (!tetra && grid.cell_type != meshes::VtkCell::triangle)
    throw std::invalid_argument(kind_ + " history: stage " + std::to_string(stage) +
                                " is neither a tetrahedral nor a triangle grid");
  meshes::write_vtu(grid, stage_path(stage, ".vtu"));
  Hdf5File h5(stage_path(stage, ".h5"));
  std::vector<double> points;
  points.reserve(3 * grid.points.size());
  for (const auto& p : grid.points) {
    points.push_back(p.x);
    points.push_back(p.y);
    points.push_back(p.z);
  }
  const std::size_t per_cell = tetra ? 4 : 3;
  const std::size_t n_points = grid.points.size(), n_cells = grid.connectivity.size() / per_cell;
  h5.write("/points", points, {n_points, 3});
  h5.write(tetra ? "/tetrahedra" : "/triangles",
           std::vector<std::int64_t>(grid.connectivity.begin(), grid.connectivity.end()),
           {n_cells, per_cell});
  for (const auto& a : grid.point_data)
    h5.write("/point/" + dataset_name(a.name), a.values,
             {n_points, static_cast<std::size_t>(a.n_components)});
  for (const auto& a : grid.cell_data)
    h5.write("/cell/" + dataset_name(a.name), a.values,
             {n_cells, static_cast<std::size_t>(a.n_components)});
  const std::string xml = grid_xml(stage, time, grid);
  h5.attribute("/", "stage", double(stage));
  h5.attribute("/", "time [s]", time);
  h5.attribute("/", "xdmf", xml);
  h5.commit();
  set_entry(stage, xml);
}

bool holds_grid(const std::string& stage_h5) {
  return Hdf5Reader(stage_h5).has_object("/points");
}

meshes::SurfaceMesh read_surface_stage(const std::string& stage_h5) {
  const Hdf5Reader h5(stage_h5);
  if (!h5.has_object("/triangles") || !h5.has_object("/cell/label"))
    throw std::runtime_error(stage_h5 + ": no labelled surface (/triangles, /cell/label)");
  const auto points = h5.doubles("/points");
  const auto triangles = h5.int64s("/triangles");
  const auto labels = h5.doubles("/cell/label");
  if (points.size() % 3 || triangles.size() != 3 * labels.size())
    throw std::runtime_error(stage_h5 + ": " + std::to_string(points.size()) + " coordinates, " +
                             std::to_string(triangles.size()) + " triangle corners and " +
                             std::to_string(labels.size()) + " labels do not make a surface");
  meshes::SurfaceMesh m;
  for (std::size_t i = 0; i < points.size(); i += 3)
    m.vertices.push_back({points[i], points[i + 1], points[i + 2]});
  for (std::size_t f = 0; f < labels.size(); ++f) {
    meshes::Triangle t;
    for (std::size_t k = 0; k < 3; ++k) {
      const auto v = triangles[3 * f + k];
      if (v < 0 || std::size_t(v) >= m.vertices.size())
        throw std::runtime_error(stage_h5 + ": triangle " + std::to_string(f) + " names vertex " +
                                 std::to_string(v) + " of " + std::to_string(m.vertices.size()));
      t[k] = std::uint32_t(v);
    }
    m.triangles.push_back(t);
    m.face_labels.push_back(int(std::lround(labels[f])));
  }
  return m;
}

void GridHistory::reload_stage(int stage) {
  const Hdf5Reader h5(stage_path(stage, ".h5"));
  set_entry(stage, h5.text_attribute("/", "xdmf"));
}

void GridHistory::set_entry(int stage, const std::string& xml) {
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                [&](const auto& x) { return x.first == stage; }),
                 entries_.end());
  entries_.emplace_back(stage, xml);
  write_xdmf();
}

void GridHistory::write_xdmf() const {
  meshes::write_atomically(xdmf_path(), [&](std::ostream& x) {
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n";
    write_collection(x);
    x << "</Domain>\n</Xdmf>\n";
  });
}

void GridHistory::write_collection(std::ostream& x) const {
  x << "  <Grid Name=\"" << kind_ << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& e : entries_)
    x << e.second;
  x << "  </Grid>\n";
}

} // namespace wear::coupling
