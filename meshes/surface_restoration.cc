// Putting the implicit recession's new surface back where the old one stands for it
// (docs/theory.md section 6.3, step 8), and its chords' volume back where it went missing.
//
// Where the front has not reached the old surface (tested at the old point a vertex would go
// to), the grid's zero set of the old surface cuts the sharp edges into chamfers and the curved
// faces into chords; the old surface is exact there, so the new vertices go back onto it: onto
// their own patch, onto the old edge between their two patches, onto the old corner of three.
// Clamped and held faces never move: their vertices go back onto the old clamped and held faces.
// Where the front has passed, the chords of the triangulation against the finer surface it was made
// from (the grid's zero set, coarsened) cut off volume where the surface is convex; each vertex
// moves out by the mean gap of its faces to that surface, and a uniform offset makes up what is
// left to the asked volume.
#include "meshes/surface_restoration.h"

#include "meshes/mesh_quality.h"
#include "meshes/recession.h"
#include "meshes/surface_locator.h"
#include "meshes/triangle_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace wear::meshes {

// The chords of a triangulation whose vertices lie on a finer curved surface (`reference`)
// cut off volume where it is convex and add it where it is concave. Each new face's gap is
// the signed distance from its centroid to the reference along the reference's normal
// (positive inside: volume lost); each movable vertex first moves along its normal by the
// area-weighted mean gap of its faces, which gives the chords' volume back where it went
// missing. What is left to `target` (the grid's own loss where the front passed, held faces
// put back) is made up by a uniform offset of the movable vertices along their normals,
// found by secant steps on the enclosed volume.
//
// Where a worn face meets a restored one at a concave corner (an element's foot beside the
// worn base), a vertex's normal points across the corner and its move can lay a thin face
// onto its neighbour (the unworn convex sample at 100 um: 2 folded base edges at an
// element's foot). The moves are then held still within 1, 2, 4, 8 rings of the fold and
// the other movable vertices make up the volume, as the remesher's restoring offset does
// (fem/worn_sample.cc); with every ring count folding the surface is handed on unmoved.
ChordRestoration chord_restoring_offset(SurfaceMesh& m, const SurfaceMesh& reference,
                                        const std::vector<char>& movable, double target,
                                        double fold_cos) {
  const SurfaceLocator locate(reference);
  const auto centroid = face_centroids(m);
  const auto area = face_areas(m);
  const auto reference_normal = face_normals(reference);
  std::vector<double> gap(m.n_faces());
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t f = 0; f < std::int64_t(m.n_faces()); ++f) {
    const auto near = locate.nearest(centroid[std::size_t(f)]);
    gap[std::size_t(f)] =
        dot(near.point - centroid[std::size_t(f)], reference_normal[std::size_t(near.face)]);
  }
  std::vector<double> sum(m.n_vertices(), 0.0), weight(m.n_vertices(), 0.0);
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    for (const auto v : m.triangles[f]) {
      sum[v] += area[f] * gap[f];
      weight[v] += area[f];
    }
  const auto normal = vertex_normals(m);
  const auto face_normal = face_normals(m);
  ChordRestoration r;
  SurfaceMesh taken;
  const int rings = hold_still_around_folds(m, [&](const std::vector<char>& held) {
    std::vector<char> free = movable;
    for (std::size_t f = 0; f < m.n_faces(); ++f)
      if (held[f])
        for (const auto v : m.triangles[f])
          free[v] = 0;
    SurfaceMesh candidate = m;
    for (std::size_t v = 0; v < m.n_vertices(); ++v)
      if (free[v] && weight[v] > 0)
        candidate.vertices[v] += normal[v] * (sum[v] / weight[v]);
    std::vector<Vec3> outward(m.n_vertices());
    for (std::size_t v = 0; v < m.n_vertices(); ++v)
      if (free[v])
        outward[v] = normal[v];
    double achieved = 0;
    const double offset = scale_to_volume_loss(
        candidate, outward, enclosed_volume(candidate) - target, &achieved, 1e-6);
    for (std::size_t v = 0; v < m.n_vertices(); ++v)
      candidate.vertices[v] += outward[v] * offset;
    auto q = surface_quality(candidate, &face_normal, 1e-10, fold_cos);
    if (q.valid()) {
      taken = std::move(candidate);
      r.uniform_offset = offset;
    }
    return q;
  });
  if (rings < 0) {
    r.held_rings = 8;
    r.volume_not_restored = enclosed_volume(m) - target;
    return r;
  }
  r.held_rings = rings;
  m = std::move(taken);
  return r;
}

PatchSeams::PatchSeams(const SurfaceMesh& s, const std::vector<int>& patch) : surface_(s) {
  for (const auto& [edge, faces] : edge_faces(s))
    if (faces.size() == 2 && patch[faces[0]] != patch[faces[1]])
      edges_[std::minmax(patch[faces[0]], patch[faces[1]])].push_back(edge);
}

std::pair<Vec3, double> PatchSeams::nearest(int p, int q, const Vec3& x) const {
  std::pair<Vec3, double> best{x, std::numeric_limits<double>::infinity()};
  const auto it = edges_.find(std::minmax(p, q));
  if (it != edges_.end())
    for (const auto& [a, b] : it->second) {
      const Vec3 y = closest_point_on_segment(x, surface_.vertices[a], surface_.vertices[b]);
      if (const double d = norm(y - x); d < best.second)
        best = {y, d};
    }
  return best;
}

