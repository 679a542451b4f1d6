// Rigid clumps in the engine: members placed by their body's pose, member forces gathered
// onto the body.
//
// A member i of body b at the body-frame offset c_i sits at x_i = x_b + R(q_b) c_i and moves
// with the rigid motion, v_i = v_b + omega_b x (x_i - x_b), spinning at omega_b; its particle
// carries the body's mass, so that a contact's effective mass is that of the bodies that meet.
// The contact forces on the members sum to the body's force and, with their levers about the
// centre of mass, to its torque:
//   F_b = m_b g + sum_i F_i,   T_b = sum_i ((x_i - x_b) x F_i + T_i).
// Pairs of members of one body never touch (the System leaves them out of its pair list).
#include "dem/engine/clumps.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace wear::dem {

void Clumps::add_body(const Vec3& x, const Vec3& v, const Quaternion& q, const Vec3& L, double m,
                      const Vec3& principal_moments, const std::vector<std::int64_t>& ids,
                      const std::vector<Vec3>& offsets) {
  position.push_back(x);
  velocity.push_back(v);
  orientation.push_back(q);
  angular_momentum.push_back(L);
  force.push_back({});
  torque.push_back({});
  mass.push_back(m);
  moments.push_back(principal_moments);
  member_id.insert(member_id.end(), ids.begin(), ids.end());
  member_offset.insert(member_offset.end(), offsets.begin(), offsets.end());
  member_slot.resize(member_id.size(), 0);
  member_begin.push_back(std::uint32_t(member_id.size()));
}

void Clumps::keep_bodies(const std::vector<std::uint8_t>& keep) {
  std::size_t kept = 0, kept_members = 0;
  for (std::size_t b = 0; b < size(); ++b) {
    if (!keep[b])
      continue;
    position[kept] = position[b];
    velocity[kept] = velocity[b];
    orientation[kept] = orientation[b];
    angular_momentum[kept] = angular_momentum[b];
    force[kept] = force[b];
    torque[kept] = torque[b];
    mass[kept] = mass[b];
    moments[kept] = moments[b];
    // Members move down only (kept_members <= member_begin[b]): read before written.
    const std::uint32_t first = member_begin[b], last = member_begin[b + 1];
    member_begin[kept] = std::uint32_t(kept_members);
    for (std::uint32_t k = first; k < last; ++k, ++kept_members) {
      member_id[kept_members] = member_id[k];
      member_offset[kept_members] = member_offset[k];
      member_slot[kept_members] = member_slot[k];
    }
    ++kept;
  }
  for (auto* v : {&position, &velocity, &angular_momentum, &force, &torque, &moments})
    v->resize(kept);
  orientation.resize(kept);
  mass.resize(kept);
  member_begin.resize(kept + 1);
  member_begin[kept] = std::uint32_t(kept_members);
  member_id.resize(kept_members);
  member_offset.resize(kept_members);
  member_slot.resize(kept_members);
}

void ClumpsState::check() const {
  const auto require = [](bool ok, const std::string& what) {
    if (!ok)
      throw std::invalid_argument("DEM state: clumps: " + what);
  };
  const std::size_t n = size();
  for (const std::size_t length :
       {position.size(), velocity.size(), orientation.size(), angular_momentum.size(), force.size(),
        torque.size(), moments.size()})
    require(length == n, "body arrays of different lengths");
  require(member_begin.size() == n + 1 && member_begin.front() == 0 &&
              std::is_sorted(member_begin.begin(), member_begin.end()) &&
              member_begin.back() == member_id.size() && member_offset.size() == member_id.size(),
          "member ranges do not fit the members");
  for (std::size_t b = 0; b < n; ++b) {
    const Quaternion& q = orientation[b];
    require(mass[b] > 0 && moments[b].x > 0 && moments[b].y > 0 && moments[b].z > 0 &&
                member_begin[b + 1] > member_begin[b] &&
                q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z > 0,
            "body " + std::to_string(b) +
                " has a non-positive mass or moment, no member or no orientation");
  }
}

void Clumps::restore(const ClumpsState& s) {
  s.check();
  static_cast<ClumpsState&>(*this) = s;
  member_slot.assign(member_id.size(), 0);
}

