// Per-stage volume output: each stage's HDF5 file holds the grid and fields as written (read
// back through the HDF5 C API), the XDMF index lists every stage, a VTU is beside each.
#include "coupling/output/grid_history.h"

#include <catch2/catch.hpp>

#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace wear;

namespace {
std::vector<double> read_dataset(const std::string& file, const std::string& name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(f >= 0);
  const hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
  REQUIRE(d >= 0);
  const hid_t space = H5Dget_space(d);
  std::vector<double> out(H5Sget_simple_extent_npoints(space));
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  return out;
}
} // namespace

TEST_CASE("grid history: stages in HDF5 with an XDMF index and VTU files, reloadable",
          "[coupling][output]") {
  const std::string dir = "grid_history_test";
  std::filesystem::remove_all(dir);
  meshes::VtuGrid g;
  g.cell_type = meshes::VtkCell::tetra;
  g.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  g.connectivity = {0, 1, 2, 3, 1, 2, 3, 4};
  g.point_data.push_back({"displacement", 3, std::vector<double>(15, 0.5)});
  g.cell_data.push_back({"von Mises", 1, {1e5, 2e5}});
  coupling::GridHistory history(dir);
  history.add_stage(0, 0.0, g);
  g.cell_data[0].values = {3e5, 4e5};
  history.add_stage(1, 4.0, g);
  CHECK(read_dataset(history.stage_path(1, ".h5"), "/cell/von_Mises") ==
        std::vector<double>{3e5, 4e5});
  CHECK(read_dataset(history.stage_path(0, ".h5"), "/cell/von_Mises") ==
        std::vector<double>{1e5, 2e5});
  CHECK(read_dataset(history.stage_path(0, ".h5"), "/points").size() == 15);
  CHECK(std::filesystem::exists(history.stage_path(1, ".vtu")));
  std::ifstream in(history.xdmf_path());
  std::stringstream text;
  text << in.rdbuf();
  CHECK(text.str().find("stage_0000.h5:/tetrahedra") != std::string::npos);
  CHECK(text.str().find("stage_0001.h5:/cell/von_Mises") != std::string::npos);
  CHECK(text.str().find("<Time Value=\"4\"/>") != std::string::npos);
  // A resumed run lists the stages written before from the files alone: same index.
  {
    coupling::GridHistory again(dir);
    again.reload_stage(0);
    again.reload_stage(1);
    std::ifstream in2(again.xdmf_path());
    std::stringstream text2;
    text2 << in2.rdbuf();
    CHECK(text2.str() == text.str());
  }
  // A surface history holds triangles.
  meshes::VtuGrid t;
  t.cell_type = meshes::VtkCell::triangle;
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  t.connectivity = {0, 1, 2};
  t.cell_data.push_back({"wear depth", 1, {1e-6}});
  coupling::GridHistory surface(dir, "surface");
  surface.add_stage(3, 1.0, t);
  CHECK(read_dataset(surface.stage_path(3, ".h5"), "/cell/wear_depth") ==
        std::vector<double>{1e-6});
  std::ifstream in3(surface.xdmf_path());
  std::stringstream text3;
  text3 << in3.rdbuf();
  CHECK(text3.str().find("TopologyType=\"Triangle\"") != std::string::npos);
  CHECK(text3.str().find("surface/stage_0003.h5:/triangles") != std::string::npos);
  // A grid of points is refused.
  t.cell_type = meshes::VtkCell::vertex;
  CHECK_THROWS_WITH(surface.add_stage(4, 2.0, t),
                    Catch::Contains("neither a tetrahedral nor a triangle grid"));
}
