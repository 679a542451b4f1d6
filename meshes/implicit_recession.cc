// The implicit recession of a worn part (docs/theory.md section 6.3, step 8).
//
// The part is phi, its signed distance on a grid (meshes/level_set_grid.h). A wearing face f
// asked to lose V_f has the depth s_L V_f / A_f; a vertex recedes by the area-weighted mean
// depth of the wearing faces around it, linearly in between; the material removed is the
// union of the balls of those radii about the surface's points, g < 0 (level_set_grid.h), and
// the new part is psi = max(phi, -g) <= 0 (outside the old part psi = phi + max(0, phi - g),
// its distance plus the depth there, so that psi runs linearly across the old surface and the
// interpolant's zero set lies at the front however thin the layer; the zero set's vertices
// then go onto the exact front, project_onto_front). For a uniform depth this is the exact inward
// offset of the surface (Huygens: every point at distance d from the surface, nothing else), with
// crests receding along their bisector and concave corners rounding; it never folds, and where
// the balls reach through a thin part or across a ridge the topology changes with them.
//
// Volume: the grid books the removed material per tetrahedron, vol(phi < 0) - vol(psi < 0),
// to the labels of the receding faces nearest its nodes (the material under each label,
// whichever ball removed it); s_L is scaled per label (within [0.1, 1.5], then a common
// factor) until each label's booked volume matches its asked one. The zero set of the
// interpolant (marching tetrahedra) encloses exactly vol(psi < 0) of the grid; the grid's own
// zero set of phi encloses less than the input (chords across edges and curved faces: the
// grid loss). Where the front has not reached the old surface (g >= 0 at the old point), the
// new surface is put back onto it (vertices onto their patch, onto the old sharp edge, onto
// the old corner), which gives that loss back there; where it has, the chords of the grid, of
// the coarsening and of the isotropic remeshing are given back by an offset of each vertex in
// proportion to the gap between its faces and the grid's zero set, scaled so that the new
// surface encloses V_input - V - V_fragments (closed pieces under 8 h^3 the front cut off,
// dropped as material lost): the volume returns where it went missing, label by label.
//
// Labels: a new face lies either on the old surface (phi = 0 there: it keeps the nearest old
// face's label and patch) or on the receded front (g = 0: it takes those of the face whose
// ball reached there); a majority filter straightens the boundaries, and islands, where the
// labels speckle along a boundary, join their surroundings (meshes/label_cleanup.h). A convex
// element whose top stands less than `vanish_height` above the wearing faces around it is worn away
// and joins them. The coarsening (meshes/surface_decimation.h) keeps the old patches apart; the
// isotropic remeshing (meshes/isotropic_remeshing.h) keeps the label boundaries, and the old sharp
// edges where the front has not passed, as curves, and gives triangles a volume mesher keeps.
// Where it leaves a fold (two faces whose normals are more than 120 degrees apart: a vertex of
// valence 3 beside a nearly straight label boundary), a flip, collapse or move of a free
// wearing vertex within two spacings mends it (meshes/fold_mending.h) before the volume
// offset, which may then fold no edge at that criterion either.
#include "meshes/implicit_recession.h"

#include "meshes/fold_mending.h"
#include "meshes/isotropic_remeshing.h"
#include "meshes/label_cleanup.h"
#include "meshes/level_set_grid.h"
#include "meshes/mesh_quality.h"
#include "meshes/recession.h"
#include "meshes/stopwatch.h"
#include "meshes/surface_decimation.h"
#include "meshes/surface_locator.h"
#include "meshes/surface_restoration.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace wear::meshes {

