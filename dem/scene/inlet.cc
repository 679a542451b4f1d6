// The inlet (inlet.h): a mass flow rate W [kg/s] fed through a rectangle.
//
// Insertion box: the rectangle (corner c, edges u, v, unit normal n = u x v / |u x v| turned
// along the velocity) swept upstream by a depth D = 2 d_max. A particle with the inlet's
// velocity crosses it in dt_b = D / (v . n), the batch interval: the previous batch has left
// the box when the next one comes, so each batch finds it (nearly) empty. The box at the
// requested rate holds a solid fraction phi = W / (rho A (v . n)); random sequential
// placement jams near 0.3, so phi above 0.2 is refused.
//
// Mass: a batch at time t places particles while the inserted mass stays within half a
// particle of W (min(t, t_end) - t_start): the rate is met to one particle over any window.
// Sizes are drawn one by one from the number fractions n_k ~ f_k / d_k^3 (std::mt19937_64,
// seeded); a particle that finds no place after 1000 tries stays first in line for the next
// batch. Positions: uniform in the box shrunk by the radius, clear of the particles of the
// system within the box (plus a diameter) and of the batch's own (InsertionGrid). A clump
// (InletSpec::shape) is placed as the sphere that holds its members, of the shape's reach
// scaled to the drawn equivalent diameter (every length above, d_max included, grows by
// that ratio), and turned by a uniform random rotation (Shoemake 1992) from the same
// generator; its mass is that of its equivalent sphere, as the engine gives the body.
#include "dem/scene/inlet.h"

#include "dem/engine/insertion_grid.h"
#include "meshes/constants.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wear::dem {

namespace {
constexpr int max_tries = 1000;

double sphere_mass(double d, double density) {
  return density * pi / 6 * d * d * d;
}
} // namespace

Inlet::Inlet(InletSpec spec) : spec_(std::move(spec)), rng_(spec_.seed) {
  const std::string what = "Scene/Inlet " + spec_.name;
  spec_.psd.validate();
  const Vec3 n = meshes::cross(spec_.edge_u, spec_.edge_v);
  const double area = meshes::norm(n);
  if (!(area > 0))
    throw std::invalid_argument(what + ": Edge u and Edge v span no area");
  normal_ = n / area;
  if (std::abs(meshes::dot(spec_.edge_u, spec_.edge_v)) >
      1e-9 * meshes::norm(spec_.edge_u) * meshes::norm(spec_.edge_v))
    throw std::invalid_argument(what + ": Edge u and Edge v must be perpendicular (a rectangle)");
  normal_speed_ = meshes::dot(spec_.velocity, normal_);
  if (normal_speed_ < 0) {
    normal_ = normal_ * -1.0;
    normal_speed_ = -normal_speed_;
  }
  if (!(normal_speed_ > 1e-3 * meshes::norm(spec_.velocity)) || !(normal_speed_ > 0))
    throw std::invalid_argument(what + ": Velocity must cross the inlet rectangle (it is " +
                                "parallel to it or zero)");
  if (!(spec_.mass_flow > 0) || !std::isfinite(spec_.mass_flow))
    throw std::invalid_argument(what + ": Mass flow rate must be positive [kg/s]");
  if (!(spec_.density > 0))
    throw std::invalid_argument(what + ": the particle density must be positive");
  if (!(spec_.end_time > spec_.start_time))
    throw std::invalid_argument(what + ": End time must lie after Start time");
  if (spec_.shape && (spec_.shape->members.empty() || !(spec_.shape->volume > 0)))
    throw std::invalid_argument(what + ": the clump shape '" + spec_.shape->name +
                                "' has no members");
  depth_ = 2 * reach_ratio() * spec_.psd.max_diameter();
  const double edge = std::min(meshes::norm(spec_.edge_u), meshes::norm(spec_.edge_v));
  if (edge < depth_)
    throw std::invalid_argument(what + ": the rectangle is narrower than two of the largest "
                                       "particles");
  const double phi = box_solid_fraction();
  if (phi > 0.2) {
    std::ostringstream s;
    s << what << ": " << spec_.mass_flow << " kg/s through " << area << " m^2 at " << normal_speed_
      << " m/s fills the insertion box to a solid fraction of " << phi
      << "; random placement needs it below 0.2: raise the speed across the inlet or its "
         "area";
    throw std::invalid_argument(s.str());
  }
  const auto frac = spec_.psd.number_fractions();
  double sum = 0;
  for (double f : frac)
    cumulative_.push_back(sum += f);
}

double Inlet::box_solid_fraction() const {
  const double area = meshes::norm(meshes::cross(spec_.edge_u, spec_.edge_v));
  return spec_.mass_flow / (spec_.density * area * normal_speed_);
}

