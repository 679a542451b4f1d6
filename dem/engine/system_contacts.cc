// Contact forces of the DEM System: the pairs of the neighbour list and the particle-wall
// contacts, each thread over the particles it owns (split at the last rebuild).
//
// Wall histories are kept in fixed slots per particle and matched by wall and contact normal
// (within about 25 degrees), so sliding across triangle boundaries of a smooth or flat wall
// keeps the history. Contacts of one wall whose normals lie within 25 degrees are merged into
// the deepest: on a finely tessellated concave surface (a worn fillet) each triangle's
// interior is its own distance minimum, and counting them all would stiffen the contact
// several times and overflow the slots; distinct contacts (a particle in a corner between an
// element flank and the base) differ by more. A revolution wall (revolution_wall.h) gives at
// most one contact, at its exact closest point, through the same slots, merge rule and law;
// on a wearing one the contact's integrals go whole to its accounting face under that point.
//
// A junction contact (an edge or vertex where a wall's covered faces meet its uncovered ones,
// MeshWall::contact_ownership) is dropped when another wall has a contact within the merge
// angle at least as deep, to 1e-6 r: on the flush junction of a sample and its holder the
// face under the particle holds it, once. Two junction contacts of different walls keep the
// deeper. Where the worn face has sunk below the holder's rim the rim's junction edge is the
// deeper and holds a particle over the seam, which with no contact there fell through it.
//
// A mesh wall with a rigid motion (rigid_motion.h) is searched in its body frame: the
// particle centre is taken there once per wall, the contact normal back to the world frame;
// the contact point stays on the mesh, where the wall's velocity is evaluated and its wear
// integrals are kept (impulses rotated into the body frame, so a face's load is the face's).
//
// Each thread adds the forces on the particles it owns into their own arrays; a force on a
// particle another thread owns (across the boundary between the threads' ranges, or a ghost's
// owner) is kept aside and added after the evaluation in thread order, so a run is bitwise
// reproducible for a given thread count. Wear integrals are accumulated per thread and summed
// in thread order.
#include "dem/engine/contact_law.h"
#include "dem/engine/pair_kernel.h"
#include "dem/engine/system.h"
#include "meshes/constants.h"
#include "meshes/surface_mesh.h"

#include <algorithm>
#include <cmath>