namespace {

void check_input(const SurfaceMesh& s, const std::vector<double>& removed,
                 const ImplicitRecessionParameters& p) {
  s.validate("surface to recede");
  if (removed.size() != s.n_faces())
    throw std::invalid_argument("implicit recession: " + std::to_string(removed.size()) +
                                " removed volumes for " + std::to_string(s.n_faces()) + " faces");
  for (std::size_t f = 0; f < removed.size(); ++f)
    if (!(removed[f] >= 0) || !std::isfinite(removed[f]))
      throw std::invalid_argument("implicit recession: face " + std::to_string(f) +
                                  " is asked to lose " + std::to_string(removed[f]) + " m^3");
  if (!check_closed(s).closed())
    throw std::invalid_argument("implicit recession: the surface is not closed");
  if (!(p.spacing > 0) || !(p.vanish_height >= 0) || !(p.volume_tolerance > 0) ||
      p.max_iterations < 1 || !(p.max_edge > p.spacing) || !(p.target_edge > p.spacing) ||
      !(p.flat_edge == 0 || p.flat_edge > p.target_edge))
    throw std::invalid_argument("implicit recession: spacing, vanish height, volume tolerance, "
                                "iteration count, largest, target or flat edge out of range");
}

// Dense index of every label of s.
struct LabelIndex {
  std::vector<int> labels;
  int of(int label) const {
    return int(std::lower_bound(labels.begin(), labels.end(), label) - labels.begin());
  }
};

// Per label index, the removed volume the grid books: per tetrahedron vol(phi < 0) -
// vol(psi < 0), shared equally among the labels of the nearest receding faces (owners) of its
// nodes where the front decides psi: the volume removed under each label, whichever face's
// ball removed it. Summed per z layer first, so the result does not depend on the thread
// count.
std::vector<double> booked_removal(const LevelSetGrid& phi, const LevelSetGrid& psi,
                                   const std::vector<std::int32_t>& owner,
                                   const std::vector<int>& label_of_face, std::size_t n_labels) {
  const int nz = phi.n(2) - 1;
  std::vector<double> per_layer(std::size_t(nz) * n_labels, 0.0);
  const double h = phi.spacing();
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = 0; k < nz; ++k) {
    double* booked = &per_layer[std::size_t(k) * n_labels];
    for (int j = 0; j + 1 < phi.n(1); ++j)
      for (int i = 0; i + 1 < phi.n(0); ++i) {
        std::size_t node[8];
        bool active = false;
        for (int c = 0; c < 8; ++c) {
          node[c] = phi.index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
          active |= psi.value[node[c]] != phi.value[node[c]];
        }
        if (!active)
          continue;
        const Vec3 o = phi.node(i, j, k);
        for (const auto& t : kuhn_tetrahedra) {
          Vec3 x[4];
          double a[4], b[4];
          int labels[4], n_active = 0;
          for (int m = 0; m < 4; ++m) {
            const int c = t[m];
            x[m] = o + Vec3(h * (c & 1), h * ((c >> 1) & 1), h * ((c >> 2) & 1));
            a[m] = level_value(phi.value[node[c]], h);
            b[m] = level_value(psi.value[node[c]], h);
            if (psi.value[node[c]] != phi.value[node[c]] && owner[node[c]] >= 0)
              labels[n_active++] = label_of_face[std::size_t(owner[node[c]])];
          }
          if (n_active == 0)
            continue;
          const double removed =
              tetrahedron_negative_volume(x, a) - tetrahedron_negative_volume(x, b);
          for (int m = 0; m < n_active; ++m)
            booked[labels[m]] += removed / n_active;
        }
      }
  }
  std::vector<double> total(n_labels, 0.0);
  for (int k = 0; k < nz; ++k)
    for (std::size_t l = 0; l < n_labels; ++l)
      total[l] += per_layer[std::size_t(k) * n_labels + l];
  return total;
}

// Labels of the new faces: the old face they lie on, or the face whose ball removed the
// material there (the candidates: the sources at the corners of the centroid's cell).
// Returns, per new face, that old face.
std::vector<std::uint32_t> label_new_faces(const SurfaceMesh& old, const SurfaceLocator& locate,
                                           const std::vector<double>& vertex_depth,
                                           const LevelSetGrid& grid,
                                           const std::vector<std::int32_t>& source,
                                           SurfaceMesh& fresh) {
  std::vector<std::uint32_t> from_face(fresh.n_faces());
  const auto centroid = face_centroids(fresh);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t f = 0; f < std::int64_t(fresh.n_faces()); ++f) {
    const Vec3 c = centroid[std::size_t(f)];
    const auto on_old = locate.nearest(c);
    const auto g = front_at(old, vertex_depth, grid, source, c);
    const bool front = g.face >= 0 && std::abs(g.value) < on_old.distance;
    from_face[std::size_t(f)] = std::uint32_t(front ? g.face : on_old.face);
    fresh.face_labels[std::size_t(f)] = old.face_labels[from_face[std::size_t(f)]];
  }
  return from_face;
}

