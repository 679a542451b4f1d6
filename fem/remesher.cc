// Remeshing of the worn sample from its boundary triangulation with gmsh 4.8.
//
// Route (verified in shared/notes/toolchain.md): the worn triangles go into gmsh as discrete
// surfaces, one per label, with the label boundaries as line elements of a discrete curve
// (classifySurfaces keeps existing 1D elements as edges, not the surfaces' split);
// `classifySurfaces` splits them further where the normal turns by more than the feature angle and
// into patches that a single map can parametrise; `createGeometry` builds that parametrisation; a
// surface loop and a volume close the model; `generate(3)` remeshes surfaces and volume with the
// sample's size field. New surface nodes lie on the old piecewise-linear surface, so the new
// surface differs from the old only by chords across curved regions (second order in the mesh
// size). Each patch takes the label that most of its input triangles carry; with label-aligned
// input every patch is pure, and a mixed patch is reported. An attempt is refused (and the next
// one tried) when a tetrahedron is nearly flat, the new boundary is open or folds, or the
// volume or a label's area changes by more than the chords can explain.
//
// Why first attempts failed (issue 34: 2 of 4 staged remeshes of the quick convex case refused,
// "Invalid boundary mesh (overlapping facets)" on the base, or a tetrahedron of quality 7.7e-5):
// createGeometry parametrises a patch by projection onto its least-squares plane only when it
// is planar to Geometry.MatchMeshTolerance (1e-8) x its diagonal; any other patch gets a
// mean-value (harmonic) map onto the unit disk that pins its longest boundary loop and leaves
// every other loop free. For a disk that map cannot fold; for a patch with holes it can. The
// worn base top is such a patch: a plate with the 23 element footprints as holes, no longer
// planar once worn (0.5 to 2.3 um per mm of diagonal in the quick case), so the free
// footprint loops folded in the parameter plane, and the triangles gmsh built there folded
// onto each other beside a footprint (two facets at 0.06 deg) or came out nearly flat (the
// slivers). Every attempt classified the same patch, so the larger feature angle and Delaunay
// failed alike, until only keeping the worn triangles was left. A worn element whose sharpened
// tip splits off at the feature angle leaves a second kind: a ring around the tip.
// Fix (classify_mappable): a patch with holes that is a graph over its plane (the worn base)
// is projected, gmsh's planarity tolerance raised to cover it; one that is not, with at most
// two holes (the rings), is cut open (fem/discrete_patches.h) and classified again. Over 79
// worn surfaces that runs handed to the remesher (quick convex 17, of which the 2 refused
// inputs of the run; quick plain 19; deformation-like at 1 mm 14; the first 14 stages
// of the wear-out case 29) the first attempt now succeeds on 73 (was 57 in the runs); it fails
// where a worn tip is crumpled (faces turning by over 90 deg within 0.5 mm), and on the base
// late in the wear-out case, which overhangs at its leading edge and keeps the harmonic map.
// An attempt also takes a third of the time: see set_size_field.
#include "fem/remesher.h"

#include "fem/discrete_patches.h"
#include "meshes/constants.h"
#include "meshes/gmsh_session.h"
#include "meshes/mesh_quality.h"
#include "meshes/planar_flip.h"
#include "meshes/sample_generator.h"
#include "meshes/stopwatch.h"
#include "meshes/surface_locator.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

