// Per-revolution evaluations of the wear tester (docs/theory.md section 7).
//
// Face sets: the wear face is the base top plus the convex elements; a column is its
// elements plus the strip of base top between the midlines to the neighbouring columns (the
// first and last strips reach the sample's leading and trailing edges). The plain sample
// uses the strips of the default pattern so both samples report the same columns.
// Samples within a revolution (every 1/n of it):
//   normal force   F = sum_f dI_Fn,f / dt over the wear face (per column likewise)  [N]
//   wear rate      dV / dt over the wear face                                       [m^3/s]
//   speed over the sample: mean |v| of particles whose centre lies above the footprint
//   bed height over the wear face: mean top (z + r) of the highest particles that would
//     cover the footprint once (a hexagonal layer of the mean diameter)
//   bottom layer: particles above the footprint whose gap to the wear surface is below one
//     layer diameter; their |v| and |omega| pooled over all samples of the revolution.
// A grain is a sphere or a clump's body (BedGrains): a body is over the footprint when its
// centre of mass is, counts once, with its centre's speed and its angular speed, its gap the
// least over its members (the lowest point above the surface under that member) and its
// top the highest member point; so the bottom layer is the bodies one of whose members lies
// within a layer diameter of the surface, their mean |v_centre| and |omega|.
// Coefficient of variation C_v = sigma / mu over the samples of a revolution; the run is
// steady once C_v of speed, bed height and wear rate stay below the threshold for the given
// number of consecutive revolutions.
// Fits through the origin minimise sum (y - f(x))^2: a = sum xy / sum x^2; (b, c) from the
// 2 x 2 normal equations in x^2 and x. R^2 = 1 - SS_res / SS_tot, SS_tot about the mean.
#include "dem/evaluation/tester_evaluation.h"

#include "meshes/sample_generator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wear::dem {

using meshes::Vec3;

Statistic statistic(const std::vector<double>& s) {
  Statistic r;
  if (s.empty())
    return r;
  for (double v : s)
    r.mean += v;
  r.mean /= double(s.size());
  double var = 0;
  for (double v : s)
    var += (v - r.mean) * (v - r.mean);
  r.std = s.size() > 1 ? std::sqrt(var / double(s.size() - 1)) : 0;
  return r;
}

WearFits fit_wear(const std::vector<double>& x, const std::vector<double>& y) {
  WearFits f;
  f.n_points = int(x.size());
  if (x.size() < 1 || x.size() != y.size())
    return f;
  double sx2 = 0, sxy = 0, sx3 = 0, sx4 = 0, sx2y = 0, mean = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx2 += x[i] * x[i];
    sxy += x[i] * y[i];
    sx3 += x[i] * x[i] * x[i];
    sx4 += x[i] * x[i] * x[i] * x[i];
    sx2y += x[i] * x[i] * y[i];
    mean += y[i];
  }
  mean /= double(y.size());
  if (sx2 > 0)
    f.a = sxy / sx2;
  const double det = sx4 * sx2 - sx3 * sx3;
  if (x.size() >= 2 && std::abs(det) > 1e-14 * sx4 * sx2) {
    f.b = (sx2y * sx2 - sxy * sx3) / det;
    f.c = (sx4 * sxy - sx3 * sx2y) / det;
  } else {
    f.c = f.a;
  }
  double tot = 0, res_l = 0, res_q = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    tot += (y[i] - mean) * (y[i] - mean);
    res_l += std::pow(y[i] - f.a * x[i], 2);
    res_q += std::pow(y[i] - f.b * x[i] * x[i] - f.c * x[i], 2);
  }
  f.r2_linear = tot > 0 ? 1 - res_l / tot : 1;
  f.r2_quadratic = tot > 0 ? 1 - res_q / tot : 1;
  return f;
}

TesterEvaluation::TesterEvaluation(const meshes::SurfaceMesh& sample,
                                   const meshes::SampleGeometry& geometry,
                                   const meshes::SamplePlacement& placement, double layer_diameter,
                                   double steady_threshold, int steady_revolutions)
    : geometry_(geometry), frame_(geometry, placement), layer_diameter_(layer_diameter),
      steady_threshold_(steady_threshold), steady_revolutions_(steady_revolutions) {
  // Column midlines along the flow from the pattern (also for the plain sample).
  meshes::SampleGeometry pattern = geometry;
  pattern.convex = true;
  for (const auto& e : meshes::element_sites(pattern)) {
    if (e.column > int(column_y_.size()))
      column_y_.resize(e.column, 0);
    column_y_[e.column - 1] = e.y;
  }
  n_columns_ = int(column_y_.size());
  set_surface(sample);
}