void Clumps::index_members(const Particles& p, std::vector<std::int64_t>& slot_of_id,
                           std::vector<std::int32_t>& body_of_slot) {
  // Slot by id, through a table as long as the largest id (ids are dense: never reused).
  std::int64_t bound = 0;
  for (std::size_t i = 0; i < p.n_real; ++i)
    bound = std::max(bound, p.id[i] + 1);
  slot_of_id.assign(std::size_t(bound), -1);
  for (std::size_t i = 0; i < p.n_real; ++i)
    slot_of_id[std::size_t(p.id[i])] = std::int64_t(i);
  body_of_slot.assign(p.n_real, -1);
  for (std::size_t b = 0; b < size(); ++b)
    for (std::uint32_t k = member_begin[b]; k < member_begin[b + 1]; ++k) {
      const std::int64_t id = member_id[k];
      const std::int64_t slot = id >= 0 && id < bound ? slot_of_id[std::size_t(id)] : -1;
      if (slot < 0)
        throw std::logic_error("DEM: member particle " + std::to_string(id) + " of clump " +
                               std::to_string(b) + " is missing");
      member_slot[k] = std::uint32_t(slot);
      body_of_slot[std::size_t(slot)] = std::int32_t(b);
    }
}

void Clumps::order_by_members(std::vector<std::int32_t>& body_of_slot) {
  const std::size_t n = size();
  auto& order = scratch_.order;
  order.resize(n);
  for (std::size_t b = 0; b < n; ++b)
    order[b] = std::uint32_t(b);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return member_slot[member_begin[a]] < member_slot[member_begin[b]];
  });
  // Each array gathered in the new order into the buffer of its type, then swapped in (the
  // buffer keeps the old array's storage for the next time).
  const auto permute = [&](auto& v, auto& buffer) {
    buffer.resize(n);
    for (std::size_t b = 0; b < n; ++b)
      buffer[b] = v[order[b]];
    v.swap(buffer);
  };
  permute(position, scratch_.vec3);
  permute(velocity, scratch_.vec3);
  permute(orientation, scratch_.quaternion);
  permute(angular_momentum, scratch_.vec3);
  permute(force, scratch_.vec3);
  permute(torque, scratch_.vec3);
  permute(mass, scratch_.real);
  permute(moments, scratch_.vec3);
  // The members follow their bodies.
  const std::size_t m = member_id.size();
  scratch_.begin.resize(n + 1);
  scratch_.id.resize(m);
  scratch_.offset.resize(m);
  scratch_.slot.resize(m);
  std::uint32_t next = 0;
  scratch_.begin[0] = 0;
  for (std::size_t b = 0; b < n; ++b) {
    for (std::uint32_t k = member_begin[order[b]]; k < member_begin[order[b] + 1]; ++k, ++next) {
      scratch_.id[next] = member_id[k];
      scratch_.offset[next] = member_offset[k];
      scratch_.slot[next] = member_slot[k];
      body_of_slot[member_slot[k]] = std::int32_t(b);
    }
    scratch_.begin[b + 1] = next;
  }
  member_begin.swap(scratch_.begin);
  member_id.swap(scratch_.id);
  member_offset.swap(scratch_.offset);
  member_slot.swap(scratch_.slot);
}

void Clumps::place_members(std::size_t b, Particles& p) const {
  // The rotation as a matrix (rows r0, r1, r2), built once for the body's members.
  const Quaternion& q = orientation[b];
  const double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z, xy = q.x * q.y, xz = q.x * q.z,
               yz = q.y * q.z, wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  const Vec3 r0{1 - 2 * (yy + zz), 2 * (xy - wz), 2 * (xz + wy)};
  const Vec3 r1{2 * (xy + wz), 1 - 2 * (xx + zz), 2 * (yz - wx)};
  const Vec3 r2{2 * (xz - wy), 2 * (yz + wx), 1 - 2 * (xx + yy)};
  const auto turn = [&](const Vec3& v) {
    return Vec3{meshes::dot(r0, v), meshes::dot(r1, v), meshes::dot(r2, v)};
  };
  const Vec3& L = angular_momentum[b];
  const Vec3 l = r0 * L.x + r1 * L.y + r2 * L.z; // R^T L
  const Vec3 w = turn({l.x / moments[b].x, l.y / moments[b].y, l.z / moments[b].z});
  for (std::uint32_t k = member_begin[b]; k < member_begin[b + 1]; ++k) {
    const std::uint32_t i = member_slot[k];
    const Vec3 arm = turn(member_offset[k]);
    p.position[i] = position[b] + arm;
    p.velocity[i] = velocity[b] + meshes::cross(w, arm);
    p.angular_velocity[i] = w;
  }
}

void Clumps::gather_forces(std::size_t b, const Particles& p) {
  Vec3 f = force[b], t = torque[b];
  for (std::uint32_t k = member_begin[b]; k < member_begin[b + 1]; ++k) {
    const std::uint32_t i = member_slot[k];
    f += p.force[i];
    t += meshes::cross(p.position[i] - position[b], p.force[i]) + p.torque[i];
  }
  force[b] = f;
  torque[b] = t;
}

} // namespace wear::dem
