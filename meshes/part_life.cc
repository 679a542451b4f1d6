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
//
// Each worn surface takes its labels from the old one (the nearest old face, or the face whose
// wear reached there), so an element's boundary moves a little with every stage, whatever the
// stage's size, and the volume above the foot it spans with it. The footprint measure does not
// use the worn surface's labels: the outline is the element's boundary on the first surface,
// the foot the mean value interpolant of the worn surface's heights along it (the top's height
// at a point of the plan: the highest upward face over it, n_z > 0, linear across the face),
// and the volume that of the upward faces whose plan centroid lies inside the outline,
// sum_f (z_f - z_foot,f) A_plan,f. A face across the outline counts whole or not at all; there
// the surface stands near its foot, so the error is of the order of a face's area times its
// height above the foot.
#include "meshes/part_life.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace wear::meshes {

namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;

// An edge of a foot's outline with its two heights [m].
struct FootEdge {
  double ax, ay, az, bx, by, bz;
};

// The foot's height at (x, y): the mean value interpolant of the heights on the closed loops
// of directed `loop` edges; on a loop's vertex or edge the loop's own height there.
double foot_height(const std::vector<FootEdge>& loop, double x, double y, double fallback) {
  double sum_w = 0, sum_wz = 0;
  for (const auto& e : loop) {
    const double ax = e.ax - x, ay = e.ay - y, bx = e.bx - x, by = e.by - y;
    const double ra = std::hypot(ax, ay), rb = std::hypot(bx, by);
    const double scale = std::max(ra, rb);
    if (ra <= 1e-12 * scale)
      return e.az;
    if (rb <= 1e-12 * scale)
      return e.bz;
    const double area2 = ax * by - ay * bx, dot = ax * bx + ay * by;
    if (ra * rb + dot <= 1e-12 * ra * rb) // on the edge: the angle is pi
      return (rb * e.az + ra * e.bz) / (ra + rb);
    const double t = area2 / (ra * rb + dot); // tan(a / 2)
    sum_w += t / ra + t / rb;
    sum_wz += t / ra * e.az + t / rb * e.bz;
  }
  return std::abs(sum_w) > 0 ? sum_wz / sum_w : fallback;
}

using EdgeFaces = std::map<Edge, std::vector<std::uint32_t>>;

// The edges where each convex element's faces meet another label, directed as in its faces
// (`edges`: m's edge_faces).
std::map<int, std::vector<Edge>> element_boundaries(const SurfaceMesh& m, const EdgeFaces& edges) {
  std::map<int, std::vector<Edge>> boundary;
  for (const auto& [edge, faces] : edges) {
    if (faces.size() != 2 || m.face_labels[faces[0]] == m.face_labels[faces[1]])
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
    }
  }
  return boundary;
}

