// Rigid motion of a wall's geometry (rigid_motion.h).
//
//   x(X, t) = p + T(tau) + R(tau) (X - p),  tau = min(max(0, t - t0), t1 - t0),
//   R(tau): rotation by theta = omega tau about the unit axis a (Rodrigues:
//           R = cos theta I + sin theta [a]x + (1 - cos theta) a a^T),
//   T(tau) = v tau + A (sin(2 pi f tau + phi) - sin phi),
//   dT/dt  = v + 2 pi f A cos(2 pi f tau + phi),
//   velocity of the material point at x: dT/dt + omega a x (x - p - T).
// The pose is a function of time only, so a resumed run sees the same walls as the original.
// A point at distance rho from the axis moves by at most |dT| + 2 |sin(d theta / 2)| rho
// between two poses: the bound that keeps the wall-contact candidates valid (system.cc).
#include "dem/engine/rigid_motion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wear::dem {

namespace {
constexpr double two_pi = 6.28318530717958647692;

bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
} // namespace

bool RigidMotion::moves() const {
  return angular_velocity != 0 || velocity != Vec3{} || (amplitude != Vec3{} && frequency > 0);
}

RigidPose pose_at(const RigidMotion& m, double t) {
  RigidPose pose;
  const double tau = std::min(std::max(0.0, t - m.start_time), m.end_time - m.start_time);
  const Vec3 a = meshes::normalized(m.axis);
  const double theta = m.angular_velocity * tau;
  const double c = std::cos(theta), s = std::sin(theta), k = 1 - c;
  pose.row[0] = {c + k * a.x * a.x, k * a.x * a.y - s * a.z, k * a.x * a.z + s * a.y};
  pose.row[1] = {k * a.y * a.x + s * a.z, c + k * a.y * a.y, k * a.y * a.z - s * a.x};
  pose.row[2] = {k * a.z * a.x - s * a.y, k * a.z * a.y + s * a.x, c + k * a.z * a.z};
  pose.angle = theta;
  const double arg = two_pi * m.frequency * tau + m.phase;
  pose.translation = m.velocity * tau + m.amplitude * (std::sin(arg) - std::sin(m.phase));
  pose.centre = m.axis_point + pose.translation;
  pose.offset = pose.centre - pose.rotate(m.axis_point);
  const bool started = t >= m.start_time && t < m.end_time; // moving in [start, end)
  pose.velocity =
      started ? m.velocity + m.amplitude * (two_pi * m.frequency * std::cos(arg)) : Vec3{};
  pose.omega = started ? a * m.angular_velocity : Vec3{};
  return pose;
}

double max_displacement(const RigidPose& a, const RigidPose& b, double axis_reach) {
  return meshes::norm(b.translation - a.translation) +
         2 * std::abs(std::sin(0.5 * (b.angle - a.angle))) * axis_reach;
}

double axis_reach(const RigidMotion& m, const Vec3* first, const Vec3* last) {
  const Vec3 a = meshes::normalized(m.axis);
  double r2 = 0;
  for (; first != last; ++first) {
    const Vec3 d = *first - m.axis_point;
    r2 = std::max(r2, meshes::norm2(d - a * meshes::dot(d, a)));
  }
  return std::sqrt(r2);
}

void validate(const RigidMotion& m, const std::string& what) {
  if (!finite(m.axis_point) || !finite(m.axis) || !finite(m.velocity) || !finite(m.amplitude) ||
      !std::isfinite(m.angular_velocity) || !std::isfinite(m.frequency) ||
      !std::isfinite(m.phase) || !std::isfinite(m.start_time) || std::isnan(m.end_time))
    throw std::invalid_argument(what + ": the motion has a non-finite value");
  if (m.angular_velocity != 0 && meshes::norm(m.axis) == 0)
    throw std::invalid_argument(what + ": a rotation needs a non-zero rotation axis");
  if (!(m.end_time > m.start_time))
    throw std::invalid_argument(what + ": the motion's end time must lie after its start time");
  if (m.frequency < 0)
    throw std::invalid_argument(what + ": the oscillation frequency must not be negative");
  if (m.amplitude != Vec3{} && m.frequency == 0)
    throw std::invalid_argument(what + ": an oscillation amplitude needs a positive frequency");
}

} // namespace wear::dem
