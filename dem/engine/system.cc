// DEM time loop: velocity Verlet (kick-drift, forces, kick) for translation and rotation,
// with the contact forces of contact_law.h.
//
//   v(t+dt/2) = v(t) + dt/2 F(t)/m,  x(t+dt) = x(t) + dt v(t+dt/2),
//   F(t+dt) from x(t+dt) and v(t+dt/2),  v(t+dt) = v(t+dt/2) + dt/2 F(t+dt)/m,
// and likewise for the spin with I = 2/5 m r^2 (spheres). Within run(), the closing
// half-kick of one step and the opening half-kick and drift of the next are one pass over the
// particles (the same operations in the same order as separate steps). Second order for
// conservative forces; the velocity-dependent damping and friction use the half-step velocity (as
// in LIGGGHTS). Time step: Rayleigh time T_R = pi R sqrt(rho/G) / (0.1631 nu + 0.8766) of the
// smallest particle; above 40 % of T_R the run is refused unless forced.
// Every particle is checked each step (finite, below the speed limit) and at each list
// rebuild (inside the domain); failures name the particle and suggest a cause.
#include "dem/engine/system.h"

#include "meshes/constants.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace wear::dem {

int System::add_wall(const MeshWall& wall) {
  const int w = register_wall(WallKind::mesh, walls_.size(), wall.name(), wall.material());
  walls_.push_back(wall);
  return w;
}

double System::rayleigh_time() const {
  double t = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < particles.n_real; ++i) {
    const Material& m = materials.material(particles.material[i]);
    t = std::min(t, pi * particles.radius[i] * std::sqrt(m.density / m.shear_modulus()) /
                        (0.1631 * m.poisson_ratio + 0.8766));
  }
  return t;
}