namespace wear::dem {

namespace {
/// A particle-wall contact found on a candidate face, before merging.
struct Candidate {
  ClosestFeature feature; ///< on the wall's mesh (a moving wall's body frame)
  Vec3 normal;            ///< unit, wall to particle centre (world frame)
  double dist;            ///< [m] centre to closest point
  std::uint32_t wall, face;
  bool junction; ///< on the border of the wall's covered faces (ContactOwnership::junction)
};
constexpr int max_wall_candidates = 32;
/// Contacts of one wall whose normals differ by less than 25 degrees are one contact.
const double cos_merge_angle = std::cos(25.0 * pi / 180.0);
/// [-] Of the radius: a junction contact within this of another wall's counts as level with it.
constexpr double junction_level_tolerance = 1e-6;

/// The System's walls of both kinds, by wall number w (System::wall_kind_, wall_local_).
struct WallTable {
  const WallKind* kind;
  const std::int32_t* local;
  const MeshWall* mesh;
  const RevolutionWall* revolution;
};

/// The contacts of a particle (centre x, radius r) on its candidate faces [b, e), each
/// (wall << 24) | face, into `found`: faces it overlaps whose closest feature it owns, and
/// revolution walls it overlaps (at their exact closest point, feature "face", face 0).
/// `bound` holds the candidates' copied FaceBounds, read in order. Returns their count, or -1
/// when there are more than max_wall_candidates.
[[gnu::always_inline]] inline int find_wall_contacts(const WallTable& walls, const std::uint32_t* b,
                                                     const std::uint32_t* e, const FaceBound* bound,
                                                     const Vec3& x, double r, Candidate* found) {
  int n_found = 0;
  // The particle centre in the frame of the candidate's wall: a moving wall's body frame,
  // taken once per wall (candidates are listed wall by wall).
  std::uint32_t frame_wall = ~0u;
  Vec3 xb = x;
  for (; b != e; ++b, ++bound) {
    const std::uint32_t w = *b >> 24, f = *b & 0xFFFFFFu;
    if (walls.kind[w] == WallKind::revolution) {
      const Vec3 point = walls.revolution[walls.local[w]].closest(x);
      const Vec3 d = x - point;
      const double dist2 = meshes::norm2(d);
      if (dist2 >= r * r || dist2 == 0)
        continue;
      if (n_found == max_wall_candidates)
        return -1;
      const double dist = std::sqrt(dist2);
      found[n_found++] = {{point, Feature::face, 0}, d / dist, dist, w, 0, false};
      continue;
    }
    const MeshWall& wall = walls.mesh[walls.local[w]];
    if (w != frame_wall) {
      frame_wall = w;
      xb = wall.to_body(x);
    }
    if (bound->rejects(xb, r))
      continue;
    const ClosestFeature cf = wall.closest(f, xb);
    const Vec3 d = xb - cf.point;
    const double dist2 = meshes::norm2(d);
    if (dist2 >= r * r || dist2 == 0)
      continue;
    const ContactOwnership own = wall.contact_ownership(f, cf, xb);
    if (own == ContactOwnership::none)
      continue;
    if (n_found == max_wall_candidates)
      return -1;
    const double dist = std::sqrt(dist2);
    const Vec3 normal = wall.moving() ? wall.pose().rotate(d / dist) : d / dist;
    found[n_found++] = {cf, normal, dist, w, f, own == ContactOwnership::junction};
  }
  return n_found;
}

/// True when contact c is merged into another whose normal lies within the merge angle: of
/// the same wall, or a junction contact of another wall, the deeper (on a tie, found first);
/// a junction contact also into a non-junction contact of another wall at least as deep to
/// `level` [m].
[[gnu::always_inline]] inline bool merged_into_another(const Candidate* found, int n_found, int c,
                                                       double level) {
  const Candidate& cand = found[c];
  for (int o = 0; o < n_found; ++o) {
    const Candidate& other = found[o];
    if (o == c || meshes::dot(other.normal, cand.normal) <= cos_merge_angle)
      continue;
    if (other.wall == cand.wall || (cand.junction && other.junction)) {
      if (other.dist < cand.dist || (other.dist == cand.dist && o < c))
        return true;
    } else if (cand.junction && other.dist <= cand.dist + level) {
      return true;
    }
  }
  return false;
}

/// The contact geometry of particle i with a wall (MeshWall or RevolutionWall) at `cand`.
template <class Wall>
[[gnu::always_inline]] inline ContactGeometry
wall_contact_geometry(const Particles& p, std::size_t i, const Wall& wall, const Candidate& cand) {
  const double r = p.radius[i];
  ContactGeometry g;
  g.normal = cand.normal;
  g.overlap = r - cand.dist;
  g.r_eff = r;
  g.m_eff = p.mass[i];
  g.arm_i = cand.dist;
  g.arm_j = 0;
  g.lever_i = r;
  g.v_contact = p.velocity[i] + meshes::cross(p.angular_velocity[i], g.normal * -r) -
                wall.velocity_at(cand.feature.point);
  g.w_relative = p.angular_velocity[i] - wall.angular_velocity_vector();
  return g;
}

/// The faces that take a contact's wear and their shares: on a mesh wall those sharing the
/// contact's feature; on a revolution wall the accounting face under the contact point.
inline int wear_faces(const MeshWall& wall, const Candidate& cand, std::uint32_t* faces,
                      double* shares) {
  return wall.faces_sharing(cand.face, cand.feature, faces, shares, 32);
}
inline int wear_faces(const RevolutionWall& wall, const Candidate& cand, std::uint32_t* faces,
                      double* shares) {
  faces[0] = wall.accounting_face(cand.feature.point);
  shares[0] = 1;
  return 1;
}

/// A vector of the world frame in the wall's frame, where its wear integrals are kept.
inline Vec3 in_wall_frame(const MeshWall& wall, const Vec3& v) {
  return wall.moving() ? wall.pose().rotate_back(v) : v;
}
inline Vec3 in_wall_frame(const RevolutionWall&, const Vec3& v) {
  return v;
}

/// Adds one contact's wear integrals over a step dt to a wearing wall's accumulator `a`: to
/// the faces that take it (wear_faces), by their shares (n_wear_values entries per face:
/// impulse, normal impulse, Archard integral, sliding work, contact-steps, and the first
/// moments at the contact point x_c that place the load on the face: x_c F_n dt and
/// x_c x F dt), and undivided to the totals after the last face.
template <class Wall>
[[gnu::always_inline]] inline void add_wear(std::vector<double>& a, const Wall& wall,
                                            const Candidate& cand, const ContactResult& res,
                                            double dt) {
  std::uint32_t faces[32];
  double shares[32];
  const int n_faces = wear_faces(wall, cand, faces, shares);
  const Vec3 impulse = in_wall_frame(wall, res.force * (-dt));
  const double fn_dt = res.normal_force * dt;
  const double archard = fn_dt * meshes::norm(res.v_tangential);
  const double work = std::abs(meshes::dot(res.tangential_force, res.v_tangential)) * dt;
  const Vec3& x = cand.feature.point;
  const Vec3 normal_moment = x * fn_dt;
  const Vec3 moment = meshes::cross(x, impulse);
  for (int k = 0; k < n_faces; ++k) {
    double* v = &a[n_wear_values * faces[k]];
    const double share = shares[k];
    v[0] += impulse.x * share;
    v[1] += impulse.y * share;
    v[2] += impulse.z * share;
    v[3] += fn_dt * share;
    v[4] += archard * share;
    v[5] += work * share;
    v[6] += share;
    v[7] += normal_moment.x * share;
    v[8] += normal_moment.y * share;
    v[9] += normal_moment.z * share;
    v[10] += moment.x * share;
    v[11] += moment.y * share;
    v[12] += moment.z * share;
  }
  // A wall of one face (an exact surface's accounting face) holds its totals there: the same
  // sums in the same order, by shares of 1 (System::wear_integrals reads them so).
  if (wall.n_faces() == 1)
    return;
  double* tot = &a[n_wear_values * wall.n_faces()];
  tot[0] += impulse.x;
  tot[1] += impulse.y;
  tot[2] += impulse.z;
  tot[3] += fn_dt;
  tot[4] += archard;
  tot[5] += work;
  tot[7] += normal_moment.x;
  tot[8] += normal_moment.y;
  tot[9] += normal_moment.z;
  tot[10] += moment.x;
  tot[11] += moment.y;
  tot[12] += moment.z;
}
/// Books an impact, a contact's first step, to a wearing wall's accumulator `a` when the
/// particle (mass m, diameter d) approaches the wall (v_n above 1e-9 |v|): per face by the shares
/// of add_wear, and undivided to the totals: the count, the normal kinetic energy m v_n^2 / 2 and
/// `measure` of the contact point's relative velocity v (v_n = -v . n, sin alpha = v_n / |v|).
template <class Wall>
inline void add_impact(std::vector<double>& a, const Wall& wall, const Candidate& cand,
                       const ContactGeometry& g, double m, double d, const ImpactMeasure& measure) {
  const double v_n = -meshes::dot(g.v_contact, g.normal), speed = meshes::norm(g.v_contact);
  // Touching without approaching (placed, or sliding on, where the normal's round-off leaves
  // a v_n of 1e-16 |v|): no impact.
  if (!(v_n > 1e-9 * speed))
    return;
  const double energy = 0.5 * m * v_n * v_n;
  const double booked = measure(m, d, speed, v_n / speed);
  std::uint32_t faces[32];
  double shares[32];
  const int n_faces = wear_faces(wall, cand, faces, shares);
  for (int k = 0; k < n_faces; ++k) {
    double* v = &a[n_wear_values * faces[k]];
    v[13] += shares[k];
    v[14] += energy * shares[k];
    v[15] += booked * shares[k];
  }
  if (wall.n_faces() == 1)
    return;
  double* tot = &a[n_wear_values * wall.n_faces()];
  tot[13] += 1;
  tot[14] += energy;
  tot[15] += booked;
}
} // namespace

std::size_t System::pair_forces(int thread, Vec3* F, Vec3* T) {
  auto& p = particles;
  const PairKernelData kernel{
      packed_position_.data(),
      packed_motion_.data(),
      p.material.data(),
      neighbors_.pair_i.data(),
      neighbors_.pair_j.data(),
      contact_.data(),
      n_mat_,
      uniform_material_ >= 0 ? &contact_[std::size_t(uniform_material_) * (n_mat_ + 1)] : nullptr,
      pair_history_.data(),
      pair_touching_.data(),
      ghost_owner_.data(),
      p.n_real,
      p.n_real + n_image_ghosts_,
      std::uint32_t(owner_split_[thread]),
      std::uint32_t(owner_split_[thread + 1]),
      &foreign_[thread],
      cos_t_,
      sin_t_,
      dt_};
  std::size_t n_contacts = 0;
  PairBlock& bl = pair_block_[thread];
  for (std::size_t k0 = pair_split_[thread]; k0 < pair_split_[thread + 1]; k0 += pair_block_size) {
    const std::size_t m = std::min<std::size_t>(pair_block_size, pair_split_[thread + 1] - k0);
    n_contacts += std::size_t(pair_block_forces(kernel, k0, int(m), bl, F, T));
  }
  return n_contacts;
}

inline Vec3 System::carried_wall_history(const WallSlot* old, bool* taken, std::uint32_t wall,
                                         const Vec3& normal, bool& carried) {
  // The old slot of this wall with the closest normal, within about 25 degrees.
  int best = -1;
  double best_dot = 0.9;
  for (int s = 0; s < wall_slots && old[s].wall >= 0; ++s) {
    if (old[s].wall == std::int32_t(wall) && !taken[s]) {
      const double cd = meshes::dot(old[s].normal, normal);
      if (cd > best_dot) {
        best_dot = cd;
        best = s;
      }
    }
  }
  carried = best >= 0;
  if (best < 0)
    return {};
  taken[best] = true;
  return old[best].delta;
}

// The elastic energy of the wall contacts as the force counts them: the same contacts found
// and merged (find_wall_contacts, merged_into_another), at most wall_slots per particle, each
// the Hertz energy 8/15 E* sqrt(r) delta^(5/2) of its overlap. Summing every face's report
// instead counted a contact on a shared edge or vertex once per face that reports it, and the
// contacts the force merges on a tessellated concave surface each.
void System::add_wall_elastic_energy(double& e) const {
  const auto& p = particles;
  Candidate found[max_wall_candidates];
  const WallTable walls{wall_kind_.data(), wall_local_.data(), walls_.data(),
                        revolution_walls_.data()};
  const std::uint32_t* candidates = wall_candidate_.data();
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const auto b = wall_candidate_offset_[i], end = wall_candidate_offset_[i + 1];
    if (b == end)
      continue;
    const int n_found =
        find_wall_contacts(walls, candidates + b, candidates + end,
                           wall_candidate_bound_.data() + b, p.position[i], p.radius[i], found);
    const double level = junction_level_tolerance * p.radius[i];
    int n_kept = 0;
    for (int c = 0; c < n_found && n_kept < wall_slots; ++c) {
      if (merged_into_another(found, n_found, c, level))
        continue;
      ++n_kept;
      const Candidate& cand = found[c];
      const int material = walls.kind[cand.wall] == WallKind::revolution
                               ? walls.revolution[walls.local[cand.wall]].material()
                               : walls.mesh[walls.local[cand.wall]].material();
      const double d = p.radius[i] - cand.dist;
      const auto& k = contact_[p.material[i] * n_mat_ + material];
      e += 8.0 / 15.0 * k.e_star * std::sqrt(p.radius[i]) * std::pow(d, 2.5);
    }
  }
}

