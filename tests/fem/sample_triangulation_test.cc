#include "fem/sample_triangulation.h"
#include "meshes/sample_generator.h"

#include <catch2/catch.hpp>

#include <deal.II/grid/tria.h>

#include <fstream>

using namespace wear;

TEST_CASE("deal.II reads the sample mesh with boundary ids = labels", "[fem]") {
  meshes::SampleGeometry s;
  s.mesh_size = 2e-3;
  const auto g = meshes::generate_sample(s, "fem_convex_2mm.msh");
  dealii::Triangulation<3> tria;
  fem::read_sample_mesh("fem_convex_2mm.msh", tria);
  CHECK(tria.n_active_cells() == g.n_tetrahedra);
  // Same tetrahedra, same volume; boundary areas per id equal the surface areas per label.
  CHECK(std::abs(fem::mesh_volume(tria) / meshes::enclosed_volume(g.surface) - 1) < 1e-9);
  const auto a_fem = fem::boundary_area(tria);
  const auto a_surf = meshes::area_per_label(g.surface);
  REQUIRE(a_fem.size() == a_surf.size());
  for (const auto& [id, a] : a_surf) {
    INFO(meshes::label::name(id));
    CHECK(a_fem.at(id) == Approx(a).epsilon(1e-9));
  }
}

TEST_CASE("bad sample meshes fail with a message", "[fem]") {
  dealii::Triangulation<3> tria;
  CHECK_THROWS_WITH(fem::read_sample_mesh("nope.msh", tria), Catch::Contains("nope.msh"));
  {
    std::ofstream o("garbage.msh");
    o << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\nthis is not a mesh\n";
  }
  dealii::Triangulation<3> t2;
  CHECK_THROWS_WITH(fem::read_sample_mesh("garbage.msh", t2), Catch::Contains("garbage.msh"));
}
