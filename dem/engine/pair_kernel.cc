// The particle-pair contact kernel (docs/theory.md section 2, law in contact_law.h).
//
// A block of listed pairs goes through three passes:
//   1. distance of every listed pair; the touching ones (|x_i - x_j| < R_i + R_j) are
//      compacted into the block without a branch, and a pair that no longer touches loses
//      its tangential history;
//   2. the Hertz-Mindlin law over the compacted contacts, several per SIMD instruction, with
//      the particle data gathered lane by lane: the law is branch-free, so no lane waits on
//      another's sliding or rolling state;
//   3. scatter of forces, torques and histories in list order.
// Half of the listed pairs do not touch in a dense bed (list skin), and which ones do is not
// predictable: compacting first removes that branch from the arithmetic. The kernel is
// compiled for generic x86-64, x86-64-v3 (AVX2, FMA) and x86-64-v4 (AVX-512); the loader picks
// one for the CPU, so a result is bitwise reproducible on one CPU kind, and differs between
// kinds in the last bits (fused multiply-adds).
#include "dem/engine/pair_kernel.h"

#include "dem/engine/contact_law.h"

#include <cmath>

namespace wear::dem {

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define WEAR_PAIR_KERNEL_CLONES                                                                    \
  __attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#else
#define WEAR_PAIR_KERNEL_CLONES
#endif

namespace {

/// Pass 1: the distance of every listed pair; the touching ones are compacted into the block
/// without a branch, and a pair that no longer touches loses its history. Returns the count.
/// Only a pair that touched at the last evaluation can hold a history (touching[] says which),
/// so the histories are written only where a contact ends, a rare, well predicted branch.
[[gnu::always_inline]] inline int compact_touching(const PairKernelData& d, const std::uint32_t* pi,
                                                   const std::uint32_t* pj, Vec3* history,
                                                   std::uint8_t* touching, int n_listed,
                                                   PairBlock& bl) {
  int m = 0;
  for (int q = 0; q < n_listed; ++q) {
    const PackedPosition& a = d.position[pi[q]];
    const PackedPosition& b = d.position[pj[q]];
    const double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
    const double dist2 = dx * dx + dy * dy + dz * dz, rs = a.r + b.r;
    const bool touch = dist2 < rs * rs;
    bl.pair[m] = std::uint32_t(q);
    bl.dx[m] = dx;
    bl.dy[m] = dy;
    bl.dz[m] = dz;
    bl.dist2[m] = dist2;
    m += touch;
    if (touching[q] > std::uint8_t(touch))
      history[q] = {};
    touching[q] = std::uint8_t(touch);
  }
  return m;
}

/// The geometry of compacted contact c between i and j, gathered lane by lane into g. Every
/// assignment component by component, g written in place: an aggregate copy (of a Vec3, or
/// of g returned by value) defeats the vectoriser.
[[gnu::always_inline]] inline void pair_geometry(const PairKernelData& d, const PairBlock& bl,
                                                 int c, std::uint32_t i, std::uint32_t j,
                                                 ContactGeometry& g) {
  const double ri = d.position[i].r, rj = d.position[j].r, rs = ri + rj;
  const PackedMotion &a = d.motion[i], &b = d.motion[j];
  const double mi = a.mass, mj = b.mass, ms = mi + mj;
  const double dist = std::sqrt(bl.dist2[c]);
  const double inv = 1.0 / dist;
  g.normal.x = bl.dx[c] * inv;
  g.normal.y = bl.dy[c] * inv;
  g.normal.z = bl.dz[c] * inv;
  g.overlap = rs - dist;
  // R* = ri rj / rs and m* = mi mj / ms by one division.
  const double inv_rm = 1.0 / (rs * ms);
  g.r_eff = ri * rj * ms * inv_rm;
  g.m_eff = mi * mj * rs * inv_rm;
  g.arm_i = ri - 0.5 * g.overlap;
  g.arm_j = rj - 0.5 * g.overlap;
  g.lever_i = ri;
  g.lever_j = rj;
  const Vec3 spin = meshes::cross(
      Vec3{a.wx * ri + b.wx * rj, a.wy * ri + b.wy * rj, a.wz * ri + b.wz * rj}, g.normal);
  g.v_contact.x = a.vx - b.vx - spin.x;
  g.v_contact.y = a.vy - b.vy - spin.y;
  g.v_contact.z = a.vz - b.vz - spin.z;
  g.w_relative.x = a.wx - b.wx;
  g.w_relative.y = a.wy - b.wy;
  g.w_relative.z = a.wz - b.wz;
}

/// The law for compacted contact c into the block's lanes. `series_only`: the history's
/// rotation by its series (contact_law.h), the lane marked in bl.redo where that is not the law.
template <bool uniform, bool series_only>
[[gnu::always_inline]] inline void
contact_law_lane(const PairKernelData& d, const std::uint32_t* pi, const std::uint32_t* pj,
                 const Vec3* history, double dt, int c, PairBlock& bl) {
  const std::uint32_t q = bl.pair[c], i = pi[q], j = pj[q];
  ContactGeometry g;
  pair_geometry(d, bl, c, i, j, g);
  ContactParameters cp;
  const ContactParameters& t =
      uniform ? *d.uniform : d.contact[d.material[i] * d.n_materials + d.material[j]];
  cp.e_star = t.e_star;
  cp.g_star = t.g_star;
  cp.beta = t.beta;
  cp.friction = t.friction;
  cp.rolling_friction = t.rolling_friction;
  cp.tangential_damping_ratio = t.tangential_damping_ratio;
  Vec3 h;
  h.x = history[q].x;
  h.y = history[q].y;
  h.z = history[q].z;
  const ContactResult r = hertz_mindlin<series_only>(cp, g, dt, h);
  bl.hx[c] = h.x, bl.hy[c] = h.y, bl.hz[c] = h.z;
  bl.fx[c] = r.force.x, bl.fy[c] = r.force.y, bl.fz[c] = r.force.z;
  bl.tix[c] = r.torque_i.x, bl.tiy[c] = r.torque_i.y, bl.tiz[c] = r.torque_i.z;
  bl.tjx[c] = r.torque_j.x, bl.tjy[c] = r.torque_j.y, bl.tjz[c] = r.torque_j.z;
  bl.redo[c] = series_only && r.rotation_eps >= rotation_series_limit ? 1.0 : 0.0;
}

/// Pass 2: the contact law over the m compacted contacts, several per SIMD instruction;
/// updated histories, forces and torques go into the block's lanes. `uniform`: one pair type
/// for all (d.uniform), loaded once instead of gathered per lane with both materials. The
/// lanes rotate the histories by the series; the rare contact whose normal turned too far for
/// it (a new or a rolling-over contact) is redone one by one with the exact rotation: the
/// exact scale's square root and division left the lanes.
template <bool uniform>
[[gnu::always_inline]] inline void
contact_law_lanes(const PairKernelData& d, const std::uint32_t* pi, const std::uint32_t* pj,
                  const Vec3* history, int m, PairBlock& bl) {
  const double dt = d.dt;
#pragma omp simd
  for (int c = 0; c < m; ++c)
    contact_law_lane<uniform, true>(d, pi, pj, history, dt, c, bl);
  for (int c = 0; c < m; ++c)
    if (bl.redo[c])
      contact_law_lane<uniform, false>(d, pi, pj, history, dt, c, bl);
}

/// Pass 3: histories, forces and torques of the m contacts scattered in list order; a
/// ghost's go to its owner, rotated by +angle; those on a particle another thread owns go to
/// d.foreign. The listed first particle is always this thread's, the second is when it is
/// real and below own_end (a real partner is listed after the first).
[[gnu::always_inline]] inline void scatter(const PairKernelData& d, const std::uint32_t* pi,
                                           const std::uint32_t* pj, Vec3* history, int m,
                                           const PairBlock& bl, Vec3* force, Vec3* torque) {
  const double co = d.cos_angle, si = d.sin_angle;
  ForeignForces& out = *d.foreign;
  if (m == 0)
    return;
  // Pairs are listed by their first particle: i's sums stay in registers while it lasts, not
  // added through memory contact by contact (each add waited on the store before it). A later
  // contact's partner j > i is never the current i.
  std::uint32_t current = pi[bl.pair[0]];
  Vec3 f_current{}, t_current{};
  for (int c = 0; c < m; ++c) {
    const std::uint32_t q = bl.pair[c], i = pi[q], j = pj[q];
    history[q] = {bl.hx[c], bl.hy[c], bl.hz[c]};
    const Vec3 f{bl.fx[c], bl.fy[c], bl.fz[c]};
    const Vec3 tj{bl.tjx[c], bl.tjy[c], bl.tjz[c]};
    if (i != current) {
      force[current] += f_current;
      torque[current] += t_current;
      current = i;
      f_current = {};
      t_current = {};
    }
    f_current += f;
    t_current += Vec3{bl.tix[c], bl.tiy[c], bl.tiz[c]};
    if (j < d.own_end) {
      force[j] -= f;
      torque[j] += tj;
      continue;
    }
    std::uint32_t o = j;
    Vec3 fo = -f, to = tj;
    if (j >= d.n_real) {
      o = d.ghost_owner[j - d.n_real];
      // A select, not a branch: every ghost of one process is an image.
      const bool image = j < d.rotated_end;
      const double c = image ? co : 1.0, s = image ? si : 0.0;
      fo = -Vec3{c * f.x - s * f.y, s * f.x + c * f.y, f.z};
      to = Vec3{c * tj.x - s * tj.y, s * tj.x + c * tj.y, tj.z};
    }
    if (o >= d.own_begin && o < d.own_end) {
      force[o] += fo;
      torque[o] += to;
    } else {
      out.target[out.n] = o;
      out.force[out.n] = fo;
      out.torque[out.n++] = to;
    }
  }
  force[current] += f_current;
  torque[current] += t_current;
}

} // namespace

// The passes are inlined into each instruction-set clone (always_inline): compiled for the
// clone's instruction set, as one function.
WEAR_PAIR_KERNEL_CLONES
int pair_block_forces(const PairKernelData& d, std::size_t k0, int n_listed, PairBlock& bl,
                      Vec3* force, Vec3* torque) {
  const std::uint32_t* pi = d.pair_i + k0;
  const std::uint32_t* pj = d.pair_j + k0;
  Vec3* history = d.history + k0;
  const int m = compact_touching(d, pi, pj, history, d.touching + k0, n_listed, bl);
  if (d.uniform)
    contact_law_lanes<true>(d, pi, pj, history, m, bl);
  else
    contact_law_lanes<false>(d, pi, pj, history, m, bl);
  scatter(d, pi, pj, history, m, bl, force, torque);
  return m;
}

} // namespace wear::dem