void System::setup() {
  auto& p = particles;
  has_clumps_ = !clumps_.empty(); // over ranks before the bodies are distributed
  if (rank_link_)
    distribute_over_ranks();
  else if (p.n_real == 0)
    throw std::invalid_argument("DEM: no particles");
  for (std::size_t i = 0; i < p.n_real; ++i) {
    if (!(p.radius[i] > 0) || !std::isfinite(p.radius[i]))
      throw std::invalid_argument("DEM: particle " + std::to_string(p.id[i]) +
                                  " has a non-positive radius " + std::to_string(p.radius[i]));
    if (p.material[i] < 0 || p.material[i] >= materials.n_materials())
      throw std::invalid_argument("DEM: particle " + std::to_string(p.id[i]) +
                                  " refers to an unknown material");
  }
  contact_ = materials.contact_table();
  n_mat_ = materials.n_materials();
  double t_r = rayleigh_time();
  // A rank may hold no particle: the extremes start from the neutral values.
  double r_max = settings.max_radius, r_min = std::numeric_limits<double>::infinity();
  if (p.n_real > 0) {
    r_max = std::max(r_max, *std::max_element(p.radius.begin(), p.radius.begin() + p.n_real));
    r_min = *std::min_element(p.radius.begin(), p.radius.begin() + p.n_real);
  }
  // A body wraps and migrates as one, by its centre: its members reach this far beyond it.
  double overhang = settings.max_overhang;
  for (const Vec3& c : clumps_.member_offset)
    overhang = std::max(overhang, meshes::norm(c));
  if (rank_link_)
    reduce_setup_values(t_r, r_max, r_min, overhang);
  dt_ = settings.time_step > 0 ? settings.time_step : settings.time_step_fraction * t_r;
  if (!(dt_ > 0) || !std::isfinite(dt_))
    throw std::invalid_argument("DEM/Time step: must be positive");
  if (dt_ > 0.4 * t_r && !settings.force_time_step) {
    std::ostringstream s;
    s << "DEM/Time step: " << dt_ << " s is " << 100 * dt_ / t_r << " % of the Rayleigh time "
      << t_r
      << " s of the smallest particle; the limit is 40 % (set 'Force time step' to override)";
    throw std::invalid_argument(s.str());
  }
  r_max_ = r_max;
  skin_ = settings.skin > 0 ? settings.skin : 0.5 * r_min;
  member_overhang_ = overhang;
  if (settings.periodic.enabled) {
    const double a = settings.periodic.angle;
    if (!(a > 0 && a < 2 * pi))
      throw std::invalid_argument("DEM/Periodic sector angle must lie in (0, 360) degrees");
    // The sector is periodic by rotation about z, which only a vertical gravity respects.
    if (settings.gravity.x != 0 || settings.gravity.y != 0)
      throw std::invalid_argument("DEM/Gravity: a periodic sector needs gravity along z");
    cos_t_ = std::cos(a);
    sin_t_ = std::sin(a);
  }
  if (settings.periodic_slab.enabled) {
    const auto& sl = settings.periodic_slab;
    if (settings.periodic.enabled)
      throw std::invalid_argument("DEM: a periodic slab and a periodic sector exclude each other");
    if (sl.axis < 0 || sl.axis > 2)
      throw std::invalid_argument("DEM: the periodic slab's axis must be 0, 1 or 2 (x, y, z)");
    // Each particle has at most one image: the period holds more than twice the ghosts' reach.
    const double reach = ghost_reach();
    if (!(sl.hi - sl.lo > 2 * reach))
      throw std::invalid_argument("DEM: the periodic slab's period " +
                                  std::to_string(sl.hi - sl.lo) +
                                  " m must exceed twice the ghosts' reach (two largest diameters "
                                  "and the skin, " +
                                  std::to_string(2 * reach) + " m)");
    shift_ = {0, 0, 0};
    shift_[sl.axis] = sl.hi - sl.lo;
  }
  for (auto& w : walls_)
    w.build_grid(r_max_ + skin_);
  if (periodic() && has_moving_walls())
    throw std::invalid_argument(
        "DEM: walls with a rigid motion cannot be combined with a periodic boundary");
  next_id_ = first_free_id(p.id.data(), p.n_real);
  if (rank_link_)
    check_ranks_at_setup();
  set_n_threads(omp_get_max_threads());
  set_up_ = true;
  time_ = settings.start_time;
  check_particles_or_throw("at setup");
  move_walls(time_);
  rebuild();
  reset_forces();
  compute_forces();
  if (rank_link_)
    return_ghost_forces();
  gather_clump_forces();
}

void System::set_n_threads(int n) {
  if (n < 1)
    throw std::invalid_argument("DEM: the thread count must be at least 1");
  n_threads_ = n;
  omp_set_num_threads(n); // every parallel loop of the engine uses the same count
  size_wear_accumulators();
  foreign_.assign(n_threads_, {});
  pair_block_.resize(n_threads_);
  thread_pair_seconds_.assign(n_threads_, 0.0);
  thread_wall_seconds_.assign(n_threads_, 0.0);
  phase_times_ = {};
  error_particle_.assign(n_threads_, -1);
  error_kind_.assign(n_threads_, no_error);
  if (!owner_split_.empty()) // split once by a rebuild (a rank's slab may hold no particle)
    split_ownership();
}

