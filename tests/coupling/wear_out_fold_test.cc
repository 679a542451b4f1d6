// The worn surface on which the convex sample's wear-out stopped (cases/wear-out, engine
// b13327c60d5d): after stage 23 of 43 the next stage folded at face 15745 (label C54) "even in
// increments of 1/32 of the stage", where two worn elements' flanks meet at a sharpened crest.
// tests/data/wear-out/stage23.h5 (extract.py beside it says how it was taken from the run's
// kept checkpoint) holds that surface with its volume mesh and the removed volume per face of
// stage 23, the wear the next stage repeats on the same bed. The worn-geometry evolution must
// apply it: the volume removed exactly (0.1 %), the clamped bottom where it was. The explicit
// recession folds there, and the implicit one takes the rest of the stage ([long]: a stage of
// increments, mesh motions and remeshes of 38,000 tetrahedra, about 4 min). stage10.h5, the
// convex sample after stage 10 of the implicit wear-out, is the surface on which CGAL 5.5's
// tangential relaxation crashed (tests/data/wear-out/README.md).
#include "coupling/output/worn_stage_file.h"
#include "fem/remesher.h"
#include "fem/worn_sample.h"
#include "meshes/fold_mending.h"
#include "meshes/implicit_recession.h"
#include "meshes/mesh_quality.h"
#include "meshes/surface_locator.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

using namespace wear;

namespace {

using WearOutStage = coupling::WornStage;

WearOutStage read_stage(const std::string& file) {
  return coupling::read_worn_stage(std::string(WEAR_SOURCE_DIR) + "/tests/data/wear-out/" + file);
}

WearOutStage read_stage23() {
  return read_stage("stage23.h5");
}

} // namespace

TEST_CASE("the wear-out's stage-24 surface takes the stage's wear without folding, the volume "
          "exact",
          "[fem][wear-out][long]") {
  const WearOutStage data = read_stage23();
  REQUIRE(data.removed_volume.size() == data.state.surface.n_faces());
  fem::WornSampleParameters p;
  p.remesh.sizes.mesh_size = 0.003; // the wear-out case's sizes
  p.remesh.sizes.mesh_size_bottom = 0.005;
  p.remesh.sizes.thickness = 0.01;
  p.remesh.sizes.curvature_refinement = false;
  const std::string dir = std::filesystem::temp_directory_path().string() + "/wear-out-stage24";
  std::filesystem::create_directories(dir);
  p.mesh_directory = dir;
  fem::WornSample sample(data.state, p);
  meshes::FaceField<double> removed("removed volume", "m^3", meshes::Extensivity::extensive,
                                    sample.surface());
  removed.values() = data.removed_volume;
  double asked = 0;
  for (const double v : data.removed_volume)
    asked += v;
  CHECK(asked == Approx(7.701890588e-07).epsilon(1e-9)); // stages.csv: applied_volume_m3

  fem::WearStageReport r;
  REQUIRE_NOTHROW(r = sample.apply_wear(removed));
  INFO("increments " << r.increments << ", spreadings " << r.n_spreadings << ", remeshes "
                     << r.n_remeshes);
  CHECK(r.n_implicit == 1); // the explicit increments fold, the implicit step takes the rest
  CHECK(r.volume_change == Approx(r.removed_volume - r.worn_through_volume).epsilon(1e-3));
  const auto& s = sample.surface();
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    if (s.face_labels[f] == meshes::label::bottom)
      for (const auto v : s.triangles[f])
        CHECK(s.vertices[v].z == 0.0);
  // The faces that do not wear (the holder's sides, the bottom) stay within 0.05 of the 3 mm
  // mesh size of where they were, through the increments, their remeshes and the implicit step
  // (0.052 mm measured; 0.28 mm when the implicit step cut the sides' corners).
  const double off = meshes::farthest_unworn_face(s, data.state.surface).distance;
  INFO("farthest unworn face " << off * 1e3 << " mm");
  CHECK(off < 0.05 * 3e-3);
  std::filesystem::remove_all(dir);
}