// Where the front has not reached the old surface, and on the edges and corners between
// clamped and held patches everywhere, the new surface stands for the old one, and the grid
// only cut its edges into chamfers and its curved faces into chords: a vertex there goes back
// onto the old surface, onto its own patch (faces of one patch only), onto the old edges
// between its two patches (a vertex on a patch boundary), or onto the old vertex its three or
// more patches share (a corner). The test is made at the old points: a vertex goes onto
// those of its patches whose old surface the front has not reached beside it, and only to an
// old point the front has not reached. A vertex on the new corner of a worn top and an
// unworn side goes onto the side (their old edge is gone with the top); one on the side's
// vertical corner, below the worn top, onto that corner. Moves longer than `reach` are not made
// (a vertex whose patch lies elsewhere). Returns, per vertex, whether it moved.
std::vector<char> snap_untouched_vertices(const SurfaceMesh& old, const std::vector<int>& old_patch,
                                          const PatchSeams& seams,
                                          const std::vector<int>& patch_of_face,
                                          const std::function<bool(const Vec3&)>& reached,
                                          double reach, SurfaceMesh& fresh) {
  SurfaceMesh by_patch = old;
  by_patch.face_labels = old_patch;
  const SurfaceLocator locate(by_patch);
  std::vector<std::vector<int>> old_vertex_patches(old.n_vertices());
  for (std::size_t f = 0; f < old.n_faces(); ++f)
    for (const auto v : old.triangles[f]) {
      auto& list = old_vertex_patches[v];
      if (std::find(list.begin(), list.end(), old_patch[f]) == list.end())
        list.push_back(old_patch[f]);
    }
  std::vector<std::vector<int>> patches(fresh.n_vertices());
  for (std::size_t f = 0; f < fresh.n_faces(); ++f)
    for (const auto v : fresh.triangles[f]) {
      auto& list = patches[v];
      if (std::find(list.begin(), list.end(), patch_of_face[f]) == list.end())
        list.push_back(patch_of_face[f]);
    }
  std::vector<char> fixed_patch(old.n_faces(), 0); // by patch id (a face index)
  for (std::size_t f = 0; f < old.n_faces(); ++f)
    if (old.face_fixed(f))
      fixed_patch[std::size_t(old_patch[f])] = 1;
  std::vector<char> moved(fresh.n_vertices(), 0);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t i = 0; i < std::int64_t(fresh.n_vertices()); ++i) {
    const auto v = std::size_t(i);
    Vec3& x = fresh.vertices[v];
    const auto& mine = patches[v];
    // A vertex between fixed patches only (a corner of the holder's sides) goes back onto
    // their old edge or corner wherever the front passed: fixed faces never move.
    const bool between_fixed =
        mine.size() >= 2 && std::all_of(mine.begin(), mine.end(),
                                        [&](int q) { return fixed_patch[std::size_t(q)] != 0; });
    // The patches whose old surface the front has not reached beside x: a vertex on the
    // corner of a worn top and an unworn side goes onto the side, not onto their old edge.
    std::vector<int> open;
    Vec3 target = x;
    double best = std::numeric_limits<double>::infinity();
    if (between_fixed)
      open = mine;
    else
      for (const int q : mine) {
        const auto near = locate.nearest(x, q);
        if (near.face >= 0 && !reached(near.point)) {
          open.push_back(q);
          target = near.point; // the target where this patch is the only open one
          best = near.distance;
        }
      }
    if (open.size() == 2) {
      std::tie(target, best) = seams.nearest(open[0], open[1], x);
    } else if (open.size() > 2) {
      best = std::numeric_limits<double>::infinity();
      for (std::size_t w = 0; w < old.n_vertices(); ++w) {
        const auto& theirs = old_vertex_patches[w];
        bool all = true;
        for (const int q : open)
          all &= std::find(theirs.begin(), theirs.end(), q) != theirs.end();
        const double d = norm(old.vertices[w] - x);
        if (all && d < best) {
          best = d;
          target = old.vertices[w];
        }
      }
    }
    if (best < reach && (between_fixed || !reached(target))) {
      x = target;
      moved[v] = 1;
    }
  }
  return moved;
}

// Clamped and held faces never move: the vertices of the new clamped and held faces go back
// onto the old clamped and held faces (within `reach`: they came from them). The balls of the
// wearing faces next to a held face round into it (the edge between a worn top and a held side
// would recede as a quarter circle); put back, the held side stays plane and the edge drops
// along it, as the explicit recession slides it.
void snap_fixed_vertices(const SurfaceMesh& old, double reach, const std::vector<char>& restored,
                         SurfaceMesh& fresh) {
  SurfaceMesh fixed_faces = old;
  for (std::size_t f = 0; f < old.n_faces(); ++f)
    fixed_faces.face_labels[f] = old.face_fixed(f) ? 1 : 0;
  const SurfaceLocator locate(fixed_faces);
  std::vector<char> on_fixed(fresh.n_vertices(), 0);
  for (std::size_t f = 0; f < fresh.n_faces(); ++f)
    if (fresh.face_fixed(f))
      for (const auto v : fresh.triangles[f])
        on_fixed[v] = !restored[v];
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t v = 0; v < std::int64_t(fresh.n_vertices()); ++v) {
    if (!on_fixed[std::size_t(v)])
      continue;
    auto& x = fresh.vertices[std::size_t(v)];
    const auto near = locate.nearest(x, 1);
    if (near.face >= 0 && near.distance < reach)
      x = near.point;
  }
}

} // namespace wear::meshes