void System::check_particles_or_throw(const char* stage) {
  const auto& p = particles;
  const auto& d = settings.domain;
  long worst = -1;
  int kind = no_error;
  for (int t = 0; t < n_threads_; ++t)
    if (error_kind_[t] != no_error && (worst < 0 || error_particle_[t] < worst)) {
      worst = error_particle_[t];
      kind = error_kind_[t];
    }
  if (worst < 0)
    for (std::size_t i = 0; i < p.n_real; ++i) {
      const Vec3& x = p.position[i];
      if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z)) {
        worst = long(i);
        kind = not_finite;
        break;
      }
      if (x.x < d.min.x || x.y < d.min.y || x.z < d.min.z || x.x > d.max.x || x.y > d.max.y ||
          x.z > d.max.z) {
        worst = long(i);
        kind = outside;
        break;
      }
    }
  if (worst < 0)
    return;
  const std::size_t i = std::size_t(worst);
  std::ostringstream s;
  s.precision(6);
  s << "DEM " << stage << ", step " << n_steps_ << " (t = " << time_ << " s): particle " << p.id[i]
    << " at (" << p.position[i].x << ", " << p.position[i].y << ", " << p.position[i].z
    << ") m with velocity (" << p.velocity[i].x << ", " << p.velocity[i].y << ", "
    << p.velocity[i].z << ") m/s ";
  switch (kind) {
  case not_finite:
    s << "has a non-finite state. Likely causes: a time step too large for the stiffness "
         "(reduce 'Time step fraction'), or overlapping particles at insertion.";
    break;
  case too_fast:
    s << "exceeds the speed limit of " << settings.max_speed
      << " m/s. Likely causes: large initial overlaps, a too large time step, or a wall "
         "moving into particles.";
    break;
  case outside:
    s << "left the domain [" << d.min.x << ", " << d.max.x << "] x [" << d.min.y << ", " << d.max.y
      << "] x [" << d.min.z << ", " << d.max.z
      << "] m. A wall may have a gap, or the particle escaped through an open top.";
    break;
  default:
    s << "touches more than " << wall_slots << " wall features at once.";
  }
  const Vec3& x = p.position[i];
  if (std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z))
    s << " " << describe_surroundings(i);
  throw std::runtime_error(s.str());
}

void System::step() {
  if (!set_up_)
    throw std::logic_error("System::step() before setup()");
  advance(false);
  close_step();
}

void System::run(std::uint64_t n) {
  if (!set_up_)
    throw std::logic_error("System::run() before setup()");
  // The closing half-kick of each step is fused into the next step's opening one: the same
  // operations in the same order, one pass over the particle arrays instead of two.
  for (std::uint64_t s = 0; s < n; ++s)
    advance(s > 0);
  if (n > 0)
    close_step();
}

void System::advance(bool close_previous) {
  auto& p = particles;
  const double h = 0.5 * dt_, vmax2 = settings.max_speed * settings.max_speed;
  const double trigger = 0.25 * skin_ * skin_; // half the skin, squared
  const Vec3 gravity = settings.gravity;
  double max_moved2 = 0; // [m^2] the largest squared displacement since the last rebuild
  const double t_begin = omp_get_wtime();
#pragma omp parallel num_threads(n_threads_) reduction(max : max_moved2)
  {
    const int thread = omp_get_thread_num();
    const auto [i0, i1] = kick_range(thread);
    const auto drift = [&](std::size_t i) {
      const Vec3 f = p.force[i], t = p.torque[i];
      if (close_previous)
        closing_kick(i, f, t);
      const double im = 1.0 / p.mass[i], ii = 1.0 / p.inertia[i];
      p.velocity[i] += f * (h * im);
      p.angular_velocity[i] += t * (h * ii);
      p.position[i] += p.velocity[i] * dt_;
      PackedPosition& packed = packed_position_[i];
      packed.x = p.position[i].x;
      packed.y = p.position[i].y;
      packed.z = p.position[i].z;
      pack_motion(i);
      // The force is used; it restarts from gravity for this step's evaluation.
      p.force[i] = gravity * p.mass[i];
      p.torque[i] = {};
      const double v2 = meshes::norm2(p.velocity[i]);
      if (!(v2 <= vmax2)) { // also catches NaN
        if (error_particle_[thread] < 0 || long(i) < error_particle_[thread]) {
          error_particle_[thread] = long(i);
          error_kind_[thread] = std::isfinite(v2) ? too_fast : not_finite;
        }
      }
      max_moved2 = std::max(max_moved2, meshes::norm2(p.position[i] - reference_position_[i]));
    };
    if (clumps_.empty()) {
      for (std::size_t i = i0; i < i1; ++i)
        drift(i);
    } else {
      // Members move with their bodies (drift_clumps), the free spheres as before.
      for (std::size_t i = i0; i < i1; ++i)
        if (body_of_slot_[i] < 0)
          drift(i);
      drift_clumps(thread, close_previous, max_moved2);
    }
  }
  if (close_previous) {
    time_ += dt_;
    ++n_steps_;
  }
  bool need_rebuild = max_moved2 > trigger;
  if (has_moving_walls()) {
    // A wall candidate stays valid while the particle and the wall together moved less than
    // the half skin that find_wall_candidates() added to the reach.
    move_walls(time_ + dt_);
    const double shift = wall_displacement();
    need_rebuild = need_rebuild || std::sqrt(max_moved2) + shift > 0.5 * skin_;
  }
  for (int t = 0; t < n_threads_; ++t)
    if (error_kind_[t] != no_error)
      check_particles_or_throw("in the drift");
  const double t_drift = omp_get_wtime();
  phase_times_.integration += t_drift - t_begin;
  if (rank_link_) {
    ranked_forces(need_rebuild, t_drift);
    gather_clump_forces();
  } else {
    if (need_rebuild) {
      rebuild(true);
      phase_times_.rebuild += omp_get_wtime() - t_drift;
    } else {
      refresh_ghosts();
      phase_times_.integration += omp_get_wtime() - t_drift;
    }
    compute_forces();
    gather_clump_forces();
  }
  for (int t = 0; t < n_threads_; ++t)
    if (error_kind_[t] != no_error)
      check_particles_or_throw("in the force computation");
}