void TesterEvaluation::set_surface(const meshes::SurfaceMesh& sample) {
  const auto centroids = meshes::face_centroids(sample);
  const std::size_t nf = sample.n_faces();
  face_column_.assign(nf, 0);
  face_label_ = sample.face_labels;
  wears_.assign(nf, 0);
  // Labels seen before stay (an element worn away still has its column in the records).
  for (std::size_t f = 0; f < nf; ++f) {
    const int l = sample.face_labels[f];
    wears_[f] = sample.roles.wears(l);
    if (meshes::label::is_convex_element(l)) {
      face_column_[f] = meshes::label::column_of(l);
      if (std::find(element_labels_.begin(), element_labels_.end(), l) == element_labels_.end())
        element_labels_.push_back(l);
    } else if (l == meshes::label::base) {
      int c = 1;
      while (c < n_columns_ && centroids[f].y > 0.5 * (column_y_[c - 1] + column_y_[c]))
        ++c;
      face_column_[f] = c;
    }
  }
  std::sort(element_labels_.begin(), element_labels_.end());
  height_.clear();
}

void TesterEvaluation::update_height_map(const meshes::SurfaceMesh& placed) {
  if (placed.revision() == height_revision_ && !height_.empty())
    return;
  height_revision_ = placed.revision();
  const double L = geometry_.length, W = geometry_.width;
  cell_ = std::min(1e-3, layer_diameter_ / 4);
  hx_ = int(std::ceil(W / cell_));
  hy_ = int(std::ceil(L / cell_));
  height_.assign(std::size_t(hx_) * hy_, geometry_.thickness);
  std::vector<Vec3> v(placed.n_vertices());
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = frame_.point_to_sample(placed.vertices[i]);
  for (std::size_t f = 0; f < placed.n_faces(); ++f) {
    if (!wears_[f])
      continue;
    const Vec3 a = v[placed.triangles[f][0]], b = v[placed.triangles[f][1]],
               c = v[placed.triangles[f][2]];
    const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (std::abs(det) < 1e-18)
      continue; // vertical in projection: its neighbours cover the cells
    const int i0 = std::max(0, int((std::min({a.x, b.x, c.x}) + W / 2) / cell_));
    const int i1 = std::min(hx_ - 1, int((std::max({a.x, b.x, c.x}) + W / 2) / cell_));
    const int j0 = std::max(0, int((std::min({a.y, b.y, c.y}) + L / 2) / cell_));
    const int j1 = std::min(hy_ - 1, int((std::max({a.y, b.y, c.y}) + L / 2) / cell_));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const double x = -W / 2 + (i + 0.5) * cell_, y = -L / 2 + (j + 0.5) * cell_;
        const double l1 = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
        const double l2 = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
        if (l1 < -1e-9 || l2 < -1e-9 || l1 + l2 > 1 + 1e-9)
          continue;
        const double z = a.z + l1 * (b.z - a.z) + l2 * (c.z - a.z);
        double& h = height_[std::size_t(j) * hx_ + i];
        h = std::max(h, z);
      }
  }
}

double TesterEvaluation::surface_height(double x, double y) const {
  const int i = std::clamp(int((x + geometry_.width / 2) / cell_), 0, hx_ - 1);
  const int j = std::clamp(int((y + geometry_.length / 2) / cell_), 0, hy_ - 1);
  return height_[std::size_t(j) * hx_ + i];
}

void TesterEvaluation::begin_revolution(double time) {
  open_ = RevolutionSamples{};
  open_.start_time = open_.last_time = time;
  open_.column_force.assign(n_columns_, {});
}

void TesterEvaluation::resume_samples(const RevolutionSamples& samples) {
  const std::size_t n = samples.force.size();
  const bool fits = samples.column_force.size() == std::size_t(n_columns_) &&
                    samples.speed.size() == n && samples.height.size() == n &&
                    samples.rate.size() == n && samples.bottom_count.size() == n &&
                    samples.last_removed.size() == samples.last_impulse.size() &&
                    (samples.last_removed.empty() || samples.last_removed.size() == wears_.size());
  for (const auto& c : samples.column_force)
    if (c.size() != n)
      throw std::invalid_argument("evaluation samples: a column's samples do not match the others");
  if (!fits)
    throw std::invalid_argument("evaluation samples do not match the sample surface's columns "
                                "and faces");
  open_ = samples;
}

