#pragma once
// The shared triangle surface mesh: vertices, outward-oriented triangles, a region label per
// face and a revision that every derived quantity is checked against.
#include "meshes/label_roles.h"
#include "meshes/vec3.h"

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace wear::meshes {

using Triangle = std::array<std::uint32_t, 3>;

/// Region labels. Numeric values double as gmsh physical tags and deal.II boundary ids:
/// convex element k of column j has id 10*j + k (C11 = 11 ... C99 = 99).
namespace label {
constexpr int unlabelled = 0;
constexpr int bottom = 1; ///< the sample's underside (clamped: sample_roles)
constexpr int side = 2;   ///< the sample's sides (free, or held in a holder)
constexpr int base = 3;   ///< top face of the base plate (wearing)
constexpr int wall = 4;   ///< a DEM wall without further structure
/// A holder's faces held flush against the sample's sides and underside (the pocket the
/// sample sits in): covered by the sample, never reached by a particle.
constexpr int pocket = 5;
inline int convex_element(int column, int element) {
  return 10 * column + element;
}
inline bool is_convex_element(int id) {
  return id >= 11 && id <= 99 && id % 10 != 0;
}
inline int column_of(int id) {
  return id / 10;
}
inline int element_of(int id) {
  return id % 10;
}
/// A scene part's surfaces (dem/scene): surface n of its CAD file (1 ... 999) keeps its
/// number in a label of its own per role the case file gives it (wearing 1000 + n, free
/// 2000 + n, clamped 3000 + n, held 4000 + n), so that the parts' tables name them S<n>,
/// S<n>-free, S<n>-clamped, S<n>-held. The number only names the label: the role is the
/// mesh's roles table's.
constexpr int max_part_surfaces = 999;
/// The label of part surface n under `role`.
int part_surface(FaceRole role, int n);
inline bool is_part_surface(int id) {
  return id > 1000 && id < 5000 && id % 1000 != 0;
}
inline int part_surface_number(int id) {
  return id % 1000;
}
/// "bottom", "side", "base", "wall", "pocket", "C<j><k>", a part's "S<n>" (wearing),
/// "S<n>-free", "S<n>-clamped", "S<n>-held", or "L<id>".
std::string name(int id);
/// Inverse of name(); throws std::invalid_argument for an unknown name.
int from_name(const std::string& name);
} // namespace label

struct BoundingBox {
  Vec3 min, max;
  Vec3 extent() const { return max - min; }
};

class SurfaceMesh {
public:
  std::vector<Vec3> vertices;      ///< [m]
  std::vector<Triangle> triangles; ///< vertex indices, counter-clockwise seen from outside
  std::vector<int> face_labels;    ///< one label id per triangle (see namespace label)
  LabelRoles roles;                ///< the role of each label (free where none is set)

  FaceRole face_role(std::size_t f) const { return roles.of(face_labels[f]); }
  bool face_wears(std::size_t f) const { return roles.wears(face_labels[f]); }
  /// Clamped or held: the face never moves (LabelRoles::fixed).
  bool face_fixed(std::size_t f) const { return roles.fixed(face_labels[f]); }

  std::size_t n_vertices() const { return vertices.size(); }
  std::size_t n_faces() const { return triangles.size(); }

  /// Increments whenever vertices or triangles change; FaceFields remember the revision
  /// they were computed on.
  std::uint64_t revision() const { return revision_; }
  void bump_revision() { ++revision_; }
  void set_revision(std::uint64_t r) { revision_ = r; }

  /// Throws std::runtime_error naming `what` when indices are out of range, labels are
  /// missing or a coordinate is not finite.
  void validate(const std::string& what) const;

  /// Sorted list of distinct labels present.
  std::vector<int> labels() const;

private:
  std::uint64_t revision_ = 1;
};

// --- geometry ------------------------------------------------------------------------------
Vec3 face_normal_unnormalized(const SurfaceMesh& m, std::size_t f); ///< 2 * area * n [m^2]
std::vector<double> face_areas(const SurfaceMesh& m);               ///< [m^2]
std::vector<Vec3> face_normals(const SurfaceMesh& m);               ///< unit outward normals
std::vector<Vec3> face_centroids(const SurfaceMesh& m);             ///< [m]
/// Area-weighted average of the normals of the faces around each vertex, normalised.
std::vector<Vec3> vertex_normals(const SurfaceMesh& m);
BoundingBox bounding_box(const SurfaceMesh& m);
/// Of points[0, n); for n = 0, min is +inf and max -inf.
BoundingBox bounding_box(const Vec3* points, std::size_t n);
double total_area(const SurfaceMesh& m);                    ///< [m^2]
std::map<int, double> area_per_label(const SurfaceMesh& m); ///< [m^2]

/// V - E + F of a closed triangle surface: 2 per sphere-like component, less 2 per handle
/// (a hole through a plate).
long euler_characteristic(const SurfaceMesh& m);
/// Volume enclosed by a closed, outward-oriented surface (divergence theorem) [m^3].
double enclosed_volume(const SurfaceMesh& m);
/// Volume between the faces of one label and the horizontal plane z = z0:
/// integral of (z - z0) n_z dA over those faces [m^3]. For a convex element standing on
/// the plane z0 this is the element's own volume (its footprint contributes nothing).
double volume_above_plane(const SurfaceMesh& m, int label_id, double z0);

// --- topology ------------------------------------------------------------------------------
/// Undirected edge (smaller vertex index first) -> faces that share it.
std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>>
edge_faces(const SurfaceMesh& m);
/// Per face, its patch: faces are joined across each edge two faces share where
/// `joined(f, g, edge)` holds (union-find; the id is a face of the patch, the same for every
/// face of it).
std::vector<int>
face_patches(const SurfaceMesh& m,
             const std::function<bool(std::uint32_t, std::uint32_t,
                                      std::pair<std::uint32_t, std::uint32_t>)>& joined);
/// Vertex -> faces around it (CSR: offsets has n_vertices + 1 entries).
struct VertexFaces {
  std::vector<std::uint32_t> offsets, faces;
};
VertexFaces vertex_faces(const SurfaceMesh& m);
/// Per face, the faces across its edges k = 0, 1, 2 (edge k runs from its vertex k to k + 1);
/// the surface must be a closed manifold (each edge in two faces), else std::runtime_error.
std::vector<std::array<std::uint32_t, 3>> face_neighbours(const SurfaceMesh& m);

struct ClosednessReport {
  std::size_t n_boundary_edges = 0;    ///< edges with one face (holes)
  std::size_t n_nonmanifold_edges = 0; ///< edges with more than two faces
  std::size_t n_misoriented_edges = 0; ///< edges traversed in the same direction twice
  bool closed() const { return n_boundary_edges == 0 && n_nonmanifold_edges == 0; }
  bool consistently_oriented() const { return n_misoriented_edges == 0; }
};
ClosednessReport check_closed(const SurfaceMesh& m);

/// Flip faces so that orientation is consistent across every manifold edge and, for a
/// closed surface, the enclosed volume is positive (normals point outward). Works per
/// connected component. Returns the number of faces flipped.
std::size_t orient_outward(SurfaceMesh& m);

/// Merge vertices with bit-identical coordinates (STL soups) and drop unused ones.
void merge_identical_vertices(SurfaceMesh& m);

/// A vertex index that names no vertex (one dropped by keep_faces).
constexpr std::uint32_t no_vertex = 0xffffffffu;
/// Keeps the faces f with keep[f], in their order, and the vertices they use, in theirs;
/// returns each old vertex's new index (no_vertex for a vertex no kept face uses). The
/// revision is left to the caller.
std::vector<std::uint32_t> keep_faces(SurfaceMesh& m, const std::vector<char>& keep);

} // namespace wear::meshes