namespace {

// The whole stage in one step on the surface the explicit recession folds on: a closed,
// unfolded surface of well-shaped triangles; each label books its asked volume to the
// tolerance, the total exactly; where nothing wears the old surface stays; gmsh keeps the
// triangles and meshes the volume at its first attempt.
struct StageBounds {
  bool per_label = true;        ///< each label books its asked volume to 1e-4
  double unworn = 0.02 * 3e-3;  ///< [m] farthest an unworn face may be from where it was
  double uniform_offset = 1e-6; ///< [m] the offset left to the wearing faces as a whole
  std::size_t folds_left = 0;   ///< folded edges (normals over 120 degrees apart) not mended
};

void check_implicit_stage(const WearOutStage& data, const meshes::ImplicitRecessionParameters& p,
                          const std::string& name, const StageBounds& bounds = {}) {
  const auto& s = data.state.surface;
  const auto r = meshes::implicit_recession(s, data.removed_volume, p);
  INFO("fine faces " << r.n_fine_faces << ", faces " << r.surface.n_faces() << ", nodes "
                     << r.n_nodes << ", " << r.n_iterations << " fields, " << r.seconds
                     << " s, grid loss " << r.grid_loss * 1e9 << " mm^3, restored " << r.n_restored
                     << " vertices, offset " << r.coarsening_loss * 1e9 << " mm^3 (uniform part "
                     << r.uniform_offset * 1e6 << " um), worst face " << r.min_face_quality << ", "
                     << r.n_fragments << " fragments dropped (" << r.fragment_volume * 1e9
                     << " mm^3)");
  for (const int label : r.vanished_labels)
    UNSCOPED_INFO("worn away: " << meshes::label::name(label));
  CHECK(meshes::check_closed(r.surface).closed());
  CHECK(meshes::surface_quality(r.surface).valid());
  // Where the mending leaves no fold, no two faces turn back by more than 120 degrees (the
  // volume mesher refuses 162): the offset folds nothing either.
  INFO(r.n_folds_mended << " folded edges mended, " << r.n_folds_left << " left");
  CHECK(r.n_folds_left <= bounds.folds_left);
  if (r.n_folds_left == 0)
    CHECK(meshes::find_folded_edges(r.surface, -0.5).empty());
  CHECK(r.min_face_quality > 0.1);
  CHECK(r.removed_volume == Approx(r.asked_volume).epsilon(1e-6));
  // The offset gives back chords where they are; what is left for a uniform offset of the
  // wearing faces is below a micrometre.
  CHECK(std::abs(r.uniform_offset) < bounds.uniform_offset);
  for (const auto& [label, asked] : r.asked) {
    INFO(meshes::label::name(label)
         << " asked " << asked * 1e9 << " mm^3, removed " << r.removed.at(label) * 1e9 << " mm^3");
    CHECK((!bounds.per_label || r.removed.at(label) == Approx(asked).epsilon(1e-4)));
  }
  // The faces that do not wear stay on the old surface, within 0.05 of the 3 mm mesh size
  // (the stated tolerance), bit for bit in the bottom's plane. The sharp edges between the
  // holder's sides stay curves wherever the front passed above them, so the corners are not
  // cut either: 0.047 mm measured on stage 24 when the front was tested per grid cell, 0.135
  // mm when only the untouched edges were curves, hence the check at 0.02 of the mesh size.
  const double off = meshes::farthest_unworn_face(r.surface, s).distance;
  for (const auto& x : r.surface.vertices)
    if (std::abs(x.z) < 1e-6)
      CHECK(x.z == 0.0);
  INFO("farthest unworn face " << off * 1e3 << " mm");
  CHECK(off < 0.05 * 3e-3);
  CHECK(off < bounds.unworn);

  fem::RemeshParameters remesh;
  remesh.sizes.mesh_size = 0.003; // the wear-out case's sizes
  remesh.sizes.mesh_size_bottom = 0.005;
  remesh.sizes.thickness = 0.01;
  remesh.sizes.curvature_refinement = false;
  const std::string dir = std::filesystem::temp_directory_path().string() + "/" + name;
  std::filesystem::create_directories(dir);
  fem::RemeshReport report;
  const auto remeshed = fem::remesh_sample(r.surface, remesh, dir + "/sample.msh", &report,
                                           fem::SurfaceKind::isotropic);
  INFO(report.n_tetrahedra << " tetrahedra, worst " << report.min_tet_quality
                           << ", failed: " << report.failed_attempts);
  CHECK(report.attempt == 1);
  CHECK(remeshed.n_faces() == r.surface.n_faces());
  CHECK(report.min_tet_quality > remesh.min_tet_quality);
  std::filesystem::remove_all(dir);
}

// The wear-out study's triangles: 1 mm, coarsened to 3 mm where flat.
meshes::ImplicitRecessionParameters study_triangles() {
  meshes::ImplicitRecessionParameters p;
  p.target_edge = 1e-3;
  p.flat_edge = 3e-3;
  return p;
}

} // namespace

