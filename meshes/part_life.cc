// What is left of a worn part (meshes/part_life.h).
//
// An element's foot is the surface its boundary spans: the edges where its faces meet another
// label form closed loops, and at a point x in plan view the foot's height is the mean value
// interpolant of the loops' vertex heights (Floater 2003; Hormann and Floater 2006, for any
// set of closed polygons):
//   z_foot(x) = sum_i w_i z_i / sum_i w_i,   w_i = (tan(a_{i-1} / 2) + tan(a_i / 2)) / r_i,
// r_i = |v_i - x| and a_i the signed angle the edge (v_i, v_{i+1}) subtends at x, summed edge
// by edge with tan(a / 2) = 2 A / (r_i r_{i+1} + s_i . s_{i+1}) (A: the signed area of the
// triangle x v_i v_{i+1}, s_i = v_i - x). It reproduces a plane exactly and interpolates the
// loops, so that an unworn element on a flat base stands on the base's plane, and a remnant
// flush with a worn base that tilts or waves by more than the vanish height across the element
// stands on it at no height (the mean of the boundary's heights, as a plane, left such
// remnants standing up to 0.7 mm on the wear-out's stage-19 surface). The element's height is
// the most a vertex stands above its foot; its volume sum_f (z_f - z_foot,f) n_z,f A_f over its
// faces with both heights the means of their vertices' (exact for a graph over the plan, which
// an element is, the foot taken linear across each face). The thinnest point is the lowest
// wearing vertex above the clamped faces' lowest vertex: for a sample clamped at its bottom,
// the remaining thickness under the deepest wear.
#include "meshes/part_life.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace wear::meshes {

namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;

// The foot's height at (x, y): the mean value interpolant of the heights on the closed loops
// of directed `boundary` edges; on a loop's vertex or edge the loop's own height there.
double foot_height(const SurfaceMesh& m, const std::vector<Edge>& boundary, double x, double y,
                   double fallback) {
  double sum_w = 0, sum_wz = 0;
  for (const auto& [a, b] : boundary) {
    const Vec3 &pa = m.vertices[a], &pb = m.vertices[b];
    const double ax = pa.x - x, ay = pa.y - y, bx = pb.x - x, by = pb.y - y;
    const double ra = std::hypot(ax, ay), rb = std::hypot(bx, by);
    const double scale = std::max(ra, rb);
    if (ra <= 1e-12 * scale)
      return pa.z;
    if (rb <= 1e-12 * scale)
      return pb.z;
    const double area2 = ax * by - ay * bx, dot = ax * bx + ay * by;
    if (ra * rb + dot <= 1e-12 * ra * rb) // on the edge: the angle is pi
      return (rb * pa.z + ra * pb.z) / (ra + rb);
    const double t = area2 / (ra * rb + dot); // tan(a / 2)
    sum_w += t / ra + t / rb;
    sum_wz += t / ra * pa.z + t / rb * pb.z;
  }
  return std::abs(sum_w) > 0 ? sum_wz / sum_w : fallback;
}

} // namespace

std::map<int, ElementStanding> convex_element_standing(const SurfaceMesh& m) {
  std::map<int, ElementStanding> standing;
  std::map<int, std::vector<Edge>> boundary; // directed as in the element's faces
  std::map<int, std::pair<double, int>> rim; // sum of the boundary's heights, count
  for (const auto& [edge, faces] : edge_faces(m)) {
    if (faces.size() != 2)
      continue;
    const int a = m.face_labels[faces[0]], b = m.face_labels[faces[1]];
    if (a == b)
      continue;
    for (const auto f : faces) {
      const int l = m.face_labels[f];
      if (!label::is_convex_element(l))
        continue;
      const auto& t = m.triangles[f];
      for (int k = 0; k < 3; ++k) {
        const Edge e{t[std::size_t(k)], t[std::size_t((k + 1) % 3)]};
        if (std::min(e.first, e.second) == edge.first && std::max(e.first, e.second) == edge.second)
          boundary[l].push_back(e);
      }
      auto& r = rim[l];
      r.first += m.vertices[edge.first].z + m.vertices[edge.second].z;
      r.second += 2;
      const int other = l == a ? b : a;
      if (m.roles.wears(l) && m.roles.wears(other))
        ++standing[l].neighbours[other];
    }
  }
  // No wearing neighbour: not an element on a base.
  for (auto it = standing.begin(); it != standing.end();)
    it = it->second.neighbours.empty() ? standing.erase(it) : std::next(it);
  std::vector<double> foot(m.n_vertices(), 0.0);
  std::vector<char> done(m.n_vertices(), 0);
  for (auto& [l, e] : standing) {
    const auto& edges = boundary[l];
    const double mean = rim[l].first / rim[l].second;
    std::fill(done.begin(), done.end(), 0);
    for (const auto& [a, b] : edges) {
      foot[a] = m.vertices[a].z, foot[b] = m.vertices[b].z;
      done[a] = done[b] = 1;
    }
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
      if (m.face_labels[f] != l)
        continue;
      const auto& t = m.triangles[f];
      for (const auto v : t) {
        if (!done[v]) {
          foot[v] = foot_height(m, edges, m.vertices[v].x, m.vertices[v].y, mean);
          done[v] = 1;
        }
        e.height = std::max(e.height, m.vertices[v].z - foot[v]);
      }
      const Vec3 &p = m.vertices[t[0]], &q = m.vertices[t[1]], &r = m.vertices[t[2]];
      const double plan_area = 0.5 * ((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x));
      e.volume += plan_area * ((p.z + q.z + r.z) - (foot[t[0]] + foot[t[1]] + foot[t[2]])) / 3;
    }
  }
  return standing;
}

PartLife part_life(const SurfaceMesh& m, double vanish_height) {
  PartLife life;
  life.elements = convex_element_standing(m);
  for (const auto& [label, e] : life.elements)
    life.n_standing += e.height > vanish_height;
  life.volume = enclosed_volume(m);
  double wear_low = std::numeric_limits<double>::infinity();
  double clamped_low = std::numeric_limits<double>::infinity();
  const auto area = face_areas(m);
  for (std::size_t f = 0; f < m.n_faces(); ++f) {
    const FaceRole role = m.face_role(f);
    for (const auto v : m.triangles[f]) {
      if (role == FaceRole::clamped)
        clamped_low = std::min(clamped_low, m.vertices[v].z);
      else if (m.roles.wears(m.face_labels[f]))
        wear_low = std::min(wear_low, m.vertices[v].z);
    }
    if (role == FaceRole::clamped)
      life.clamped_area += area[f];
  }
  if (std::isfinite(wear_low) && std::isfinite(clamped_low))
    life.thinnest = wear_low - clamped_low;
  return life;
}

} // namespace wear::meshes
