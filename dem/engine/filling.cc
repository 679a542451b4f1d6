// Filling. Random sequential insertion: candidate centres uniform in the region's bounding
// box, accepted when inside the region and not overlapping any particle (checked through a
// hash grid with cells of the largest diameter). Diameters are drawn from the number
// fractions n_k ~ f_k / d_k^3 of the mass fractions. A fixed-seed mt19937_64 makes the fill
// reproducible. Filling to a height: N = 0.6 A h / mean particle volume, inserted loosely,
// then settled under gravity; the bed height is the mean top-layer centre height plus a
// radius, the packing fraction is counted in the bed core by particle centres.
// Over ranks (System::set_rank_link) every rank inserts the same bed from the same seed and
// keeps its slab's particles at setup, so the bed is the same whatever the rank count; the
// settling test and the bed's figures are taken over all ranks.
#include "dem/engine/filling.h"

#include "dem/engine/insertion_grid.h"
#include "dem/engine/system.h"
#include "meshes/constants.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

namespace wear::dem {

void SizeDistribution::validate() const {
  if (diameters.empty() || diameters.size() != mass_fractions.size())
    throw std::invalid_argument("DEM/Size distribution: need as many mass fractions as diameters");
  double sum = 0;
  for (std::size_t k = 0; k < diameters.size(); ++k) {
    if (!(diameters[k] > 0) || diameters[k] > 1)
      throw std::invalid_argument("DEM/Size distribution: diameter " + std::to_string(k + 1) +
                                  " must lie in (0, 1] m, got " + std::to_string(diameters[k]));
    if (!(mass_fractions[k] >= 0))
      throw std::invalid_argument("DEM/Size distribution: mass fraction " + std::to_string(k + 1) +
                                  " is negative");
    sum += mass_fractions[k];
  }
  if (std::abs(sum - 1) > 1e-6)
    throw std::invalid_argument("DEM/Size distribution: mass fractions sum to " +
                                std::to_string(sum) + ", not 1");
  if (!(scaling_factor > 0))
    throw std::invalid_argument("DEM/Scaling factor must be positive");
}

std::vector<double> SizeDistribution::number_fractions() const {
  std::vector<double> n(diameters.size());
  for (std::size_t k = 0; k < n.size(); ++k)
    n[k] = mass_fractions[k] / std::pow(diameters[k], 3);
  const double s = std::accumulate(n.begin(), n.end(), 0.0);
  for (auto& x : n)
    x /= s;
  return n;
}

double SizeDistribution::mean_diameter() const {
  const auto n = number_fractions();
  double d = 0;
  for (std::size_t k = 0; k < n.size(); ++k)
    d += n[k] * diameters[k] * scaling_factor;
  return d;
}

double SizeDistribution::min_diameter() const {
  return scaling_factor * *std::min_element(diameters.begin(), diameters.end());
}
double SizeDistribution::max_diameter() const {
  return scaling_factor * *std::max_element(diameters.begin(), diameters.end());
}

FillRegion box_region(const Vec3& lo, const Vec3& hi, double m) {
  const Vec3 a = lo + Vec3{m, m, m}, b = hi - Vec3{m, m, m};
  return {a, b, [a, b](const Vec3& x) {
            return x.x >= a.x && x.y >= a.y && x.z >= a.z && x.x <= b.x && x.y <= b.y && x.z <= b.z;
          }};
}

FillRegion annular_sector_region(double r_in, double r_out, double angle, double z_lo, double z_hi,
                                 double m) {
  const double ri = r_in + m, ro = r_out - m, zl = z_lo + m, zh = z_hi - m;
  return {{-ro, -ro, zl}, {ro, ro, zh}, [=](const Vec3& x) {
            const double r = std::hypot(x.x, x.y);
            if (r < ri || r > ro || x.z < zl || x.z > zh)
              return false;
            double th = std::atan2(x.y, x.x);
            if (th < 0)
              th += 2 * pi;
            // keep the margin from both cut planes as an arc length at this radius
            return th * r >= m && (angle - th) * r >= m;
          }};
}

namespace {
/// The n diameters to place [m, at s = 1], fixed before placing: counts from the number
/// fractions (rounded, the remainder carried to the next size), in a random order. Redrawing
/// a diameter after a failed placement would favour small particles and skew the size
/// distribution.
std::vector<double> diameters_to_place(const SizeDistribution& psd, std::size_t n,
                                       std::mt19937_64& rng) {
  const auto frac = psd.number_fractions();
  std::vector<double> diameters;
  diameters.reserve(n);
  double carried = 0;
  for (std::size_t k = 0; k < frac.size(); ++k) {
    const double exact = frac[k] * double(n) + carried;
    const auto count = static_cast<std::size_t>(std::llround(exact));
    carried = exact - double(count);
    diameters.insert(diameters.end(), std::min(count, n - diameters.size()), psd.diameters[k]);
  }
  diameters.resize(n, psd.diameters.back());
  std::shuffle(diameters.begin(), diameters.end(), rng);
  return diameters;
}
} // namespace

std::size_t insert_random(Particles& p, const FillRegion& region, const SizeDistribution& psd,
                          std::size_t n, double density, int material, std::uint64_t seed,
                          std::size_t max_attempts) {
  psd.validate();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(region.lo.x, region.hi.x), uy(region.lo.y, region.hi.y),
      uz(region.lo.z, region.hi.z);
  InsertionGrid grid(p, psd.max_diameter());
  const std::vector<double> diameters = diameters_to_place(psd, n, rng);
  std::size_t added = 0, fails = 0;
  while (added < n && fails < max_attempts) {
    const double r = 0.5 * diameters[added] * psd.scaling_factor;
    const Vec3 x{ux(rng), uy(rng), uz(rng)};
    if (!region.inside(x) || grid.overlaps(p, x, r)) {
      ++fails;
      continue;
    }
    fails = 0;
    grid.add(x, std::uint32_t(p.n_real));
    p.add(x, {}, r, density, material);
    ++added;
  }
  return added;
}

std::size_t insert_random_clumps(System& system, const FillRegion& region,
                                 const SizeDistribution& psd, const ClumpShape& shape,
                                 std::size_t n, double density, int material, std::uint64_t seed,
                                 std::size_t max_attempts) {
  psd.validate();
  if (shape.members.empty() || !(shape.volume > 0))
    throw std::invalid_argument("DEM: clump shape '" + shape.name + "' has no members");
  Particles& p = system.particles;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(region.lo.x, region.hi.x), uy(region.lo.y, region.hi.y),
      uz(region.lo.z, region.hi.z), u01(0, 1);
  // Cells of the largest member diameter at the largest scale: a member's overlaps lie in
  // its own cell and the 26 around it.
  double r_member = 0;
  for (const auto& m : shape.members)
    r_member = std::max(r_member, m.radius);
  const double largest_scale = psd.max_diameter() / shape.equivalent_diameter();
  InsertionGrid grid(p, 2 * r_member * largest_scale);
  const std::vector<double> diameters = diameters_to_place(psd, n, rng);
  std::vector<Vec3> placed(shape.members.size());
  std::size_t added = 0, fails = 0;
  while (added < n && fails < max_attempts) {
    const double scale = diameters[added] * psd.scaling_factor / shape.equivalent_diameter();
    const Vec3 x{ux(rng), uy(rng), uz(rng)};
    // A uniform random rotation (Shoemake 1992).
    const double u1 = u01(rng), u2 = 2 * pi * u01(rng), u3 = 2 * pi * u01(rng);
    const Quaternion q{std::sqrt(u1) * std::cos(u3), std::sqrt(1 - u1) * std::sin(u2),
                       std::sqrt(1 - u1) * std::cos(u2), std::sqrt(u1) * std::sin(u3)};
    bool clear = true;
    for (std::size_t k = 0; k < shape.members.size() && clear; ++k) {
      placed[k] = x + rotate(q, shape.members[k].centre * scale);
      clear =
          region.inside(placed[k]) && !grid.overlaps(p, placed[k], shape.members[k].radius * scale);
    }
    if (!clear) {
      ++fails;
      continue;
    }
    fails = 0;
    const std::size_t first = p.n_real;
    system.add_clump(shape.scaled(scale), density, material, x, q);
    for (std::size_t k = 0; k < shape.members.size(); ++k)
      grid.add(p.position[first + k], std::uint32_t(first + k));
    ++added;
  }
  return added;
}

std::size_t insert_lattice(Particles& p, const FillRegion& region, double a, double diameter,
                           double density, int material, double jitter, std::uint64_t seed,
                           std::size_t max_n) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::size_t added = 0;
  const long i0 = long(std::floor(region.lo.x / a)) - 1, i1 = long(std::ceil(region.hi.x / a)) + 1;
  const long j0 = long(std::floor(region.lo.y / a)) - 1, j1 = long(std::ceil(region.hi.y / a)) + 1;
  const long k0 = long(std::floor(region.lo.z / a)) - 1, k1 = long(std::ceil(region.hi.z / a)) + 1;
  for (long k = k0; k <= k1; ++k)
    for (long j = j0; j <= j1; ++j)
      for (long i = i0; i <= i1 && added < max_n; ++i) {
        const Vec3 x{(i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a};
        if (!region.inside(x))
          continue;
        p.add(x + Vec3{u(rng), u(rng), u(rng)}, {}, 0.5 * diameter, density, material);
        ++added;
      }
  return added;
}

double packing_fraction(const Particles& p, double area, double z_lo, double z_hi) {
  double v = 0;
  for (std::size_t i = 0; i < p.n_real; ++i)
    if (p.position[i].z >= z_lo && p.position[i].z < z_hi)
      v += 4.0 / 3.0 * pi * std::pow(p.radius[i], 3);
  return v / (area * (z_hi - z_lo));
}

FillReport fill_to_height(System& system, const std::function<FillRegion(double)>& make_region,
                          double area, double z_floor, double target_height,
                          const SizeDistribution& psd, double density, int material,
                          std::uint64_t seed, double loose_factor, double speed_tolerance,
                          double max_time, const std::function<void(double)>& on_check,
                          double packing, const std::function<void()>& before_setup,
                          const ClumpShape* shape) {
  psd.validate();
  if (!(target_height > 0))
    throw std::invalid_argument("DEM/Fill height must be positive");
  const auto frac = psd.number_fractions();
  double mean_volume = 0;
  for (std::size_t k = 0; k < frac.size(); ++k)
    mean_volume += frac[k] * pi / 6 * std::pow(psd.diameters[k] * psd.scaling_factor, 3);
  const auto n = static_cast<std::size_t>(packing * area * target_height / mean_volume);
  const FillRegion region = make_region(z_floor + loose_factor * target_height);
  const std::size_t got =
      shape ? insert_random_clumps(system, region, psd, *shape, n, density, material, seed)
            : insert_random(system.particles, region, psd, n, density, material, seed);
  if (got < n)
    throw std::runtime_error("DEM fill: only " + std::to_string(got) + " of " + std::to_string(n) +
                             " particles fit into the insertion region; "
                             "raise the loose factor or lower the fill height");
  if (before_setup)
    before_setup();
  system.setup();
  RankLink* link = system.rank_link(); // over ranks: the figures of the whole bed
  const double check_every = 0.02;
  while (system.time() < max_time) {
    system.run(std::max<std::uint64_t>(1, std::uint64_t(check_every / system.time_step())));
    // Settled when the mean speed is below the tolerance and no particle is still falling
    // (a few late arrivals barely move the mean).
    double v[2] = {0, double(system.particles.n_real)}, v_max = 0;
    for (std::size_t i = 0; i < system.particles.n_real; ++i) {
      const double s = meshes::norm(system.particles.velocity[i]);
      v[0] += s;
      v_max = std::max(v_max, s);
    }
    if (link) {
      link->sum_in_rank_order(v, 2);
      link->max_over_ranks(&v_max, 1);
    }
    if (on_check)
      on_check(system.time());
    if (v[0] / v[1] < speed_tolerance && v_max < 10 * speed_tolerance && system.time() > 0.1)
      break;
  }
  const Particles& p = system.particles;
  std::vector<double> z(p.n_real);
  for (std::size_t i = 0; i < p.n_real; ++i)
    z[i] = p.position[i].z;
  if (link) {
    std::vector<double> mine = std::move(z);
    link->gather_in_rank_order(mine, z);
  }
  std::sort(z.begin(), z.end());
  // Top layer: the highest particles that would cover the area once.
  const double d = psd.max_diameter();
  const auto per_layer =
      std::max<std::size_t>(1, std::size_t(area / (0.866 * d * d))); // hexagonal layer
  double top = 0;
  const std::size_t m = std::min(per_layer, z.size());
  for (std::size_t k = z.size() - m; k < z.size(); ++k)
    top += z[k];
  FillReport r;
  r.n_particles = z.size();
  r.bed_height = top / double(m) + 0.5 * d - z_floor;
  r.packing_fraction = packing_fraction(p, area, z_floor + d, z_floor + r.bed_height - d);
  if (link)
    link->sum_in_rank_order(&r.packing_fraction, 1);
  r.settle_time = system.time();
  return r;
}

} // namespace wear::dem