TEST_CASE("the implicit recession takes the wear-out's stage-24 wear whole, without folding, "
          "and the remesher keeps its triangles",
          "[fem][wear-out][long]") {
  check_implicit_stage(read_stage23(), meshes::ImplicitRecessionParameters{}, "stage24-implicit");
}

TEST_CASE("the implicit recession takes the wear-out's stage-11 wear on the study's triangles, "
          "1 mm coarsened to 3 mm where flat, where CGAL's relaxation crashed",
          "[fem][wear-out][long]") {
  // tests/data/wear-out/stage10.h5: the convex sample after stage 10 of the wear-out on the
  // implicit evolution, with stage 10's wear. CGAL 5.5's tangential relaxation ended in a
  // segmentation fault on its zero set (a vertex all of whose faces had become degenerate).
  // C55, the most worn element, is asked 18.1 mm^3 of which its balls take 10.9 at the
  // largest label scale (the base's balls reach its flanks first); the common factor spreads
  // the rest over the other labels (+1 % each), so only the total is exact here. The sides'
  // corners below the worn top are 0.067 mm off (the stated tolerance: 0.15 mm). Of the 23
  // folded edges (normals over 120 degrees apart) the remeshing leaves at the worn elements'
  // feet, 18 are mended; 5 across a foot's label boundary are not, and the offset then leaves
  // 14 (none beyond the volume mesher's 162 degrees; 34 without the mending and the boundary
  // projection).
  StageBounds bounds;
  bounds.per_label = false;
  bounds.unworn = 0.05 * 3e-3;
  bounds.uniform_offset = 2e-6;
  bounds.folds_left = 5;
  check_implicit_stage(read_stage("stage10.h5"), study_triangles(), "stage11-implicit", bounds);
}

TEST_CASE("the implicit recession takes the wear-out's stage-6 wear on both samples, the "
          "folds its remeshing leaves at an element's foot and a worn top's rim mended",
          "[fem][wear-out][long]") {
  // tests/data/wear-out/stage6-{convex,plain}.h5: the samples after stage 5 of the wear-out
  // with stage 6's wear, written by the failed stage. The isotropic remeshing left a face of
  // C12 at its foot turned over against the base (convex) and a vertex of valence 3 on the
  // worn top at its rim with a side, one of whose faces turned down (plain); the first was
  // refused as a fold, the second by gmsh (two facets intersect).
  // The plain sample's wearing faces are left a uniform offset of 1.25 um.
  StageBounds bounds;
  bounds.uniform_offset = 2e-6;
  for (const std::string sample : {"convex", "plain"}) {
    INFO(sample);
    check_implicit_stage(read_stage("stage6-" + sample + ".h5"), study_triangles(),
                         "stage6-" + sample, bounds);
  }
}