void System::wall_forces(int thread, Vec3* F, Vec3* T) {
  const auto& p = particles;
  const double dt = dt_;
  auto& acc = wear_acc_[thread];
  // Scratch of one particle, declared once: default-initialising it per particle cost more
  // than the contacts themselves.
  Candidate found[max_wall_candidates];
  const WallTable walls{wall_kind_.data(), wall_local_.data(), walls_.data(),
                        revolution_walls_.data()};
  std::int32_t new_wall[wall_slots];
  Vec3 new_normal[wall_slots], new_delta[wall_slots];
  for (std::size_t q = wall_split_[thread]; q < wall_split_[thread + 1]; ++q) {
    const std::size_t i = wall_particles_[q];
    const Vec3 x = p.position[i];
    const std::uint32_t* candidates = wall_candidate_.data();
    const int n_found = find_wall_contacts(
        walls, candidates + wall_candidate_offset_[i], candidates + wall_candidate_offset_[i + 1],
        wall_candidate_bound_.data() + wall_candidate_offset_[i], x, p.radius[i], found);
    const double level = junction_level_tolerance * p.radius[i];
    bool overflow = n_found < 0;
    bool taken[wall_slots] = {}; // old slots whose history went to a new contact
    int n_new = 0;
    Vec3 f_sum{}, t_sum{};
    for (int c = 0; c < n_found; ++c) {
      if (merged_into_another(found, n_found, c, level))
        continue;
      if (n_new == wall_slots) {
        overflow = true;
        break;
      }
      const Candidate& cand = found[c];
      // One of the two is the contact's wall; a branch per contact, no virtual call.
      const bool revolution = walls.kind[cand.wall] == WallKind::revolution;
      const MeshWall* mesh = revolution ? nullptr : &walls.mesh[walls.local[cand.wall]];
      const RevolutionWall* rev = revolution ? &walls.revolution[walls.local[cand.wall]] : nullptr;
      const ContactGeometry g = revolution ? wall_contact_geometry(p, i, *rev, cand)
                                           : wall_contact_geometry(p, i, *mesh, cand);
      const int material = revolution ? rev->material() : mesh->material();
      bool carried = false;
      Vec3 delta =
          carried_wall_history(&slots_[wall_slots * q], taken, cand.wall, g.normal, carried);
      const auto res = hertz_mindlin(contact_[p.material[i] * n_mat_ + material], g, dt, delta);
      f_sum += res.force;
      t_sum += res.torque_i;
      new_wall[n_new] = std::int32_t(cand.wall);
      new_normal[n_new] = g.normal;
      new_delta[n_new] = delta;
      ++n_new;
      if (revolution && rev->wearing()) {
        add_wear(acc[cand.wall], *rev, cand, res, dt);
        if (!carried)
          add_impact(acc[cand.wall], *rev, cand, g, p.mass[i], 2 * p.radius[i], settings.impact);
      } else if (!revolution && mesh->wearing()) {
        add_wear(acc[cand.wall], *mesh, cand, res, dt);
        if (!carried)
          add_impact(acc[cand.wall], *mesh, cand, g, p.mass[i], 2 * p.radius[i], settings.impact);
      }
    }
    if (overflow && (error_particle_[thread] < 0 || long(i) < error_particle_[thread])) {
      error_particle_[thread] = long(i);
      error_kind_[thread] = too_many_walls;
    }
    WallSlot* slot = &slots_[wall_slots * q];
    for (int s = 0; s < n_new; ++s)
      slot[s] = {new_normal[s], new_delta[s], new_wall[s]};
    if (n_new < wall_slots)
      slot[n_new].wall = -1;
    F[i] += f_sum;
    T[i] += t_sum;
  }
}

} // namespace wear::dem
