// A worn stage file (coupling/output/worn_stage_file.h) reads back as the sample it describes:
// a unit tetrahedron's boundary as the surface, in the file's face order, with its labels,
// roles and removed volumes; a file whose arrays do not fit together is refused naming the
// file and the array; a sample and stage written with write_worn_stage read back the same.
#include "coupling/output/hdf5_file.h"
#include "coupling/output/worn_stage_file.h"
#include "meshes/surface_mesh.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

using namespace wear;

namespace {

// A tetrahedron of edge 1 mm at the origin: the bottom (z = 0) clamped, three base faces.
void write_stage(const std::string& path, const std::vector<double>& removed,
                 const std::vector<int>& triangles) {
  coupling::Hdf5File h5(path);
  h5.write("vertices", std::vector<double>{0, 0, 0, 1e-3, 0, 0, 0, 1e-3, 0, 0, 0, 1e-3}, {4, 3});
  h5.write("tetrahedra", std::vector<std::int64_t>{0, 1, 2, 3}, {1, 4});
  h5.write("triangles", triangles, {triangles.size() / 3, 3});
  h5.write("labels", std::vector<int>{meshes::label::bottom, 3, 3, 3}, {4});
  h5.write("removed_volume", removed, {removed.size()});
  h5.commit();
}

const std::vector<int> boundary{0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2}; // outward

} // namespace

TEST_CASE("a worn stage file reads back as its sample and stage, and a broken one is refused",
          "[worn_stage_file]") {
  const std::string dir =
      (std::filesystem::temp_directory_path() / "worn-stage-file-test").string();
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/stage.h5";

  write_stage(path, {0, 1e-12, 2e-12, 3e-12}, boundary);
  const auto s = coupling::read_worn_stage(path);
  const auto& m = s.state.surface;
  REQUIRE(m.n_faces() == 4);
  CHECK(m.n_vertices() == 4);
  CHECK(s.removed_volume == std::vector<double>{0, 1e-12, 2e-12, 3e-12});
  CHECK(m.face_labels[0] == meshes::label::bottom);
  CHECK(!m.face_wears(0)); // the bottom is clamped
  CHECK(m.face_wears(1));
  // The tetrahedron's volume from the surface: 1/6 mm^3, so the faces are the file's, outward.
  CHECK(meshes::enclosed_volume(m) == Approx(1e-9 / 6).epsilon(1e-12));
  CHECK(s.state.tetrahedra.size() == 4);
  CHECK(s.state.removed_volume == std::vector<double>(4, 0.0)); // no wear accumulated yet

  write_stage(path, {0, 1e-12, 2e-12}, boundary);
  CHECK_THROWS_WITH(coupling::read_worn_stage(path),
                    Catch::Contains(path) && Catch::Contains("removed_volume has 3 entries for 4"));
  auto wrong = boundary;
  wrong[4] = 7;
  write_stage(path, {0, 0, 0, 0}, wrong);
  CHECK_THROWS_WITH(coupling::read_worn_stage(path), Catch::Contains("names vertex 7 of 4"));
  write_stage(path, {0, -1e-12, 0, 0}, boundary);
  CHECK_THROWS_WITH(coupling::read_worn_stage(path), Catch::Contains("negative"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("a worn stage written from a sample's state reads back face for face",
          "[worn_stage_file]") {
  const std::string dir =
      (std::filesystem::temp_directory_path() / "worn-stage-file-write-test").string();
  std::filesystem::create_directories(dir);
  write_stage(dir + "/in.h5", {0, 1e-12, 2e-12, 3e-12}, boundary);
  auto s = coupling::read_worn_stage(dir + "/in.h5");
  // The surface's vertices in another order than the volume's: the writer maps them back.
  auto& m = s.state.surface;
  std::swap(m.vertices[0], m.vertices[3]);
  for (auto& t : m.triangles)
    for (auto& v : t)
      v = v == 0 ? 3 : v == 3 ? 0 : v;
  coupling::write_worn_stage(dir + "/out.h5", s.state, {4e-12, 3e-12, 2e-12, 1e-12});
  const auto back = coupling::read_worn_stage(dir + "/out.h5");
  REQUIRE(back.state.surface.n_faces() == 4);
  CHECK(back.removed_volume == std::vector<double>{4e-12, 3e-12, 2e-12, 1e-12});
  CHECK(back.state.surface.face_labels == m.face_labels);
  for (std::size_t f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k) {
      const auto& a = back.state.surface.vertices[back.state.surface.triangles[f][k]];
      const auto& b = m.vertices[m.triangles[f][k]];
      CHECK((a.x == b.x && a.y == b.y && a.z == b.z));
    }
  CHECK(meshes::enclosed_volume(back.state.surface) == Approx(1e-9 / 6).epsilon(1e-12));
  // A surface vertex that is not a volume vertex is refused, naming the file.
  m.vertices[1].x += 1e-9;
  CHECK_THROWS_WITH(coupling::write_worn_stage(dir + "/bad.h5", s.state, {0, 0, 0, 0}),
                    Catch::Contains("bad.h5") && Catch::Contains("not a vertex of the volume"));
  CHECK(!std::filesystem::exists(dir + "/bad.h5"));
  std::filesystem::remove_all(dir);
}