// The upward faces of a surface (n_z > 0) in plan view, bucketed on a grid, for the height of
// the surface's top at a point of the plan.
class PlanTop {
public:
  explicit PlanTop(const SurfaceMesh& m) : m_(m) {
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0, sum = 0;
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
      const auto& t = m.triangles[f];
      const Vec3 &p = m.vertices[t[0]], &q = m.vertices[t[1]], &r = m.vertices[t[2]];
      if (plan_area(p, q, r) <= 0)
        continue;
      up_.push_back(std::uint32_t(f));
      for (const Vec3* v : {&p, &q, &r})
        x0 = std::min(x0, v->x), x1 = std::max(x1, v->x), y0 = std::min(y0, v->y),
        y1 = std::max(y1, v->y);
      sum += std::sqrt(plan_area(p, q, r));
    }
    if (up_.empty())
      return;
    cell_ = 2 * sum / double(up_.size());
    x0_ = x0, y0_ = y0;
    nx_ = std::size_t((x1 - x0) / cell_) + 1, ny_ = std::size_t((y1 - y0) / cell_) + 1;
    start_.assign(nx_ * ny_ + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
      for (const auto f : up_) {
        const auto [i0, i1, j0, j1] = cells(f);
        for (std::size_t j = j0; j <= j1; ++j)
          for (std::size_t i = i0; i <= i1; ++i)
            if (pass == 0)
              ++start_[j * nx_ + i + 1];
            else
              faces_[fill[j * nx_ + i]++] = f;
      }
      if (pass == 0) {
        for (std::size_t c = 1; c < start_.size(); ++c)
          start_[c] += start_[c - 1];
        faces_.resize(start_.back());
      }
    }
  }
  static double plan_area(const Vec3& p, const Vec3& q, const Vec3& r) {
    return 0.5 * ((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x));
  }
  // The highest upward face's height at (x, y); NaN where none lies over it.
  double height(double x, double y) const {
    double z = std::numeric_limits<double>::quiet_NaN();
    if (up_.empty() || x < x0_ || y < y0_)
      return z;
    const auto i = std::size_t((x - x0_) / cell_), j = std::size_t((y - y0_) / cell_);
    if (i >= nx_ || j >= ny_)
      return z;
    for (std::size_t k = start_[j * nx_ + i]; k < start_[j * nx_ + i + 1]; ++k) {
      const auto& t = m_.triangles[faces_[k]];
      const Vec3 &p = m_.vertices[t[0]], &q = m_.vertices[t[1]], &r = m_.vertices[t[2]];
      const Vec3 at{x, y, 0};
      const double a = plan_area(p, q, r), u = plan_area(at, q, r) / a, v = plan_area(p, at, r) / a;
      const double tolerance = 1e-12;
      if (u < -tolerance || v < -tolerance || u + v > 1 + tolerance)
        continue;
      const double h = u * p.z + v * q.z + (1 - u - v) * r.z;
      if (!(h <= z))
        z = h;
    }
    return z;
  }
  // The upward faces whose plan bounding boxes meet the box [x0, x1] x [y0, y1], each once.
  std::vector<std::uint32_t> faces_in(double x0, double y0, double x1, double y1) const {
    std::vector<std::uint32_t> out;
    if (up_.empty())
      return out;
    const auto clamp = [](double u, std::size_t n) {
      return std::size_t(std::clamp(u, 0.0, double(n - 1)));
    };
    const auto i0 = clamp((x0 - x0_) / cell_, nx_), i1 = clamp((x1 - x0_) / cell_, nx_);
    const auto j0 = clamp((y0 - y0_) / cell_, ny_), j1 = clamp((y1 - y0_) / cell_, ny_);
    for (std::size_t j = j0; j <= j1; ++j)
      for (std::size_t i = i0; i <= i1; ++i)
        out.insert(out.end(), faces_.begin() + std::ptrdiff_t(start_[j * nx_ + i]),
                   faces_.begin() + std::ptrdiff_t(start_[j * nx_ + i + 1]));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

private:
  std::array<std::size_t, 4> cells(std::uint32_t f) const {
    const auto& t = m_.triangles[f];
    double x0 = m_.vertices[t[0]].x, x1 = x0, y0 = m_.vertices[t[0]].y, y1 = y0;
    for (const auto v : t)
      x0 = std::min(x0, m_.vertices[v].x), x1 = std::max(x1, m_.vertices[v].x),
      y0 = std::min(y0, m_.vertices[v].y), y1 = std::max(y1, m_.vertices[v].y);
    return {std::min(nx_ - 1, std::size_t((x0 - x0_) / cell_)),
            std::min(nx_ - 1, std::size_t((x1 - x0_) / cell_)),
            std::min(ny_ - 1, std::size_t((y0 - y0_) / cell_)),
            std::min(ny_ - 1, std::size_t((y1 - y0_) / cell_))};
  }
  const SurfaceMesh& m_;
  std::vector<std::uint32_t> up_, faces_;
  std::vector<std::size_t> start_;
  double x0_ = 0, y0_ = 0, cell_ = 1;
  std::size_t nx_ = 0, ny_ = 0;
};

// The foot of one element at a time, its outline `loop` with the outline's heights, and the
// faces standing on it: each vertex's foot height is computed once per element (`element_`
// holds whose it is), a vertex of the outline pinned at its own height.
class ElementFoot {
public:
  explicit ElementFoot(const SurfaceMesh& m)
      : m_(m), height_(m.n_vertices(), 0.0), element_(m.n_vertices(), -1) {}
  std::vector<FootEdge> loop;
  /// Starts element `l`; `fallback` [m] where the interpolant has no weight.
  void start(int l, double fallback) { l_ = l, fallback_ = fallback; }
  void pin(std::uint32_t v) { height_[v] = m_.vertices[v].z, element_[v] = l_; }
  /// Face t stands on the foot: its vertices' heights above it, and its volume between it and
  /// the foot, (z_f - z_foot,f) A_plan,f, to e.
  void add_face(const Triangle& t, ElementStanding& e) {
    for (const auto v : t) {
      if (element_[v] != l_) {
        height_[v] = foot_height(loop, m_.vertices[v].x, m_.vertices[v].y, fallback_);
        element_[v] = l_;
      }
      e.height = std::max(e.height, m_.vertices[v].z - height_[v]);
    }
    const Vec3 &p = m_.vertices[t[0]], &q = m_.vertices[t[1]], &r = m_.vertices[t[2]];
    e.volume += PlanTop::plan_area(p, q, r) *
                ((p.z + q.z + r.z) - (height_[t[0]] + height_[t[1]] + height_[t[2]])) / 3;
  }

private:
  const SurfaceMesh& m_;
  std::vector<double> height_;
  std::vector<int> element_;
  int l_ = -1;
  double fallback_ = 0;
};