void BedGrains::add(const Vec3& x, double v, double w, double g, double t) {
  centre.push_back(x);
  speed.push_back(v);
  spin.push_back(w);
  gap.push_back(g);
  top.push_back(t);
}

std::vector<double> BedGrains::packed() const {
  std::vector<double> out;
  out.reserve(7 * size());
  for (std::size_t i = 0; i < size(); ++i)
    out.insert(out.end(),
               {centre[i].x, centre[i].y, centre[i].z, speed[i], spin[i], gap[i], top[i]});
  return out;
}

void BedGrains::append_packed(const std::vector<double>& values) {
  for (std::size_t k = 0; k + 7 <= values.size(); k += 7) {
    const double* v = values.data() + k;
    add({v[0], v[1], v[2]}, v[3], v[4], v[5], v[6]);
  }
}

BedGrains TesterEvaluation::grains(const Particles& p, const Clumps* clumps,
                                   const meshes::SurfaceMesh& placed) {
  update_height_map(placed);
  BedGrains g;
  std::vector<char> member;
  if (clumps && !clumps->empty()) {
    member.assign(p.n_real, 0);
    for (const auto slot : clumps->member_slot)
      if (slot < p.n_real)
        member[slot] = 1;
  }
  for (std::size_t i = 0; i < p.n_real; ++i) {
    if ((!member.empty() && member[i]) || !over_sample(p.position[i]))
      continue;
    const Vec3 x = frame_.point_to_sample(p.position[i]);
    g.add(x, meshes::norm(p.velocity[i]), meshes::norm(p.angular_velocity[i]),
          x.z - p.radius[i] - surface_height(x.x, x.y), x.z + p.radius[i]);
  }
  if (member.empty())
    return g;
  for (std::size_t b = 0; b < clumps->size(); ++b) {
    if (!over_sample(clumps->position[b]))
      continue;
    double gap = std::numeric_limits<double>::infinity(), top = -gap;
    Vec3 spin{0, 0, 0};
    for (auto k = clumps->member_begin[b]; k < clumps->member_begin[b + 1]; ++k) {
      const std::uint32_t i = clumps->member_slot[k];
      const Vec3 x = frame_.point_to_sample(p.position[i]);
      gap = std::min(gap, x.z - p.radius[i] - surface_height(x.x, x.y));
      top = std::max(top, x.z + p.radius[i]);
      spin = p.angular_velocity[i]; // every member carries the body's
    }
    g.add(frame_.point_to_sample(clumps->position[b]), meshes::norm(clumps->velocity[b]),
          meshes::norm(spin), gap, top);
  }
  return g;
}

void TesterEvaluation::sample(const BedGrains& g, double time, const std::vector<double>& removed,
                              const std::vector<double>& normal_impulse) {
  const double dt = time - open_.last_time;
  if (!(dt > 0))
    return;
  const std::size_t nf = removed.size();
  if (open_.last_removed.empty()) {
    open_.last_removed.assign(nf, 0);
    open_.last_impulse.assign(nf, 0);
  }
  double volume = 0, force = 0;
  std::vector<double> column_force(n_columns_, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    if (!wears_[f])
      continue;
    const double di = normal_impulse[f] - open_.last_impulse[f];
    volume += removed[f] - open_.last_removed[f];
    force += di;
    column_force[face_column_[f] - 1] += di;
  }
  open_.last_removed = removed;
  open_.last_impulse = normal_impulse;
  open_.last_time = time;
  open_.force.push_back(force / dt);
  open_.rate.push_back(volume / dt);
  for (int c = 0; c < n_columns_; ++c)
    open_.column_force[c].push_back(column_force[c] / dt);

  const double L = geometry_.length, W = geometry_.width;
  double speed = 0, n_over = 0, n_bottom = 0;
  std::vector<double> tops;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const double v = g.speed[i];
    speed += v;
    n_over += 1;
    tops.push_back(g.top[i]);
    if (g.gap[i] < layer_diameter_) {
      const double w = g.spin[i];
      n_bottom += 1;
      open_.bottom_v += v;
      open_.bottom_v2 += v * v;
      open_.bottom_w += w;
      open_.bottom_w2 += w * w;
    }
  }
  open_.bottom_n += n_bottom;
  open_.bottom_count.push_back(n_bottom);
  open_.speed.push_back(n_over > 0 ? speed / n_over : 0);
  const auto per_layer =
      std::max<std::size_t>(1, std::size_t(L * W / (0.866 * layer_diameter_ * layer_diameter_)));
  const std::size_t m = std::min(per_layer, tops.size());
  std::partial_sort(tops.begin(), tops.begin() + m, tops.end(), std::greater<double>());
  double top = 0;
  for (std::size_t k = 0; k < m; ++k)
    top += tops[k];
  open_.height.push_back(m > 0 ? top / double(m) - geometry_.thickness : 0);
}