// Patches of the old surface: faces of one label joined across edges where their normals turn
// by less than the feature angle (union-find).
std::vector<int> old_patches(const SurfaceMesh& s, double feature_angle_deg) {
  const auto normal = face_normals(s);
  const double cos_feature = std::cos(feature_angle_deg * 3.14159265358979323846 / 180);
  return face_patches(s, [&](std::uint32_t f, std::uint32_t g, auto) {
    return s.face_labels[f] == s.face_labels[g] && dot(normal[f], normal[g]) >= cos_feature;
  });
}

// The edges between two patches of one label (faces labelled by patch, `label_of_patch`) where
// the front has not reached the old edge between those patches beside either end
// (`reached_old`, at the nearest point of that edge), or whose label is clamped or held: the
// old sharp edges, chamfered by the grid, which the isotropic remeshing keeps as curves (a
// free side's vertical corner, up to the worn top beside it).
std::vector<std::pair<std::uint32_t, std::uint32_t>>
untouched_patch_boundaries(const SurfaceMesh& m, const std::map<int, int>& label_of_patch,
                           const PatchSeams& seams,
                           const std::function<bool(const Vec3&)>& reached_old) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> curves;
  for (const auto& [edge, faces] : edge_faces(m)) {
    const int p = m.face_labels[faces[0]], q = faces.size() == 2 ? m.face_labels[faces[1]] : p;
    if (p == q || label_of_patch.at(p) != label_of_patch.at(q))
      continue;
    // Clamped and held faces never move, nor do the sharp edges between two of their patches
    // (a corner of the holder's sides), wherever the front passed above them.
    bool untouched = m.roles.fixed(label_of_patch.at(p));
    if (!untouched) {
      untouched = true;
      for (const auto v : {edge.first, edge.second}) {
        const auto [y, distance] = seams.nearest(p, q, m.vertices[v]);
        untouched &= std::isfinite(distance) && !reached_old(y);
      }
    }
    if (untouched)
      curves.push_back(edge);
  }
  return curves;
}

// Per face of `m`, the patch of the face of `patches` (labelled by patch) nearest its
// centroid among the faces of its own label: a face beside a label boundary that the
// remesher moved keeps a patch of its label, so that no vertex inside one label is taken
// for one on a seam.
std::vector<int> nearest_patches(const SurfaceMesh& patches,
                                 const std::map<int, int>& label_of_patch, const SurfaceMesh& m) {
  SurfaceMesh by_label = patches;
  for (auto& label : by_label.face_labels)
    label = label_of_patch.at(label);
  const SurfaceLocator locate(by_label);
  const auto centroid = face_centroids(m);
  std::vector<int> patch(m.n_faces());
  for (std::size_t f = 0; f < patch.size(); ++f) {
    auto near = locate.nearest(centroid[f], m.face_labels[f]);
    if (near.face < 0)
      near = locate.nearest(centroid[f]);
    patch[f] = patches.face_labels[std::size_t(near.face)];
  }
  return patch;
}

// Vertices of wearing faces that are neither on a clamped or held face nor `restored`.
std::vector<char> free_wearing_vertices(const SurfaceMesh& m, const std::vector<char>& restored) {
  std::vector<char> movable(m.n_vertices(), 0), fixed(m.n_vertices(), 0);
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    for (const auto v : m.triangles[f]) {
      if (m.face_fixed(f))
        fixed[v] = 1;
      else if (m.face_wears(f))
        movable[v] = 1;
    }
  for (std::size_t v = 0; v < movable.size(); ++v)
    movable[v] = movable[v] && !fixed[v] && !restored[v];
  return movable;
}