void System::close_step() {
  auto& p = particles;
  const double t_begin = omp_get_wtime();
#pragma omp parallel num_threads(n_threads_)
  {
    const int thread = omp_get_thread_num();
    const auto [i0, i1] = kick_range(thread);
    if (clumps_.empty()) {
      for (std::size_t i = i0; i < i1; ++i)
        closing_kick(i, p.force[i], p.torque[i]);
    } else {
      for (std::size_t i = i0; i < i1; ++i)
        if (body_of_slot_[i] < 0)
          closing_kick(i, p.force[i], p.torque[i]);
      close_clumps(thread);
    }
  }
  phase_times_.integration += omp_get_wtime() - t_begin;
  time_ += dt_;
  ++n_steps_;
}

std::pair<std::size_t, std::size_t> System::kick_range(int thread) const {
  const std::size_t n = particles.n_real;
  return {n * thread / n_threads_, n * (thread + 1) / n_threads_};
}

void System::closing_kick(std::size_t i, const Vec3& f, const Vec3& t) {
  // One expression for step() and the fused pass of run(): they stay bitwise identical.
  // The reciprocals as the drift takes them: inlined into advance(), the two passes share
  // one division each.
  auto& p = particles;
  const double h = 0.5 * dt_;
  p.velocity[i] += f * (h * (1.0 / p.mass[i]));
  p.angular_velocity[i] += t * (h * (1.0 / p.inertia[i]));
}

void System::compute_forces() {
  auto& p = particles;
  std::size_t n_contacts = 0;
  const double t_begin = omp_get_wtime();
  // One region, no barrier inside: every thread adds to its own arrays only.
#pragma omp parallel num_threads(n_threads_) reduction(+ : n_contacts)
  {
    const int thread = omp_get_thread_num();
    Vec3* F = p.force.data();
    Vec3* T = p.torque.data();
    const double t0 = omp_get_wtime();
    n_contacts += pair_forces(thread, F, T);
    const double t1 = omp_get_wtime();
    wall_forces(thread, F, T);
    thread_pair_seconds_[thread] = t1 - t0;
    thread_wall_seconds_[thread] = omp_get_wtime() - t1;
  }
  const double region = omp_get_wtime() - t_begin;
  apply_foreign_forces();
  n_pair_contacts_ = n_contacts;
  for (int t = 0; t < n_threads_; ++t) {
    phase_times_.pair += thread_pair_seconds_[t] / n_threads_;
    phase_times_.wall += thread_wall_seconds_[t] / n_threads_;
    phase_times_.wait += (region - thread_pair_seconds_[t] - thread_wall_seconds_[t]) / n_threads_;
  }
  ++phase_times_.n_steps;
}