namespace wear::fem {

namespace {

// Adds the triangles of `worn` as one discrete surface per label; element tag = face + 1.
// Returns the label of each surface entity.
std::map<int, int> add_discrete_surfaces(const meshes::SurfaceMesh& worn) {
  std::map<int, int> label_of;
  const auto labels = worn.labels();
  std::vector<std::size_t> node_tags(worn.n_vertices());
  std::vector<double> coords(3 * worn.n_vertices());
  for (std::size_t v = 0; v < worn.n_vertices(); ++v) {
    node_tags[v] = v + 1;
    coords[3 * v] = worn.vertices[v].x;
    coords[3 * v + 1] = worn.vertices[v].y;
    coords[3 * v + 2] = worn.vertices[v].z;
  }
  for (std::size_t l = 0; l < labels.size(); ++l) {
    const int tag = static_cast<int>(l) + 1;
    gmsh::model::addDiscreteEntity(2, tag);
    label_of[tag] = labels[l];
    if (l == 0)
      gmsh::model::mesh::addNodes(2, tag, node_tags, coords);
    std::vector<std::size_t> elements, nodes;
    for (std::size_t f = 0; f < worn.n_faces(); ++f)
      if (worn.face_labels[f] == labels[l]) {
        elements.push_back(f + 1);
        for (const auto v : worn.triangles[f])
          nodes.push_back(v + 1);
      }
    gmsh::model::mesh::addElementsByType(tag, 2, elements, nodes);
  }
  return label_of;
}

// The edges between faces of different labels as one discrete curve of line elements.
// classifySurfaces regroups all triangles by the feature angle alone, across the discrete
// surfaces they came in, and only existing 1D elements stop it: without them, a wear face
// rounded into a side below the feature angle joins the side's patch (707 to 2,428 faces
// in the staged deformation run, every such remesh fell back to keeping the surface).
// `cuts` (fem/discrete_patches.h) join them, so that the patches they split off carry no hole.
void add_label_boundaries(const meshes::SurfaceMesh& worn, const std::vector<Edge>& cuts) {
  std::vector<std::size_t> lines, nodes;
  const auto add = [&](std::uint32_t a, std::uint32_t b) {
    lines.push_back(worn.n_faces() + lines.size() + 1); // element tags follow the faces'
    nodes.push_back(a + 1);
    nodes.push_back(b + 1);
  };
  for (const auto& [edge, faces] : meshes::edge_faces(worn))
    if (faces.size() == 2 && worn.face_labels[faces[0]] != worn.face_labels[faces[1]])
      add(edge.first, edge.second);
  for (const auto& [a, b] : cuts)
    add(a, b);
  const int tag = 1;
  gmsh::model::addDiscreteEntity(1, tag);
  gmsh::model::mesh::addElementsByType(tag, 1, lines, nodes);
}

} // namespace

void write_surface_msh(const meshes::SurfaceMesh& m, const std::string& path) {
  meshes::GmshSession session("surface");
  for (const auto& [tag, label] : add_discrete_surfaces(m)) {
    gmsh::model::addPhysicalGroup(2, {tag}, label);
    gmsh::model::setPhysicalName(2, label, meshes::label::name(label));
  }
  meshes::gmsh_write_msh(path);
}

namespace {

// Background size: the smaller of the sample's graded size field and a chord-tolerance
// size from the curvature of the input surface, h_v = sqrt(8 delta / kappa_v) (the sagitta
// of a chord h on a circle of curvature kappa is kappa h^2 / 8), kappa_v the largest
// curvature across the smooth edges at v, kappa_e = (angle between the two face normals) /
// (distance between the face centroids). Edges sharper than the feature angle and label
// boundaries become curves of the new model and are left out. This depends on the geometry
// only, not on the input triangles' size, so repeated remeshing does not drift (gmsh's own
// curvature sizing on discrete curves took 38 s of 45 at 1.5 mm).
void set_size_field(const meshes::SurfaceMesh& worn, const RemeshParameters& p) {
  const auto normal = meshes::face_normals(worn);
  const auto centroid = meshes::face_centroids(worn);
  const double cos_feature = std::cos(p.feature_angle_deg * pi / 180);
  std::vector<double> kappa(worn.n_vertices(), 0);
  for (const auto& [edge, faces] : meshes::edge_faces(worn)) {
    if (faces.size() != 2 || worn.face_labels[faces[0]] != worn.face_labels[faces[1]])
      continue;
    const double c = meshes::dot(normal[faces[0]], normal[faces[1]]);
    if (c < cos_feature)
      continue;
    const double k =
        std::acos(std::min(1.0, c)) / meshes::norm(centroid[faces[0]] - centroid[faces[1]]);
    kappa[edge.first] = std::max(kappa[edge.first], k);
    kappa[edge.second] = std::max(kappa[edge.second], k);
  }
  std::vector<double> data;
  data.reserve(12 * worn.n_faces());
  for (const auto& t : worn.triangles) {
    for (int d = 0; d < 3; ++d)
      for (const auto v : t)
        data.push_back(worn.vertices[v][d]);
    for (const auto v : t)
      data.push_back(kappa[v] > 0 ? std::sqrt(8 * p.chord_tolerance / kappa[v])
                                  : p.sizes.mesh_size_bottom);
  }
  const int view = gmsh::view::add("chord size");
  gmsh::view::addListData(view, "ST", static_cast<int>(worn.n_faces()), data);
  const int graded = meshes::set_sample_size_field(p.sizes, p.up, p.up_offset);
  const int local = gmsh::model::mesh::field::add("PostView");
  gmsh::model::mesh::field::setNumber(local, "ViewTag", view);
  const int both = gmsh::model::mesh::field::add("Min");
  gmsh::model::mesh::field::setNumbers(both, "FieldsList", {double(graded), double(local)});
  gmsh::model::mesh::field::setAsBackgroundMesh(both);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  // gmsh places the nodes of a curve by integrating 1 / size along it, to 1e-9 by default:
  // on this piecewise-linear field that took 5.4 of the 6.5 s of an attempt in the quick
  // case; to 1e-4 (0.05 s) a node moves by less than a thousandth of an edge.
  gmsh::option::setNumber("Mesh.LcIntegrationPrecision", 1e-4);
}

// Label of each classified patch: the label most of its input triangles carry.
std::map<int, int> patch_labels(const meshes::SurfaceMesh& worn, std::size_t* n_mixed) {
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::map<int, int> label_of;
  *n_mixed = 0;
  for (const auto& [dim, tag] : surfaces) {
    std::vector<std::size_t> elements, nodes;
    gmsh::model::mesh::getElementsByType(2, elements, nodes, tag);
    std::map<int, std::size_t> votes;
    for (const auto e : elements)
      if (e >= 1 && e <= worn.n_faces())
        ++votes[worn.face_labels[e - 1]];
    if (votes.empty())
      throw std::runtime_error("remeshing: gmsh patch " + std::to_string(tag) +
                               " holds none of the worn surface's triangles");
    std::size_t best = 0, total = 0;
    for (const auto& [label, n] : votes) {
      total += n;
      if (n > best) {
        best = n;
        label_of[tag] = label;
      }
    }
    *n_mixed += total - best;
  }
  return label_of;
}
constexpr int keep_surface = 0; // attempt that keeps the input triangles, meshing the volume only
// Quality below which a tetrahedron counts as flat: the floor of the keep_surface attempt,
// which has no other attempt to fall back to.
constexpr double flat_tet_quality = 1e-8;

// One way to mesh the volume: gmsh's 2D algorithm (or keep_surface), the feature angle of the
// classification, and the quality below which a tetrahedron refuses the attempt.
struct Attempt {
  int algorithm;
  double feature_angle_deg; ///< [deg]
  double tet_floor;         ///< [-]
};

// The input faces of each patch gmsh classified (element tag = face + 1), by patch tag.
std::map<int, std::vector<std::uint32_t>> patch_faces(const meshes::SurfaceMesh& worn) {
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::map<int, std::vector<std::uint32_t>> faces;
  for (const auto& [dim, tag] : surfaces) {
    std::vector<std::size_t> elements, nodes;
    gmsh::model::mesh::getElementsByType(2, elements, nodes, tag);
    auto& list = faces[tag];
    for (const auto e : elements)
      if (e >= 1 && e <= worn.n_faces())
        list.push_back(static_cast<std::uint32_t>(e - 1));
  }
  return faces;
}

// A patch with holes whose face normals all lie within 84 deg of its plane's normal is mapped
// by projection: below 90 deg it cannot fold (the worn base of the wear-out case reached
// 82 deg at its leading edge and was meshed so).
constexpr double graph_normal_cos = 0.1;
// gmsh's planarity tolerance is set this factor above the largest relative deviation of a
// patch to project, and must stay this factor below that of every patch that would fold.
constexpr double planarity_margin = 1.5;

// A patch with holes that projection could fold is cut open when it has at most this many
// boundary loops (a ring around a split-off tip: 2). Cut into strips, the base with its 23
// footprints meshed worse than uncut: 8 first attempts of 21 succeeded.
constexpr int max_loops_to_cut = 3;

// The largest relative deviation of the patches with holes that project (0: none), the
// smallest of the patches that must not project, and the cuts that open the holes of those
// patches with few holes that cannot project.
struct HolePlan {
  double project_deviation = 0;
  double fold_deviation = std::numeric_limits<double>::infinity();
  std::vector<Edge> cuts;
  bool projection_safe() const {
    return planarity_margin * planarity_margin * project_deviation < fold_deviation;
  }
};

HolePlan plan_holes(const meshes::SurfaceMesh& worn) {
  HolePlan plan;
  for (const auto& [tag, faces] : patch_faces(worn)) {
    const PatchShape shape = patch_shape(worn, faces);
    const bool graph = shape.min_normal_cos > graph_normal_cos;
    if (!graph)
      plan.fold_deviation = std::min(plan.fold_deviation, shape.relative_deviation);
    if (shape.n_loops < 2)
      continue;
    if (graph) {
      plan.project_deviation = std::max(plan.project_deviation, shape.relative_deviation);
    } else if (shape.n_loops <= max_loops_to_cut) {
      const auto cuts = hole_cuts(worn, faces);
      plan.cuts.insert(plan.cuts.end(), cuts.begin(), cuts.end());
    }
  }
  return plan;
}

void classify(const meshes::SurfaceMesh& worn, double feature_angle_deg,
              const std::vector<Edge>& cuts) {
  std::vector<Edge> curves = cuts;
  add_label_boundaries(worn, curves);
  gmsh::model::mesh::classifySurfaces(feature_angle_deg * pi / 180, true, true, pi);
}

// Classifies the input so that the patches gmsh reparametrises map without folding. gmsh
// maps a patch with holes harmonically with the holes' loops free, and those fold; so a
// patch with holes is projected onto its plane when it is a graph over it (gmsh projects a
// patch that lies within Geometry.MatchMeshTolerance x its diagonal of the plane: the
// tolerance is raised to cover them, when every patch it would also cover is a graph over
// its plane), or else, with few holes, cut open and classified again. A patch with many
// holes that is no graph (the base late in the wear-out case) is left to the harmonic map.
void classify_mappable(const meshes::SurfaceMesh& worn, double feature_angle_deg, RemeshReport& r) {
  classify(worn, feature_angle_deg, {});
  HolePlan plan = plan_holes(worn);
  r.n_cut_edges = plan.cuts.size();
  if (!plan.cuts.empty()) {
    gmsh::clear();
    add_discrete_surfaces(worn);
    classify(worn, feature_angle_deg, plan.cuts);
    plan = plan_holes(worn); // the pieces are new patches
  }
  if (plan.project_deviation > 0 && plan.projection_safe()) {
    r.planarity_tolerance = planarity_margin * plan.project_deviation;
    gmsh::option::setNumber("Geometry.MatchMeshTolerance", r.planarity_tolerance);
  }
}

// The patches gmsh splits the input into (at the label boundaries, at feature edges, at
// the cuts that open holes, and where one map cannot parametrise them), with their
// parametrisation; returns the label of each patch. Refuses (throws) a classification that
// loses a label or mixes labels in a patch.
std::map<int, int> classify_patches(const meshes::SurfaceMesh& worn, double feature_angle_deg,
                                    RemeshReport& r) {
  classify_mappable(worn, feature_angle_deg, r);
  auto label_of = patch_labels(worn, &r.n_mixed_faces);
  // A small worn region can end up inside a neighbour's patch and lose its label in the
  // vote; fail this attempt so the next one (finally: keep the worn triangles) is tried.
  std::set<int> kept;
  for (const auto& [tag, label] : label_of)
    kept.insert(label);
  for (const int label : worn.labels())
    if (!kept.count(label))
      throw std::runtime_error("no patch kept label '" + meshes::label::name(label) + "'");
  // Where wear has rounded the edge between the wear face and a side below the feature
  // angle, gmsh joins them into one patch, and the vote would relabel a whole side as
  // wearing down to the clamped bottom: refuse, so the next attempt is tried.
  if (r.n_mixed_faces > 0)
    throw std::runtime_error(std::to_string(r.n_mixed_faces) +
                             " input faces fell into a patch of another label");
  gmsh::model::mesh::createGeometry();
  return label_of;
}

// The volume enclosed by the surface entities, and one physical group per label (patches
// labelled by `label_of`) and for the volume, as generate_sample writes them.
void add_volume(const std::map<int, int>& label_of, RemeshReport& r) {
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::vector<int> tags;
  std::map<int, std::vector<int>> by_label;
  for (const auto& [dim, tag] : surfaces) {
    tags.push_back(tag);
    by_label[label_of.at(tag)].push_back(tag);
  }
  r.n_patches = tags.size();
  const int loop = gmsh::model::geo::addSurfaceLoop(tags);
  const int volume = gmsh::model::geo::addVolume({loop});
  gmsh::model::geo::synchronize();
  for (const auto& [label, group] : by_label) {
    gmsh::model::addPhysicalGroup(2, group, label);
    gmsh::model::setPhysicalName(2, label, meshes::label::name(label));
  }
  gmsh::model::addPhysicalGroup(3, {volume}, 1);
  gmsh::model::setPhysicalName(3, 1, "sample");
}

// Refuses (throws) a new mesh with a tetrahedron of quality at most `lowest`, an open or
// folding boundary, or a volume or label area that changed by more than the chords explain.
// Fills r.area_after.
void check_new_mesh(const meshes::SurfaceMesh& remeshed, double lowest, RemeshReport& r) {
  if (r.n_tetrahedra == 0)
    throw std::runtime_error("gmsh produced no tetrahedra");
  if (!(r.min_tet_quality > lowest)) {
    std::ostringstream m;
    m << std::setprecision(3) << "gmsh left a tetrahedron of quality " << r.min_tet_quality
      << ", below " << lowest;
    throw std::runtime_error(m.str());
  }
  // gmsh can leave a patch it failed on partly meshed and still fill the volume: only a
  // closed boundary that encloses the worn volume is accepted.
  const auto closed = meshes::check_closed(remeshed);
  if (!closed.closed())
    throw std::runtime_error("the new boundary is not closed (" +
                             std::to_string(closed.n_boundary_edges) + " open edges)");
  // gmsh meshes each patch on its own parametrisation: where a worn-off element leaves a low
  // remnant beside the base, a new triangle on one side of their common curve can lie folded
  // onto the other (seen at 50x: cos -0.952 across a C12-base edge). Every increment after it
  // starts from a folded surface, so such a surface is refused like a bad tetrahedron.
  const auto quality = meshes::surface_quality(remeshed);
  if (!quality.valid()) {
    std::ostringstream where;
    if (!quality.bad_faces.empty()) {
      const auto f = quality.bad_faces.front();
      const auto c = meshes::face_centroids(remeshed)[f];
      where << std::setprecision(4) << ", the first at (" << c.x * 1e3 << ", " << c.y * 1e3 << ", "
            << c.z * 1e3 << ") mm, label " << meshes::label::name(remeshed.face_labels[f]);
    }
    throw std::runtime_error("the new surface folds (" + std::to_string(quality.n_folded_edges) +
                             " folded edges, " + std::to_string(quality.n_self_intersections) +
                             " crossing face pairs, " + std::to_string(quality.n_degenerate) +
                             " degenerate faces" + where.str() + ")");
  }
  if (std::abs(r.volume_after / r.volume_before - 1) > 0.01)
    throw std::runtime_error("the new mesh's volume differs from the worn one by " +
                             std::to_string(100 * (r.volume_after / r.volume_before - 1)) + " %");
  // Each label keeps its area within 5 % (the chords across a small, sharply worn element
  // change it by a few per cent; a side relabelled as wear face loses a quarter): a check on the
  // labels that does not depend on how gmsh split the patches.
  r.area_after = meshes::area_per_label(remeshed);
  for (const auto& [label, area] : r.area_before) {
    const auto it = r.area_after.find(label);
    const double after = it == r.area_after.end() ? 0.0 : it->second;
    if (std::abs(after - area) > 0.05 * area)
      throw std::runtime_error("label '" + meshes::label::name(label) + "' changed its area from " +
                               std::to_string(area * 1e6) + " to " + std::to_string(after * 1e6) +
                               " mm^2");
  }
}

// One attempt: the discrete model, its parametrisation and the volume mesh with the given
// 2D algorithm, written to msh_path. Fills the patch and mesh counts of r.
meshes::SurfaceMesh mesh_discrete_volume(const meshes::SurfaceMesh& worn, const RemeshParameters& p,
                                         const Attempt& attempt, const std::string& msh_path,
                                         RemeshReport& r) {
  const int algorithm = attempt.algorithm;
  meshes::GmshSession session("remesh");
  // With keep_surface the input entities stay and only the volume is meshed anew.
  auto label_of = add_discrete_surfaces(worn);
  r.n_mixed_faces = 0;
  r.n_cut_edges = 0;
  r.planarity_tolerance = 0;
  if (algorithm != keep_surface)
    label_of = classify_patches(worn, attempt.feature_angle_deg, r);
  add_volume(label_of, r);
  set_size_field(worn, p);
  if (algorithm != keep_surface)
    gmsh::option::setNumber("Mesh.Algorithm", algorithm);
  // gmsh would fall back to MeshAdapt on a patch the chosen algorithm fails on, which on
  // discrete surfaces can take many minutes (closest-point searches); fail fast instead and
  // let the next attempt (larger feature angle, other algorithm) take over.
  gmsh::option::setNumber("Mesh.AlgorithmSwitchOnFailure", 0);
  // gmsh meshes curves and surfaces in OpenMP loops, out of which its exception on an error
  // cannot pass (std::terminate: "Unable to recover the edge" ended the program): there an
  // error only stops the meshing, and is thrown here.
  gmsh::option::setNumber("General.AbortOnError", 1);
  gmsh::model::mesh::generate(2);
  std::string error;
  gmsh::logger::getLastError(error);
  if (!error.empty())
    throw std::runtime_error(error);
  gmsh::option::setNumber("General.AbortOnError", 2);
  gmsh::model::mesh::generate(3);
  auto remeshed =
      meshes::gmsh_labelled_surface(&r.n_tetrahedra, &r.volume_after, &r.min_tet_quality);
  check_new_mesh(remeshed, attempt.tet_floor, r);
  meshes::gmsh_write_msh(msh_path);
  return remeshed;
}

// Checks the input of remesh_sample: a closed surface and parameters in range.
void check_remesh_input(const meshes::SurfaceMesh& worn, const RemeshParameters& p) {
  worn.validate("worn surface to remesh");
  const auto closed = meshes::check_closed(worn);
  if (!closed.closed())
    throw std::runtime_error("remeshing: the worn surface is not closed (" +
                             std::to_string(closed.n_boundary_edges) + " open edges, " +
                             std::to_string(closed.n_nonmanifold_edges) + " non-manifold edges)");
  if (!(p.feature_angle_deg > 0 && p.feature_angle_deg < 90))
    throw std::invalid_argument("FEM/Remeshing/feature angle must lie in (0, 90) deg, got " +
                                std::to_string(p.feature_angle_deg));
  if (!(p.min_tet_quality > 0 && p.min_tet_quality < 1))
    throw std::invalid_argument(
        "remeshing: the smallest tetrahedron quality must lie in (0, 1), got " +
        std::to_string(p.min_tet_quality));
}

// The attempts in turn, until one succeeds (its algorithm and angle go to r); false when
// none does. Frontal-Delaunay at the configured feature angle first. A worn surface can hold
// creases of a few degrees more than the angle between its flank and a flattened top, which
// classify as jagged feature curves whose segments cut neighbouring facets ("PLC error" in
// the volume mesher); a larger angle smooths them out, then Delaunay. Last resort: keep the
// worn triangles and mesh only the volume (always possible for a valid closed surface; it
// repairs the interior, the surface triangles stay as relaxed by the wear stages). The
// errors of the failed attempts are appended to `errors`.
bool mesh_first_attempt_that_succeeds(const meshes::SurfaceMesh& input, const RemeshParameters& p,
                                      SurfaceKind kind, const std::string& msh_path,
                                      meshes::SurfaceMesh& remeshed, RemeshReport& r,
                                      std::string& errors) {
  const double angle = p.feature_angle_deg, wider = std::min(89.0, angle + 20);
  // Kept as a last resort, a relaxed worn surface may leave nearly flat tetrahedra.
  std::vector<Attempt> attempts = {{p.surface_algorithm, angle, p.min_tet_quality},
                                   {p.surface_algorithm, wider, p.min_tet_quality},
                                   {5, wider, p.min_tet_quality},
                                   {keep_surface, angle, flat_tet_quality}};
  // The implicit recession's surface is isotropic already: kept, it is the first attempt, and
  // kept with the flat floor the second. gmsh's reparametrisation is no fallback for it: on
  // the wear-out's convex sample (stage 15) its split of a patch (classifySurfaces, METIS) did
  // not return in 75 minutes.
  if (kind == SurfaceKind::isotropic)
    attempts = {{keep_surface, angle, p.min_tet_quality}, {keep_surface, angle, flat_tet_quality}};
  int n = 0;
  for (const Attempt& attempt : attempts) {
    ++n;
    const std::string which = "[algorithm " + std::to_string(attempt.algorithm) + ", angle " +
                              std::to_string(int(attempt.feature_angle_deg)) + "] ";
    try {
      remeshed = mesh_discrete_volume(input, p, attempt, msh_path, r);
      r.attempt = n;
      r.surface_algorithm = attempt.algorithm;
      r.feature_angle_deg = attempt.feature_angle_deg;
      r.failed_attempts = errors;
      return true;
    } catch (const std::string& e) { // the gmsh API throws its last error as a string
      errors += " " + which + e;
    } catch (const std::exception& e) {
      errors += " " + which + e.what();
    }
  }
  return false;
}

} // namespace

meshes::SurfaceMesh remesh_sample(const meshes::SurfaceMesh& worn, const RemeshParameters& p,
                                  const std::string& msh_path, RemeshReport* report,
                                  SurfaceKind kind) {
  const meshes::Stopwatch start;
  check_remesh_input(worn, p);
  RemeshReport r;
  // Relaxed flat sides hold non-Delaunay triangles, which a volume mesher that keeps them can
  // only fill with flat tetrahedra; flipping them is exact (the same planes).
  // An isotropic input is kept as it is: it is not flipped.
  meshes::SurfaceMesh input = worn;
  if (kind == SurfaceKind::worn)
    r.n_flat_flips = meshes::flip_flat_edges(input);
  r.n_faces_before = worn.n_faces();
  r.volume_before = meshes::enclosed_volume(worn);
  r.area_before = meshes::area_per_label(worn);
  meshes::SurfaceMesh remeshed;
  std::string errors;
  if (!mesh_first_attempt_that_succeeds(input, p, kind, msh_path, remeshed, r, errors)) {
    const std::string dump = msh_path + ".failed-input.msh";
    write_surface_msh(input, dump);
    throw std::runtime_error("remeshing: gmsh failed to mesh the worn volume with every surface "
                             "algorithm:" +
                             errors + "; the input surface is in '" + dump + "'");
  }
  // An attempt refused on the way leaves its input beside the mesh, so the case that made
  // it fail can be replayed in a test.
  if (!errors.empty())
    write_surface_msh(input, msh_path + ".refused-input.msh");
  remeshed.set_revision(worn.revision() + 1);
  remeshed.roles = worn.roles; // the labels are the worn surface's, so are their roles
  r.n_faces_after = remeshed.n_faces();
  r.surface_distance = meshes::one_sided_distance(remeshed, worn);
  r.seconds = start.seconds();
  if (report)
    *report = r;
  return remeshed;
}

} // namespace wear::fem