// The depth at each vertex: the area-weighted mean of s_L V_f / A_f over the wearing faces
// around it (as the explicit recession's, meshes/recession.h), so that the receded surface
// is continuous where the wear per face is not; the receding faces are the wearing faces
// with a vertex that recedes.
void vertex_depths(const SurfaceMesh& s, const std::vector<double>& unit_depth,
                   const std::vector<double>& scale, const std::vector<int>& label_of_face,
                   const std::vector<double>& area, std::vector<double>& depth,
                   std::vector<char>& receding) {
  std::vector<double> weight(s.n_vertices(), 0.0);
  std::fill(depth.begin(), depth.end(), 0.0);
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    if (s.face_wears(f))
      for (const auto v : s.triangles[f]) {
        depth[v] += scale[std::size_t(label_of_face[f])] * unit_depth[f] * area[f];
        weight[v] += area[f];
      }
  for (std::size_t v = 0; v < depth.size(); ++v)
    depth[v] = weight[v] > 0 ? depth[v] / weight[v] : 0.0;
  for (std::size_t f = 0; f < s.n_faces(); ++f) {
    const auto& t = s.triangles[f];
    receding[f] = s.face_wears(f) && (depth[t[0]] > 0 || depth[t[1]] > 0 || depth[t[2]] > 0);
  }
}

// Drops the closed pieces of `m` that enclose less than `smallest` [m^3] (either sign): a
// fragment of a few grid cells that the front cut off (the tip of an element whose flanks
// receded past it) is material gone with the wear, and decimated to a few faces it leaves a
// pocket of two faces on one another that no volume mesher takes. Returns the volume dropped.
double drop_small_pieces(SurfaceMesh& m, double smallest, std::size_t& n_dropped) {
  const auto piece = face_patches(m, [](std::uint32_t, std::uint32_t, auto) { return true; });
  std::map<int, double> volume;
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    const auto& t = m.triangles[f];
    volume[piece[f]] += dot(m.vertices[t[0]], cross(m.vertices[t[1]], m.vertices[t[2]])) / 6;
  }
  double dropped = 0;
  n_dropped = 0;
  for (const auto& [id, v] : volume)
    if (std::abs(v) < smallest) {
      dropped += v;
      ++n_dropped;
    }
  if (n_dropped == 0)
    return 0;
  // The kept vertices are numbered by first use, not in keep_faces' index order: the
  // coarsening and remeshing after this take their ties in vertex order, and on the
  // wear-out's stage 11 the index order left folds at the elements' feet that gmsh refused.
  SurfaceMesh kept;
  kept.roles = m.roles;
  std::vector<std::int64_t> index(m.n_vertices(), -1);
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    if (std::abs(volume[piece[f]]) < smallest)
      continue;
    Triangle t;
    for (int k = 0; k < 3; ++k) {
      auto& i = index[m.triangles[f][std::size_t(k)]];
      if (i < 0) {
        i = std::int64_t(kept.vertices.size());
        kept.vertices.push_back(m.vertices[m.triangles[f][std::size_t(k)]]);
      }
      t[std::size_t(k)] = std::uint32_t(i);
    }
    kept.triangles.push_back(t);
    kept.face_labels.push_back(m.face_labels[f]);
  }
  kept.set_revision(m.revision());
  m = std::move(kept);
  return dropped;
}