void System::apply_foreign_forces() {
  auto& p = particles;
  for (auto& t : foreign_) {
    for (std::size_t k = 0; k < t.n; ++k) {
      p.force[t.target[k]] += t.force[k];
      p.torque[t.target[k]] += t.torque[k];
    }
    t.n = 0;
  }
}

void System::reset_forces() {
  auto& p = particles;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    // A member's force holds its contacts only; gravity acts on its body.
    p.force[i] = clumps_.empty() || body_of_slot_[i] < 0 ? settings.gravity * p.mass[i] : Vec3{};
    p.torque[i] = {};
  }
  for (std::size_t b = 0; b < clumps_.size(); ++b) {
    clumps_.force[b] = settings.gravity * clumps_.mass[b];
    clumps_.torque[b] = {};
  }
}

Energy System::energy() const {
  const auto& p = particles;
  Energy e;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    if (!clumps_.empty() && body_of_slot_[i] >= 0)
      continue; // its body's motion is counted below
    e.kinetic += 0.5 * p.mass[i] * meshes::norm2(p.velocity[i]);
    e.rotational += 0.5 * p.inertia[i] * meshes::norm2(p.angular_velocity[i]);
    e.potential -= p.mass[i] * meshes::dot(settings.gravity, p.position[i]);
  }
  for (std::size_t b = 0; b < clumps_.size(); ++b) {
    e.kinetic += 0.5 * clumps_.mass[b] * meshes::norm2(clumps_.velocity[b]);
    e.rotational +=
        rotational_energy(clumps_.orientation[b], clumps_.moments[b], clumps_.angular_momentum[b]);
    e.potential -= clumps_.mass[b] * meshes::dot(settings.gravity, clumps_.position[b]);
  }
  // Hertz elastic energy 8/15 E* sqrt(R*) delta^(5/2), plus the tangential springs.
  for (std::size_t k = 0; k < neighbors_.n_pairs(); ++k) {
    const auto i = neighbors_.pair_i[k], j = neighbors_.pair_j[k];
    const double d = p.radius[i] + p.radius[j] - meshes::norm(p.position[i] - p.position[j]);
    if (d <= 0)
      continue;
    const auto& c = contact_[p.material[i] * n_mat_ + p.material[j]];
    const double r = p.radius[i] * p.radius[j] / (p.radius[i] + p.radius[j]);
    e.elastic += 8.0 / 15.0 * c.e_star * std::sqrt(r) * std::pow(d, 2.5) +
                 4 * c.g_star * std::sqrt(r * d) * meshes::norm2(pair_history_[k]);
  }
  add_wall_elastic_energy(e.elastic);
  return e;
}

double System::bytes_per_particle() const {
  const auto& p = particles;
  const double n = double(std::max<std::size_t>(1, p.n_real));
  const double per_slot = 5 * sizeof(Vec3) + 3 * sizeof(double) + sizeof(int) + 8;
  std::size_t foreign = 0;
  for (const auto& t : foreign_)
    foreign += t.target.size() * (sizeof(std::uint32_t) + 2 * sizeof(Vec3));
  double bytes = (per_slot + sizeof(PackedPosition) + sizeof(PackedMotion)) * p.position.size() +
                 sizeof(Vec3) * reference_position_.size() +
                 sizeof(std::uint32_t) * wall_candidate_offset_.size() +
                 sizeof(FaceBound) * wall_candidate_bound_.size() + double(foreign) +
                 sizeof(WallSlot) * slots_.size();
  return (bytes + sizeof(PairBlock) * pair_block_.size() + double(rebuild_scratch_.bytes())) / n;
}