bool TesterEvaluation::over_sample(const Vec3& position) const {
  const Vec3 x = frame_.point_to_sample(position);
  return std::abs(x.x) <= geometry_.width / 2 && std::abs(x.y) <= geometry_.length / 2 &&
         x.z >= geometry_.thickness - 1e-3;
}

RevolutionRecord& TesterEvaluation::end_revolution(double time, const std::vector<double>& removed,
                                                   double contact_total_removed) {
  RevolutionRecord r;
  r.revolution = int(history_.size()) + 1;
  r.time = time;
  r.column_wear.assign(n_columns_, 0);
  for (int l : element_labels_)
    r.element_wear[l] = 0;
  for (std::size_t f = 0; f < removed.size(); ++f) {
    if (!wears_[f]) {
      r.wear_volume_other += removed[f];
      continue;
    }
    r.wear_volume += removed[f];
    r.column_wear[face_column_[f] - 1] += removed[f];
    if (meshes::label::is_convex_element(face_label_[f]))
      r.element_wear[face_label_[f]] += removed[f];
  }
  r.contact_total_wear_volume = contact_total_removed;
  r.wear_volume_cumulative =
      r.wear_volume + (history_.empty() ? 0 : history_.back().wear_volume_cumulative);
  if (!element_labels_.empty()) {
    double sum = 0;
    for (const auto& [l, v] : r.element_wear)
      sum += v;
    r.mean_element_increment = sum / double(element_labels_.size());
  }
  r.normal_force = statistic(open_.force);
  for (int c = 0; c < n_columns_; ++c)
    r.column_normal_force.push_back(statistic(open_.column_force[c]));
  if (open_.bottom_n > 0) {
    const auto pooled = [&](double s, double s2) {
      Statistic st;
      st.mean = s / open_.bottom_n;
      st.std = std::sqrt(std::max(0.0, s2 / open_.bottom_n - st.mean * st.mean));
      return st;
    };
    r.bottom_speed = pooled(open_.bottom_v, open_.bottom_v2);
    r.bottom_spin = pooled(open_.bottom_w, open_.bottom_w2);
  }
  r.bottom_count = statistic(open_.bottom_count).mean;
  r.speed_over_sample = statistic(open_.speed);
  r.bed_height = statistic(open_.height);
  r.wear_rate = statistic(open_.rate);
  r.steady = r.speed_over_sample.cv() < steady_threshold_ &&
             r.bed_height.cv() < steady_threshold_ && r.wear_rate.cv() < steady_threshold_;
  r.steady_revolution = history_.empty() ? 0 : history_.back().steady_revolution;
  if (r.steady_revolution == 0 && r.steady) {
    int run = 1;
    for (auto it = history_.rbegin(); it != history_.rend() && it->steady; ++it)
      ++run;
    if (run >= steady_revolutions_)
      r.steady_revolution = r.revolution;
  }
  history_.push_back(r);
  // Fits of the cumulative wear since the steady revolution (or since the start).
  const int from = r.steady_revolution;
  std::vector<double> x, y;
  const double y0 = from > 0 ? history_[from - 1].wear_volume_cumulative : 0;
  for (const auto& h : history_)
    if (h.revolution > from) {
      x.push_back(h.revolution - from);
      y.push_back(h.wear_volume_cumulative - y0);
    }
  history_.back().fits = fit_wear(x, y);
  history_.back().fits_from = from;
  return history_.back();
}

} // namespace wear::dem