// The grid's zero set of psi lies off the exact one by the interpolation's error, a fraction
// of the spacing, in every step whatever its depth: it cuts the convex crests and fills the
// concave feet. Each vertex whose nearest old point recedes goes onto the exact front of the
// face whose ball decides psi there (inward_front_point), when that lies within a spacing and
// in no other face's ball: the volume the grid misplaces is put back where it misplaced it.
// Returns the vertices moved.
std::size_t project_onto_front(const SurfaceMesh& old, const SurfaceLocator& locate_old,
                               const std::vector<double>& depth, const LevelSetGrid& psi,
                               const std::vector<std::int32_t>& source, SurfaceMesh& fresh) {
  const auto normal = vertex_normals(old);
  const double h = psi.spacing();
  std::size_t n_moved = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : n_moved)
  for (std::int64_t i = 0; i < std::int64_t(fresh.n_vertices()); ++i) {
    Vec3& x = fresh.vertices[std::size_t(i)];
    const auto near = locate_old.nearest(x);
    if (near.face < 0 || !(front_value(old, depth, std::size_t(near.face), near.point) < 0))
      continue;
    // Onto the front of the face whose ball decides psi at x, unless that point lies inside
    // another face's ball (beside a crest, where the fronts of two faces meet and the point
    // would overshoot the crest).
    const auto g = front_at(old, depth, psi, source, x);
    if (g.face < 0)
      continue;
    const Vec3 y = inward_front_point(old, depth, normal, std::size_t(g.face), x);
    if (norm(y - x) < h && front_at(old, depth, psi, source, y).value > -1e-3 * h) {
      x = y;
      ++n_moved;
    }
  }
  return n_moved;
}

} // namespace