std::size_t System::RebuildScratch::bytes() const {
  // Capacities, not sizes: the storage is kept between rebuilds.
  const auto of = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  std::size_t b = of(old_histories) + of(old_by_id.bucket) + of(old_by_id.entry) + of(bucket_fill) +
                  of(slots_of_id) + of(wrap) + of(n_candidates) + of(slots) + of(pair_touch) +
                  of(sort_key) + of(sort_perm) + of(gather_vec3) + of(gather_double) +
                  of(gather_int) + of(gather_id) + of(clump_slot_of_id);
  for (const auto& v : chunk_candidates)
    b += of(v);
  return b;
}

void System::set_wall_vertices(int w, const std::vector<Vec3>& vertices) {
  walls_[mesh_index(w, "set_wall_vertices")].set_vertices(vertices);
  if (set_up_) {
    rebuild();
  }
}

void System::replace_wall_mesh(int w, const meshes::SurfaceMesh& mesh) {
  const std::size_t m = mesh_index(w, "replace_wall_mesh");
  const MeshWall& old = walls_[m];
  MeshWall wall(mesh, old.material(), old.motion(), old.wearing(), old.name(),
                old.covered_labels());
  wall.set_rigid_motion(old.rigid_motion());
  wall.move_to(wall_time_);
  walls_[m] = std::move(wall);
  if (!set_up_)
    return;
  walls_[m].build_grid(r_max_ + skin_);
  for (auto& t : wear_acc_)
    if (walls_[m].wearing())
      t[w].assign(n_wear_values * (walls_[m].n_faces() + 1), 0.0);
  rebuild();
}

void WearIntegrals::zero_faces(std::size_t n_faces) {
  impulse.assign(n_faces, {});
  normal_impulse.assign(n_faces, 0);
  archard.assign(n_faces, 0);
  sliding_work.assign(n_faces, 0);
  contact_steps.assign(n_faces, 0);
  normal_moment.assign(n_faces, {});
  impulse_moment.assign(n_faces, {});
  impacts.assign(n_faces, 0);
  impact_energy.assign(n_faces, 0);
  impact_measure.assign(n_faces, 0);
}

WearIntegrals System::wear_integrals(int w) const {
  if (!wall_wearing(w))
    throw std::invalid_argument("wall '" + wall_name(w) + "' is not a wearing wall");
  const std::size_t nf = wall_faces(w);
  WearIntegrals r;
  r.zero_faces(nf);
  for (int t = 0; t < n_threads_; ++t) {
    const auto& a = wear_acc_[t][w];
    for (std::size_t f = 0; f < nf; ++f) {
      const double* v = &a[n_wear_values * f];
      r.impulse[f] += Vec3{v[0], v[1], v[2]};
      r.normal_impulse[f] += v[3];
      r.archard[f] += v[4];
      r.sliding_work[f] += v[5];
      r.contact_steps[f] += v[6];
      r.normal_moment[f] += Vec3{v[7], v[8], v[9]};
      r.impulse_moment[f] += Vec3{v[10], v[11], v[12]};
      r.impacts[f] += v[13];
      r.impact_energy[f] += v[14];
      r.impact_measure[f] += v[15];
    }
    // a wall of one face keeps its totals on that face (add_wear)
    const double* tot = &a[n_wear_values * (nf == 1 ? 0 : nf)];
    r.total_impulse += Vec3{tot[0], tot[1], tot[2]};
    r.total_normal_impulse += tot[3];
    r.total_archard += tot[4];
    r.total_sliding_work += tot[5];
    r.total_normal_moment += Vec3{tot[7], tot[8], tot[9]};
    r.total_impulse_moment += Vec3{tot[10], tot[11], tot[12]};
    r.total_impacts += tot[13];
    r.total_impact_energy += tot[14];
    r.total_impact_measure += tot[15];
  }
  return r;
}

void System::reset_wear_integrals() {
  for (auto& t : wear_acc_)
    for (auto& w : t)
      std::fill(w.begin(), w.end(), 0.0);
}

} // namespace wear::dem