double Inlet::reach_ratio() const {
  return spec_.shape ? 2 * spec_.shape->reach() / spec_.shape->equivalent_diameter() : 1.0;
}

double Inlet::owed_mass(double t) const {
  const double running = std::max(0.0, std::min(t, spec_.end_time) - spec_.start_time);
  return spec_.mass_flow * running - done_.inserted_mass;
}

double Inlet::next_diameter() {
  if (done_.pending.empty()) {
    const double u = std::uniform_real_distribution<double>(0, 1)(rng_);
    std::size_t k = 0;
    while (k + 1 < cumulative_.size() && u >= cumulative_[k])
      ++k;
    done_.pending.push_back(spec_.psd.diameters[k] * spec_.psd.scaling_factor);
  }
  return done_.pending.front();
}

std::vector<NewParticle> Inlet::batch(double t, const Particles& existing) {
  std::vector<NewParticle> out;
  if (t < spec_.start_time)
    return out;
  const double d_max = spec_.psd.max_diameter() * reach_ratio();
  // The particles of the system that may touch the box, and the batch's own, in one set.
  Particles near;
  const Vec3 u = spec_.edge_u, v = spec_.edge_v, back = normal_ * -depth_;
  const double uu = meshes::dot(u, u), vv = meshes::dot(v, v);
  for (std::size_t i = 0; i < existing.n_real; ++i)
    if (may_touch(existing.position[i]))
      near.add(existing.position[i], {}, existing.radius[i], 1, 0);
  InsertionGrid grid(near, d_max);
  std::uniform_real_distribution<double> unit(0, 1);
  const double target = owed_mass(t) + done_.inserted_mass;
  while (true) {
    const double d = next_diameter(), m = sphere_mass(d, spec_.density);
    const double r = 0.5 * d * reach_ratio(); // the sphere that holds a clump's members
    if (done_.inserted_mass + m > target + 0.5 * m)
      break;
    bool placed = false;
    for (int k = 0; k < max_tries && !placed; ++k) {
      // Uniform over the box shrunk by r (the rectangle's edges and both faces of the box).
      const double a = r + (1 - 2 * r / std::sqrt(uu)) * std::sqrt(uu) * unit(rng_);
      const double b = r + (1 - 2 * r / std::sqrt(vv)) * std::sqrt(vv) * unit(rng_);
      const double c = r + (depth_ - 2 * r) * unit(rng_);
      const Vec3 x =
          spec_.corner + u * (a / std::sqrt(uu)) + v * (b / std::sqrt(vv)) + back * (c / depth_);
      if (grid.overlaps(near, x, r))
        continue;
      grid.add(x, std::uint32_t(near.n_real));
      near.add(x, {}, r, 1, 0);
      NewParticle q;
      q.position = x;
      q.velocity = spec_.velocity;
      q.radius = 0.5 * d;
      q.density = spec_.density;
      q.material = spec_.material;
      if (spec_.shape) {
        // A uniform random rotation (Shoemake 1992).
        const double u1 = unit(rng_), u2 = 2 * pi * unit(rng_), u3 = 2 * pi * unit(rng_);
        q.shape = spec_.shape.get();
        q.orientation = {std::sqrt(u1) * std::cos(u3), std::sqrt(1 - u1) * std::sin(u2),
                         std::sqrt(1 - u1) * std::cos(u2), std::sqrt(u1) * std::sin(u3)};
      }
      out.push_back(q);
      placed = true;
    }
    if (!placed)
      break; // it waits, first in line, for the next batch
    done_.pending.erase(done_.pending.begin());
    done_.inserted_mass += m;
    ++done_.n_inserted;
  }
  return out;
}

bool Inlet::may_touch(const Vec3& x) const {
  const double margin = spec_.psd.max_diameter() * reach_ratio();
  const Vec3 d = x - spec_.corner;
  const double lu = meshes::norm(spec_.edge_u), lv = meshes::norm(spec_.edge_v);
  const double a = meshes::dot(d, spec_.edge_u) / lu, b = meshes::dot(d, spec_.edge_v) / lv,
               c = -meshes::dot(d, normal_);
  return a >= -margin && a <= lu + margin && b >= -margin && b <= lv + margin && c >= -margin &&
         c <= depth_ + margin;
}

InletState Inlet::state() const {
  InletState s = done_;
  std::ostringstream o;
  o << rng_;
  s.rng = o.str();
  return s;
}

void Inlet::restore(const InletState& s) {
  done_ = s;
  std::istringstream in(s.rng);
  in >> rng_;
  if (!in)
    throw std::invalid_argument("Scene/Inlet " + spec_.name + ": cannot read the saved state");
}

} // namespace wear::dem