ImplicitRecession implicit_recession(const SurfaceMesh& s,
                                     const std::vector<double>& removed_volume,
                                     const ImplicitRecessionParameters& p) {
  const Stopwatch clock;
  check_input(s, removed_volume, p);
  ImplicitRecession r;
  LabelIndex index{s.labels()};
  std::vector<int> label_of_face(s.n_faces());
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    label_of_face[f] = index.of(s.face_labels[f]);
  const auto area = face_areas(s);
  std::vector<double> unit_depth(s.n_faces(), 0.0), asked(index.labels.size(), 0.0);
  double largest_depth = 0;
  for (std::size_t f = 0; f < s.n_faces(); ++f)
    if (s.face_wears(f) && removed_volume[f] > 0 && area[f] > 0) {
      unit_depth[f] = removed_volume[f] / area[f];
      asked[std::size_t(label_of_face[f])] += removed_volume[f];
      r.asked_volume += removed_volume[f];
      largest_depth = std::max(largest_depth, unit_depth[f]);
    }
  for (std::size_t l = 0; l < asked.size(); ++l)
    if (asked[l] > 0)
      r.asked[index.labels[l]] = asked[l];

  const double h = p.spacing, band = 3 * h;
  LevelSetGrid phi(bounding_box(s), h, band + h);
  r.n_nodes = phi.n_nodes();
  signed_distance(s, phi, band);
  const double volume_before = enclosed_volume(s);
  r.grid_loss = volume_before - negative_volume(phi);

  LevelSetGrid psi = phi;
  std::vector<std::int32_t> source, owner;
  std::vector<double> depth(s.n_vertices(), 0.0), booked;
  std::vector<char> receding(s.n_faces(), 0);
  // psi and the booked volumes for the label scales `scale` times `common`.
  const auto build = [&](const std::vector<double>& scale, double common) {
    std::vector<double> scaled = scale;
    for (auto& x : scaled)
      x *= common;
    vertex_depths(s, unit_depth, scaled, label_of_face, area, depth, receding);
    receding_front(s, depth, receding, psi, band, source, owner);
    // Outside the old part psi is its distance plus the depth there (phi - g, the depth of
    // the ball that reaches nearest), not phi: psi then runs linearly across the old
    // surface, and the interpolant's zero set lies at the front however thin the layer.
    // max(phi, -g) there, a layer of depth d << h moves the zero set by about d / 2 only,
    // and the volume scaling doubled the depths to book the asked volume.
    for (std::size_t n = 0; n < psi.value.size(); ++n) {
      const double f = phi.value[n], g = psi.value[n];
      psi.value[n] = f > 0 ? f + std::max(0.0, f - g) : std::max(f, -g);
    }
    if (r.asked_volume > 0)
      booked = booked_removal(phi, psi, owner, label_of_face, asked.size());
    ++r.n_iterations;
  };
  // Newton steps on log(volume) against log(scale): the volume grows in proportion to the
  // depth on a broad face, and up to its cube where the balls are large next to the faces (a
  // sharpened crest). The exponent comes from the last two steps; a step is at most a factor 2.
  const auto newton = [](double x, double value, double target, double previous_x,
                         double previous_value) {
    double exponent = 1;
    if (previous_value > 0 && value > 0 && previous_x > 0 && previous_x != x)
      exponent = std::clamp(std::log(value / previous_value) / std::log(x / previous_x), 0.5, 4.0);
    return x * (value > 0 ? std::clamp(std::pow(target / value, 1 / exponent), 0.5, 2.0) : 2.0);
  };
  std::vector<double> scale(asked.size(), 1.0), previous_scale(asked.size(), 0.0),
      previous_booked(asked.size(), 0.0);
  const int per_label_iterations = p.volume_per_label ? std::max(1, p.max_iterations - 4) : 1;
  for (int it = 0;; ++it) {
    build(scale, 1.0);
    if (r.asked_volume == 0)
      break;
    bool converged = true;
    for (std::size_t l = 0; l < asked.size(); ++l) {
      if (asked[l] == 0)
        continue;
      const double target = asked[l];
      converged &= std::abs(booked[l] - target) <= p.volume_tolerance * target;
      const double next =
          newton(scale[l], booked[l], target, previous_scale[l], previous_booked[l]);
      previous_scale[l] = scale[l];
      previous_booked[l] = booked[l];
      // A label asked for more than the material under it holds (an element asked to recede
      // beyond its width) cannot be matched: its balls would reach through the part. Its
      // scale stays below 1.5, and the common factor below makes up the total.
      scale[l] = std::clamp(next, 0.1, 1.5);
    }
    if (converged && p.volume_per_label)
      break;
    if (it + 1 == per_label_iterations) {
      // The per-label scales did not settle (a label that cannot be matched), or are not
      // asked for: the last ones are kept, and a common factor brings the total to its target.
      scale = previous_scale;
      const double target = r.asked_volume;
      double common = 1, previous_common = 0, total = 0, previous_total = 0;
      for (const double x : booked)
        total += x;
      for (int step = 0; step < 4 && std::abs(total - target) > p.volume_tolerance * target;
           ++step) {
        const double next = newton(common, total, target, previous_common, previous_total);
        previous_common = common;
        previous_total = total;
        common = next;
        build(scale, common);
        total = 0;
        for (const double x : booked)
          total += x;
      }
      break;
    }
  }
  // psi, depth, source and booked all belong to the last build.
  for (std::size_t l = 0; l < booked.size(); ++l)
    if (booked[l] != 0)
      r.removed[index.labels[l]] = booked[l];

  r.surface = zero_surface(psi);
  r.surface.roles = s.roles;
  r.fragment_volume = drop_small_pieces(r.surface, 8 * h * h * h, r.n_fragments);
  const SurfaceLocator locate_old(s);
  r.n_projected = project_onto_front(s, locate_old, depth, psi, source, r.surface);
  // The new faces carry their old patch as label while islands are merged and the surface is
  // coarsened, so that both keep the patches apart; then each patch's label is put back.
  const auto from_face = label_new_faces(s, locate_old, depth, psi, source, r.surface);
  // Whether the front reached a point y of the old surface (by more than a hundredth of the
  // spacing): where it did not, the new surface stands for the old one.
  const auto reached_old = [&](const Vec3& y) {
    return front_at(s, depth, psi, source, y).value < -0.01 * h;
  };
  r.n_fine_faces = r.surface.n_faces();
  const auto patch = old_patches(s, p.feature_angle_deg);
  std::map<int, int> label_of_patch;
  for (std::size_t f = 0; f < r.surface.n_faces(); ++f) {
    const int id = patch[from_face[f]];
    label_of_patch[id] = r.surface.face_labels[f];
    r.surface.face_labels[f] = id;
  }
  smooth_label_boundaries(r.surface, 2);
  merge_label_islands(r.surface, 0.05);
  DecimationParameters coarse;
  coarse.max_error = 0.1 * h;
  coarse.max_edge = p.max_edge;
  decimate(r.surface, coarse);
  // The patches go back to their labels; the edges between two patches of one label where
  // the front has not passed (the old sharp edges, chamfered by the grid) stay curves of the
  // isotropic remeshing, and the new faces find their patch on the coarse surface.
  const SurfaceMesh coarse_patches = r.surface;
  const PatchSeams seams(s, patch);
  auto curves = untouched_patch_boundaries(r.surface, label_of_patch, seams, reached_old);
  for (auto& label : r.surface.face_labels)
    label = label_of_patch.at(label);
  IsotropicRemeshParameters even;
  even.target_edge = p.target_edge;
  isotropic_remesh(r.surface, curves, even);
  if (p.flat_edge > 0) // the flat regions coarsened, the curved ones and the curves kept
    coarsen_flat_regions(r.surface, curves, p.flat_edge, p.flat_error_fraction * h);
  auto patch_of_face = nearest_patches(coarse_patches, label_of_patch, r.surface);
  const auto unsnapped = r.surface.vertices;
  auto restored =
      snap_untouched_vertices(s, patch, seams, patch_of_face, reached_old, h, r.surface);
  r.n_teeth_joined = join_label_teeth(r.surface, patch_of_face);
  if (r.n_teeth_joined > 0) { // the tips go onto their new label's patch
    r.surface.vertices = unsnapped;
    restored = snap_untouched_vertices(s, patch, seams, patch_of_face, reached_old, h, r.surface);
  }
  r.n_restored = std::size_t(std::count(restored.begin(), restored.end(), 1));
  snap_fixed_vertices(s, *std::max_element(depth.begin(), depth.end()) + 2 * h, restored,
                      r.surface);
  r.vanished_labels = merge_vanished_elements(r.surface, p.vanish_height);
  // The remeshing can leave a vertex of valence 3 beside a nearly straight label boundary
  // (an element's foot), one of whose faces turns over; it is mended where it is.
  FoldMendingParameters mend;
  mend.max_shift = 2 * h;
  const auto mended = mend_folds(r.surface, free_wearing_vertices(r.surface, restored), mend);
  r.n_folds_mended = mended.n_folds_before - mended.n_folds_after;
  r.n_folds_left = mended.n_folds_after;
  if (mended.n_flips + mended.n_collapses + mended.n_moves > 0) {
    std::vector<char> kept(r.surface.n_vertices(), 0);
    for (std::size_t v = 0; v < restored.size(); ++v)
      if (mended.new_index[v] != no_vertex)
        kept[mended.new_index[v]] |= restored[v];
    restored = std::move(kept);
  }
  r.surface.set_revision(s.revision() + 1);
  // The chords of the grid, of the coarsening and of the remeshing where the front passed cut
  // off volume there; an offset in proportion to each face's gap gives it back, so that the
  // new surface encloses the input's volume less the asked one.
  // A fragment dropped is material lost with the wear: the rest keeps its volume.
  const double target = volume_before - r.asked_volume - r.fragment_volume;
  r.coarsening_loss = target - enclosed_volume(r.surface);
  const auto movable = free_wearing_vertices(r.surface, restored);
  // The offset folds no edge at the mending's criterion, unless the mending left one.
  const auto chords =
      chord_restoring_offset(r.surface, coarse_patches, movable, target,
                             r.n_folds_left == 0 ? mend.fold_cos : volume_mesher_fold_cos);
  r.uniform_offset = chords.uniform_offset;
  r.restore_held_rings = chords.held_rings;
  r.volume_not_restored = chords.volume_not_restored;
  r.removed_volume = volume_before - enclosed_volume(r.surface);
  r.min_face_quality = min_triangle_quality(r.surface);
  const auto area_before = area_per_label(s), area_after = area_per_label(r.surface);
  for (const auto& [label, a] : area_before)
    if (s.roles.of(label) == FaceRole::clamped) {
      const auto it = area_after.find(label);
      r.worn_through_area += a - (it == area_after.end() ? 0.0 : it->second);
    }
  r.seconds = clock.seconds();
  return r;
}

} // namespace wear::meshes