// Whether (x, y) lies inside the closed loops of `outline` (crossing number).
bool inside(const std::vector<std::array<double, 4>>& outline, double x, double y) {
  bool in = false;
  for (const auto& e : outline)
    if ((e[1] > y) != (e[3] > y) && x < e[0] + (y - e[1]) * (e[2] - e[0]) / (e[3] - e[1]))
      in = !in;
  return in;
}

} // namespace

std::map<int, ElementStanding> convex_element_standing(const SurfaceMesh& m) {
  std::map<int, ElementStanding> standing;
  const auto edges = edge_faces(m);
  const auto boundary = element_boundaries(m, edges);
  for (const auto& [edge, faces] : edges) {
    if (faces.size() != 2)
      continue;
    const int a = m.face_labels[faces[0]], b = m.face_labels[faces[1]];
    if (a == b)
      continue;
    for (const auto f : faces) {
      const int l = m.face_labels[f], other = l == a ? b : a;
      if (label::is_convex_element(l) && m.roles.wears(l) && m.roles.wears(other))
        ++standing[l].neighbours[other];
    }
  }
  // No wearing neighbour: not an element on a base.
  for (auto it = standing.begin(); it != standing.end();)
    it = it->second.neighbours.empty() ? standing.erase(it) : std::next(it);
  ElementFoot foot(m);
  for (auto& [l, e] : standing) {
    const auto& outline = boundary.at(l);
    foot.loop.clear();
    double mean = 0;
    for (const auto& [a, b] : outline) {
      const Vec3 &pa = m.vertices[a], &pb = m.vertices[b];
      foot.loop.push_back({pa.x, pa.y, pa.z, pb.x, pb.y, pb.z});
      mean += 0.5 * (pa.z + pb.z) / double(outline.size());
    }
    foot.start(l, mean);
    for (const auto& [a, b] : outline)
      foot.pin(a), foot.pin(b);
    for (std::size_t f = 0; f < m.n_faces(); ++f)
      if (m.face_labels[f] == l)
        foot.add_face(m.triangles[f], e);
  }
  return standing;
}

ElementFootprints element_footprints(const SurfaceMesh& first) {
  ElementFootprints footprints;
  for (const auto& [l, edges] : element_boundaries(first, edge_faces(first)))
    for (const auto& [a, b] : edges) {
      const Vec3 &pa = first.vertices[a], &pb = first.vertices[b];
      footprints[l].push_back({pa.x, pa.y, pb.x, pb.y});
    }
  return footprints;
}

std::map<int, ElementStanding> footprint_standing(const SurfaceMesh& m,
                                                  const ElementFootprints& footprints) {
  std::map<int, ElementStanding> standing;
  const PlanTop top(m);
  ElementFoot foot(m);
  for (const auto& [l, outline] : footprints) {
    // The outline's heights on m: where no upward face lies over a point of it (not on a
    // part's top), the mean of the others'.
    foot.loop.clear();
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    double sum = 0;
    int n = 0;
    for (const auto& e : outline) {
      foot.loop.push_back({e[0], e[1], top.height(e[0], e[1]), e[2], e[3], top.height(e[2], e[3])});
      for (const double z : {foot.loop.back().az, foot.loop.back().bz})
        if (std::isfinite(z))
          sum += z, ++n;
      x0 = std::min({x0, e[0], e[2]}), x1 = std::max({x1, e[0], e[2]});
      y0 = std::min({y0, e[1], e[3]}), y1 = std::max({y1, e[1], e[3]});
    }
    if (n == 0)
      continue;
    const double mean = sum / n;
    for (auto& e : foot.loop)
      e.az = std::isfinite(e.az) ? e.az : mean, e.bz = std::isfinite(e.bz) ? e.bz : mean;
    foot.start(l, mean);
    auto& s = standing[l];
    for (const auto f : top.faces_in(x0, y0, x1, y1)) {
      const auto& t = m.triangles[f];
      const Vec3 &p = m.vertices[t[0]], &q = m.vertices[t[1]], &r = m.vertices[t[2]];
      if (inside(outline, (p.x + q.x + r.x) / 3, (p.y + q.y + r.y) / 3))
        foot.add_face(t, s);
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
