// A scene's DEM run (scene_run.h).
//
// Engine settings follow the DEM subsection's size distribution, not the particles present
// at set-up, since inlets add particles later: time step = Time step fraction x the Rayleigh
// time of the smallest particle, T_R = pi r sqrt(rho / G) / (0.1631 nu + 0.8766); skin =
// half the smallest radius; list reach = the largest radius. Every wall accumulates its
// per-face integrals (engine "wearing" walls), so each gets its force, moment and Archard
// load-distance per window; `Wears` marks the FEM part only. A disc, open cylinder or cone that
// keeps its place and does not wear is an exact surface of revolution (revolution_surface,
// scene_walls.h) of one label, its window integrals summed as totals on one face.
//
// A fill to a bed height (Fill/Bed height) is placed at random up to DEM/Loose factor heights
// above its floor, counted from DEM/Assumed packing, and settles with the walls at rest until
// it is still (settled_mean_speed) or for DEM/Settle time at most, as the tester's bed does.
//
// Time: inlet batches, flux-plane and field samples and outlets act every exchange interval (the
// shortest inlet interval, at most a tenth of the output interval), the engine stepping in between.
// A scene that starts empty sets the engine up at its first particle, its clock starting there.
//
// Node moves (the reference method): scene_node_moves.cc.
//
// The fill region (scene_fill.h) is checked clear of the walls before any particle exists.
// Before that, a Count above what the region holds at the densest packing of spheres is
// refused (require_fill_count_fits): the insertion would try for minutes before giving up.
#include "dem/scene/scene_run.h"

#include "dem/scene/particle_shapes.h"
#include "dem/scene/scene_fill.h"

#include "dem/engine/rank_states.h"

#include "meshes/constants.h"
#include "meshes/solid_region.h"
#include "meshes/triangle_geometry.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace wear::dem {

namespace {

Vec3 vec(const std::vector<double>& v) {
  return scene_vector(v);
}

/// The first triangle of `m` with its label: the accounting face of an exact wall, whose
/// loads are totals.
meshes::SurfaceMesh first_face(const meshes::SurfaceMesh& m) {
  meshes::SurfaceMesh one;
  const auto& t = m.triangles.at(0);
  one.vertices = {m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]};
  one.triangles = {{0, 1, 2}};
  one.face_labels = {m.face_labels.at(0)};
  one.roles = m.roles;
  return one;
}

} // namespace

namespace {

/// Throws when a triangle of a wall cuts the insertion box of `inlet` (shrunk by `margin`
/// [m], so a wall flush with the box's side, where particles at most touch it, passes).
void require_clear_of_walls(const std::vector<SceneWall>& walls, const Inlet& inlet,
                            double margin) {
  const InletSpec& in = inlet.spec();
  const Vec3 e[3] = {meshes::normalized(in.edge_u), meshes::normalized(in.edge_v), inlet.normal()};
  const Vec3 lo{margin, margin, -inlet.depth() + margin},
      hi{meshes::norm(in.edge_u) - margin, meshes::norm(in.edge_v) - margin, -margin};
  const auto local = [&](const Vec3& x) {
    const Vec3 d = x - in.corner;
    return Vec3{meshes::dot(d, e[0]), meshes::dot(d, e[1]), meshes::dot(d, e[2])};
  };
  for (const auto& w : walls) {
    const auto& m = w.surface.mesh;
    for (const auto& t : m.triangles)
      if (meshes::triangle_intersects_box(local(m.vertices[t[0]]), local(m.vertices[t[1]]),
                                          local(m.vertices[t[2]]), lo, hi))
        throw std::invalid_argument("Scene/Inlet " + in.name + ": its insertion box (the " +
                                    "rectangle swept " + std::to_string(inlet.depth()) +
                                    " m upstream) intersects wall '" + w.parameters.name +
                                    "': particles would appear inside it; move the inlet");
  }
}

/// Throws naming `what` when a corner of the box [lo, hi] lies outside the periodic sector
/// 0 <= theta <= angle [rad] (for a sector of at most 180 degrees, which is convex, the box
/// is then inside).
void require_in_sector(const Vec3& lo, const Vec3& hi, double angle, const std::string& what) {
  if (angle > pi)
    return;
  for (int k = 0; k < 8; ++k) {
    const Vec3 x{k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
    const double theta = std::atan2(x.y, x.x);
    const double tolerance = 1e-12 * (1 + std::hypot(x.x, x.y));
    if (std::hypot(x.x, x.y) > tolerance &&
        (x.y < -tolerance || std::sin(angle) * x.x - std::cos(angle) * x.y < -tolerance))
      throw std::invalid_argument(what + " reaches outside the periodic sector 0 <= theta < " +
                                  std::to_string(angle * 180 / pi) +
                                  " deg (Scene/Periodic "
                                  "sector) at (" +
                                  std::to_string(x.x) + ", " + std::to_string(x.y) + ", " +
                                  std::to_string(x.z) + ") m, theta " +
                                  std::to_string(theta * 180 / pi) + " deg");
  }
}

/// Throws naming `what` when the box [lo, hi] reaches outside the scene's periodic slab (none:
/// nothing to check).
void require_in_slab(const SceneParameters& s, const Vec3& lo, const Vec3& hi,
                     const std::string& what) {
  if (s.periodic_direction == "none")
    return;
  const int a = periodic_axis(s);
  if (lo[a] < s.periodic_from || hi[a] > s.periodic_to)
    throw std::invalid_argument(what + " reaches outside the periodic slab " +
                                std::to_string(s.periodic_from) + " <= " + s.periodic_direction +
                                " < " + std::to_string(s.periodic_to) +
                                " m (Scene/Periodic from, to): it spans " + std::to_string(lo[a]) +
                                " .. " + std::to_string(hi[a]) + " m");
}

/// The periodic image of a position nearest an earlier one: shifted by whole periods along a
/// slab's axis, or turned by the sector angle (at most once: a particle moves far less than a
/// sector between two samples); none without a periodic boundary.
NearestImage nearest_image(const SceneParameters& s) {
  if (s.periodic_direction != "none") {
    const int a = periodic_axis(s);
    const double L = s.periodic_to - s.periodic_from;
    return [a, L](const Vec3& previous, const Vec3& current) {
      Vec3 x = current;
      x[a] += L * std::round((previous[a] - current[a]) / L);
      return x;
    };
  }
  if (s.periodic_angle_deg > 0) {
    const double angle = s.periodic_angle_deg * pi / 180;
    return [angle](const Vec3& previous, const Vec3& current) {
      Vec3 best = current;
      for (const double turn : {angle, -angle}) {
        const double c = std::cos(turn), sn = std::sin(turn);
        const Vec3 x{c * current.x - sn * current.y, sn * current.x + c * current.y, current.z};
        if (meshes::norm2(x - previous) < meshes::norm2(best - previous))
          best = x;
      }
      return best;
    };
  }
  return {};
}

} // namespace

SceneRun::SceneRun(const SceneParameters& scene, const DemParameters& dem,
                   std::vector<SceneWall> walls, const ImpactMeasure& impact)
    : scene_(scene), dem_(dem), walls_(std::move(walls)), impact_(impact) {
  validate(scene_);
  validate(dem_);
  particle_shape_ = particle_shape(dem_.particle_shape, "DEM/Particle shape");
  if (scene_.fill.region != "none") {
    auto built = std::make_shared<SceneFillShape>(fill_shape(scene_, dem_.loose_factor));
    // read_case checked a box's or cylinder's count; a mesh region's volume is known now.
    require_fill_count_fits(scene_, dem_.psd, built->solid ? built->solid->volume() : -1);
    built->clearance = particle_shape_ ? 2 * particle_shape_->reach() * dem_.psd.max_diameter() /
                                             particle_shape_->equivalent_diameter()
                                       : dem_.psd.max_diameter();
    require_clear_of_walls(walls_, *built,
                           built->floor_z +
                               (scene_.fill.count == 0 ? scene_.fill.bed_height : built->full_top),
                           scene_.fill.clear_above);
    fill_shape_ = built;
    const SceneFillShape& shape = *fill_shape_;
    if (shape.hi.z > shape.full_top + 1e-12)
      throw std::invalid_argument(
          "Scene/Fill: a bed of " + std::to_string(scene_.fill.bed_height) +
          " m is placed loosely up to DEM/Loose factor = " + std::to_string(dem_.loose_factor) +
          " times its height above the region's floor; lower Loose factor or " +
          (shape.cylinder
               ? "lengthen Axis to at least " + std::to_string(shape.hi.z - shape.floor_z) + " m"
               : "raise Maximum z to at least " + std::to_string(shape.hi.z) + " m"));
    if (scene_.periodic_angle_deg > 0 && shape.sector == 0)
      require_in_sector(shape.lo, shape.hi, scene_.periodic_angle_deg * pi / 180,
                        "Scene/Fill: " + shape.describe());
    require_in_slab(scene_, shape.lo, shape.hi, "Scene/Fill: " + shape.describe());
  }
  // Materials first: the inlets need the particle material's index.
  add_materials_and_walls();
  exchange_ = 0.1 * scene_.output_interval;
  for (std::size_t k = 0; k < scene_.inlets.size(); ++k) {
    const auto& in = scene_.inlets[k];
    InletSpec spec;
    spec.name = in.name;
    spec.corner = vec(in.corner);
    spec.edge_u = vec(in.edge_u);
    spec.edge_v = vec(in.edge_v);
    spec.mass_flow = in.mass_flow;
    spec.velocity = vec(in.velocity);
    spec.start_time = in.start_time;
    if (in.end_time > 0)
      spec.end_time = in.end_time;
    spec.psd = dem_.psd;
    spec.density = dem_.particle.density;
    spec.material = particle_material_;
    spec.seed = dem_.seed + 1000003 * (k + 1); // one stream per inlet, apart from the fill's
    if (particle_shape_)
      spec.shape = std::make_shared<const ClumpShape>(*particle_shape_);
    inlets_.emplace_back(spec);
    require_clear_of_walls(walls_, inlets_.back(), 0.25 * dem_.psd.min_diameter());
    if (scene_.periodic_angle_deg > 0 || scene_.periodic_direction != "none") {
      const Vec3 up = inlets_.back().normal() * -inlets_.back().depth();
      Vec3 lo = spec.corner, hi = spec.corner;
      for (const Vec3& x : {spec.corner + spec.edge_u, spec.corner + spec.edge_v,
                            spec.corner + spec.edge_u + spec.edge_v, spec.corner + up,
                            spec.corner + spec.edge_u + up, spec.corner + spec.edge_v + up,
                            spec.corner + spec.edge_u + spec.edge_v + up})
        for (int d = 0; d < 3; ++d) {
          lo[d] = std::fmin(lo[d], x[d]);
          hi[d] = std::fmax(hi[d], x[d]);
        }
      require_in_sector(lo, hi, scene_.periodic_angle_deg * pi / 180,
                        "Scene/Inlet " + in.name + ": its insertion box");
      require_in_slab(scene_, lo, hi, "Scene/Inlet " + in.name + ": its insertion box");
    }
    exchange_ = std::min(exchange_, inlets_.back().interval());
  }
  for (const auto& out : scene_.outlets)
    outlets_.push_back({out.name, vec(out.minimum), vec(out.maximum), 0, 0});
  for (const auto& f : scene_.flux_planes)
    flux_planes_.emplace_back(f.name, vec(f.point), vec(f.normal));
  const auto& g = scene_.fields;
  if (g.cells != std::vector<int>{0, 0, 0})
    fields_.emplace(
        FieldGrid{vec(g.minimum), vec(g.maximum), {g.cells[0], g.cells[1], g.cells[2]}});
}

void SceneRun::add_materials_and_walls() {
  auto& m = system_.materials;
  particle_material_ = m.add(engine_material("particle", dem_.particle));
  const int wall = m.add(engine_material("walls", dem_.walls));
  const int sample = m.add(engine_material("sample", dem_.sample));
  const int holder = m.add(engine_material("holder", dem_.holder));
  m.set_pair(particle_material_, particle_material_, dem_.particle_particle);
  for (int w : {wall, sample, holder}) {
    m.set_pair(particle_material_, w, dem_.particle_wall);
    for (int other : {wall, sample, holder})
      m.set_pair(w, other, dem_.particle_wall); // walls never meet
  }
  for (const auto& w : walls_) {
    const std::string& name = w.parameters.material;
    const int id = name == "sample" ? sample : name == "holder" ? holder : wall;
    if (const auto surface = revolution_surface(w.parameters)) {
      // Its loads as totals on one face (one label: a disc's, an open cylinder's or cone's):
      // locating each contact among the triangles made a bin's settling 1.6 times slower.
      const meshes::SurfaceMesh one_face = first_face(w.surface.mesh);
      system_.add_wall(RevolutionWall(*surface, id, surface_motion(w.parameters), true,
                                      w.parameters.name, &one_face));
      continue;
    }
    MeshWall mesh_wall(w.surface.mesh, id, surface_motion(w.parameters), true, w.parameters.name,
                       w.covered_labels);
    mesh_wall.set_rigid_motion(rigid_motion(w.parameters));
    system_.add_wall(mesh_wall);
  }
  auto& s = system_.settings;
  s.gravity = vec(scene_.gravity);
  s.domain = {vec(scene_.domain_min), vec(scene_.domain_max)};
  // The engine's spheres are the clumps' members, smaller than the equivalent sphere: their
  // radii set the time step, the skin and the reach.
  const auto [r_min, r_max] = engine_radii();
  const Material particle = engine_material("particle", dem_.particle);
  const double rayleigh = pi * r_min * std::sqrt(particle.density / particle.shear_modulus()) /
                          (0.1631 * particle.poisson_ratio + 0.8766);
  s.time_step = dem_.time_step_fraction * rayleigh;
  s.skin = 0.5 * r_min;
  s.max_radius = r_max;
  if (particle_shape_) { // inlets insert clumps up to the largest diameter later
    const double scale = dem_.psd.max_diameter() / particle_shape_->equivalent_diameter();
    for (const auto& m : particle_shape_->members)
      s.max_overhang = std::max(s.max_overhang, meshes::norm(m.centre) * scale);
  }
  s.max_speed = dem_.max_speed;
  s.impact = impact_;
  if (scene_.periodic_angle_deg > 0)
    s.periodic = {true, scene_.periodic_angle_deg * pi / 180};
  if (scene_.periodic_direction != "none")
    s.periodic_slab = {true, periodic_axis(scene_), scene_.periodic_from, scene_.periodic_to};
}

void SceneRun::setup(const std::function<void(const std::string&)>& progress) {
  const auto say = [&](const std::string& text) {
    if (progress)
      progress(text);
  };
  if (dem_.n_threads > 0)
    omp_set_num_threads(dem_.n_threads); // the engine takes OpenMP's count at its set-up
  fill(progress);
  if (system_.particles.n_real > 0 && !engine_ready()) {
    fit_rank_slabs();
    system_.setup();
    say("set up with " + std::to_string(system_.n_grains_over_ranks()) + " particles");
  }
  time_ = engine_ready() ? system_.time() : 0.0;
}

SceneRunState SceneRun::state() const {
  SceneRunState s;
  s.time = time_;
  s.engine_ready = engine_ready();
  if (s.engine_ready)
    s.system = system_.export_state();
  s.n_removed = n_removed_;
  for (const auto& in : inlets_)
    s.inlets.push_back(in.state());
  for (const auto& o : outlets_) {
    s.outlet_mass.push_back(o.removed_mass);
    s.outlet_counts.push_back(o.n_removed);
  }
  for (const auto& f : flux_planes_)
    s.flux_planes.push_back(f.state(rank_link()));
  if (rank_link())
    s.rank_bounds = slabs_.cuts().bound;
  for (const auto& m : node_moves_)
    s.node_moves.push_back(m.state());
  return s;
}

void SceneRun::resume(const SceneRunState& s) {
  if (s.inlets.size() != inlets_.size() || s.outlet_mass.size() != outlets_.size() ||
      s.outlet_counts.size() != outlets_.size() || s.flux_planes.size() != flux_planes_.size())
    throw std::invalid_argument("scene run: the state has " + std::to_string(s.inlets.size()) +
                                " inlets, " + std::to_string(s.outlet_mass.size()) +
                                " outlets and " + std::to_string(s.flux_planes.size()) +
                                " flux planes; the scene has " + std::to_string(inlets_.size()) +
                                ", " + std::to_string(outlets_.size()) + " and " +
                                std::to_string(flux_planes_.size()));
  if (s.node_moves.size() != node_moves_.size())
    throw std::invalid_argument("scene run: the state moves the nodes of " +
                                std::to_string(s.node_moves.size()) + " walls, the run of " +
                                std::to_string(node_moves_.size()));
  for (std::size_t i = 0; i < node_moves_.size(); ++i) { // before the engine's set-up
    node_moves_[i].resume(s.node_moves[i], system_);
    walls_[std::size_t(node_moves_[i].wall())].surface.mesh = node_moves_[i].deformation().mesh();
  }
  if (dem_.n_threads > 0)
    omp_set_num_threads(dem_.n_threads);
  if (s.engine_ready) {
    // Over ranks a state written by this rank of as many ranks continues bit for bit on the
    // slabs it was written on, its particles added where its last rebuild had them (so that
    // the set-up moves none); a whole bed (merged from another rank count, or one process's)
    // is added on every rank, cut anew, and each rank keeps its slab's part.
    const RankLink* link = rank_link();
    const int rank = link ? link->rank() : 0, n_ranks = link ? link->n_ranks() : 1;
    const bool exact = continues_exactly(s.system, rank, n_ranks);
    const bool own_part = link && exact;
    add_state_particles(system_.particles, s.system, own_part, dem_.particle.density);
    if (!s.system.clumps.empty())
      system_.add_state_clumps(s.system.clumps);
    system_.settings.start_time = s.system.time;
    if (own_part) {
      if (s.rank_bounds.size() != std::size_t(n_ranks) + 1)
        throw std::invalid_argument("scene run: the state of rank " + std::to_string(rank) +
                                    " of " + std::to_string(n_ranks) + " carries " +
                                    std::to_string(s.rank_bounds.size()) + " slab bounds");
      use_rank_slabs(s.rank_bounds);
    } else {
      fit_rank_slabs(cut_balanced_);
    }
    system_.setup();
    if (exact)
      system_.resume_state(s.system);
    else
      system_.import_state(s.system);
  }
  time_ = s.time;
  n_removed_ = s.n_removed;
  for (std::size_t k = 0; k < inlets_.size(); ++k)
    inlets_[k].restore(s.inlets[k]);
  for (std::size_t k = 0; k < outlets_.size(); ++k) {
    outlets_[k].removed_mass = s.outlet_mass[k];
    outlets_[k].n_removed = s.outlet_counts[k];
  }
  for (std::size_t k = 0; k < flux_planes_.size(); ++k)
    flux_planes_[k].restore(s.flux_planes[k]);
}

std::pair<double, double> SceneRun::engine_radii() const {
  const double d_min = dem_.psd.min_diameter(), d_max = dem_.psd.max_diameter();
  if (!particle_shape_)
    return {0.5 * d_min, 0.5 * d_max};
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (const auto& m : particle_shape_->members) {
    lo = std::min(lo, m.radius);
    hi = std::max(hi, m.radius);
  }
  const double d_eq = particle_shape_->equivalent_diameter();
  return {lo * d_min / d_eq, hi * d_max / d_eq};
}

double SceneRun::fill_margin() const {
  return engine_radii().second;
}

void SceneRun::fill(const std::function<void(const std::string&)>& progress) {
  const auto& f = scene_.fill;
  if (f.region == "none")
    return;
  const SceneFillShape& shape = *fill_shape_;
  const double r_max = fill_margin();
  const ClumpShape* clump = particle_shape_ ? &*particle_shape_ : nullptr;
  if (f.count > 0) {
    const FillRegion region = shape.region(r_max, shape.hi.z);
    const std::size_t got =
        clump ? insert_random_clumps(system_, region, dem_.psd, *clump, std::size_t(f.count),
                                     dem_.particle.density, particle_material_, dem_.seed)
              : insert_random(system_.particles, region, dem_.psd, std::size_t(f.count),
                              dem_.particle.density, particle_material_, dem_.seed);
    if (got < f.count)
      throw std::runtime_error("Scene/Fill: only " + std::to_string(got) + " of " +
                               std::to_string(f.count) + " particles fit into " + shape.describe() +
                               "; enlarge it or lower Count");
    return;
  }
  // The bed settles with the surfaces at rest, as a bed poured before the machine starts: a
  // floor or belt moving under it would keep shearing it and the settling might not end.
  for (std::size_t k = 0; k < walls_.size(); ++k)
    system_.set_wall_motion(int(k), WallMotion{});
  const auto report = fill_to_height(
      system_, [&shape, r_max](double z_top) { return shape.region(r_max, z_top); },
      shape.footprint - shape.submerged_volume / f.bed_height, shape.floor_z, f.bed_height,
      dem_.psd, dem_.particle.density, particle_material_, dem_.seed, dem_.loose_factor,
      settled_mean_speed, dem_.settle_time,
      [&](double t) {
        if (progress)
          progress("settling the fill: t = " + std::to_string(t) + " s");
      },
      dem_.assumed_packing, [this] { fit_rank_slabs(); }, clump);
  for (std::size_t k = 0; k < walls_.size(); ++k)
    system_.set_wall_motion(int(k), surface_motion(walls_[k].parameters));
  if (progress)
    progress("filled: " +
             (clump ? std::to_string(system_.clumps().size()) + " clumps of '" + clump->name +
                          "' (" + std::to_string(report.n_particles) + " member spheres)"
                    : std::to_string(report.n_particles) + " particles") +
             ", bed " + std::to_string(report.bed_height) + " m, settled in " +
             std::to_string(report.settle_time) + " s");
}

void SceneRun::exchange() {
  bool set_up = engine_ready();
  RankLink* link = rank_link();
  Particles near;
  for (auto& inlet : inlets_) {
    if (link && set_up) { // every rank's particles near the box, so that all draw one batch
      const auto& p = system_.particles;
      near = gather_particles(p, link, GatherTo::every_rank,
                              [&](std::size_t i) { return inlet.may_touch(p.position[i]); });
    }
    auto batch = inlet.batch(time_, link && set_up ? near : system_.particles);
    if (batch.empty())
      continue;
    if (set_up) {
      system_.insert_particles(batch);
      continue;
    }
    for (const auto& q : batch) {
      if (q.shape) {
        system_.add_clump(q.shape->scaled(2 * q.radius / q.shape->equivalent_diameter()), q.density,
                          q.material, q.position, q.orientation, q.velocity, q.angular_velocity);
        continue;
      }
      system_.particles.add(q.position, q.velocity, q.radius, q.density, q.material);
      system_.particles.angular_velocity.back() = q.angular_velocity;
    }
  }
  if (!set_up && system_.particles.n_real > 0) {
    system_.settings.start_time = time_;
    fit_rank_slabs();
    system_.setup();
    set_up = true;
  }
  if (!set_up)
    return;
  for (auto& plane : flux_planes_) // before the outlets: a particle that crossed is counted
    plane.sample(system_.particles, nearest_image(scene_), link);
  if (fields_)
    fields_->sample(system_.particles);
  n_removed_ += apply_outlets(system_, outlets_);
}

const std::vector<int>& SceneRun::accounting_labels(std::size_t k) const {
  return system_.wall_kind(int(k)) == WallKind::revolution
             ? system_.revolution_wall(int(k)).accounting()->mesh().face_labels
             : walls_[k].surface.mesh.face_labels;
}

SceneWindow SceneRun::advance(double t_end) {
  SceneWindow w;
  w.t_begin = time_;
  bool set_up = engine_ready();
  const auto begin_integrals = [this] {
    system_.reset_wear_integrals();
    for (auto& m : node_moves_)
      m.begin_window();
  };
  if (set_up)
    begin_integrals();
  double accounted_from = time_;
  while (time_ < t_end - 1e-9 * exchange_) {
    const bool was_set_up = set_up;
    exchange();
    set_up = engine_ready();
    if (set_up && !was_set_up) {
      begin_integrals();
      accounted_from = time_;
    }
    const double next = std::min(t_end, time_ + exchange_);
    if (set_up) {
      run_steps(std::max<std::uint64_t>(
          1, std::uint64_t(std::llround((next - time_) / system_.time_step()))));
      time_ = system_.time();
    } else {
      time_ = next;
    }
  }
  if (set_up && !node_moves_.empty() && system_.n_steps() % node_moves_.front().every() != 0)
    move_nodes(); // the window's last wear, so that its moves add up to the window's volume
  w.t_end = time_;
  const auto& p = system_.particles;
  RankLink* link = rank_link();
  w.n_particles = set_up ? system_.n_grains_over_ranks() : 0;
  for (const auto& in : inlets_) {
    const auto s = in.state();
    w.n_inserted += s.n_inserted;
    w.inserted_mass += s.inserted_mass;
  }
  w.n_removed = n_removed_;
  for (const auto& o : outlets_)
    w.outlet_mass.push_back(o.removed_mass);
  for (const auto& f : flux_planes_)
    w.flux_mass.push_back(f.net_mass());
  const double duration = time_ - accounted_from;
  w.integrated = duration;
  if (fields_) {
    w.fields = fields_->window(link);
    fields_->reset();
  }
  w.walls.resize(walls_.size());
  if (set_up && duration > 0)
    for (std::size_t k = 0; k < walls_.size(); ++k) {
      WearIntegrals wi = system_.wear_integrals_over_ranks(int(k));
      auto& loads = w.walls[k];
      loads.force = wi.total_impulse / duration;
      loads.torque = wi.total_impulse_moment / duration;
      loads.archard = wi.total_archard;
      const auto& labels = accounting_labels(k);
      for (std::size_t f = 0; f < labels.size(); ++f)
        loads.archard_label[labels[f]] += wi.archard[f];
      if (walls_[k].parameters.wears)
        w.wearing.emplace(k, std::move(wi)); // the part's loads are made of it
    }
  if (set_up && w.n_particles > 0) {
    // Over the engine's spheres (a clump's members each once).
    double sum[2] = {0, double(p.n_real)}; // [m/s], [-]
    for (std::size_t i = 0; i < p.n_real; ++i) {
      const double v = meshes::norm(p.velocity[i]);
      sum[0] += v;
      w.max_speed = std::max(w.max_speed, v);
    }
    if (link) {
      link->sum_in_rank_order(sum, 2);
      link->max_over_ranks(&w.max_speed, 1);
    }
    w.mean_speed = sum[0] / sum[1];
  }
  return w;
}

WallLoads SceneRun::wall_loads(std::size_t k, const WearLaw& law, const SceneWindow& w) const {
  const auto at = w.wearing.find(k);
  if (at == w.wearing.end())
    throw std::logic_error("SceneRun::wall_loads: the window holds no integrals of wall '" +
                           walls_.at(k).parameters.name + "'");
  const WearIntegrals& integrals = at->second;
  return dem::wall_loads(integrals, law.removed_volume(integrals), walls_.at(k).surface.mesh,
                         w.integrated, load_spreading(dem_.wall_loads, dem_.psd),
                         impact_part(law, integrals));
}

PushReport SceneRun::replace_wall_surface(std::size_t k, const meshes::SurfaceMesh& mesh,
                                          double push_tolerance) {
  if (node_moves(k))
    throw std::logic_error("SceneRun::replace_wall_surface: wall '" + walls_.at(k).parameters.name +
                           "' moves its own nodes");
  const PushReport pushed = system_.push_out_of_wall(int(k), mesh, push_tolerance);
  system_.replace_wall_mesh(int(k), mesh);
  walls_.at(k).surface.mesh = mesh;
  return pushed;
}

} // namespace wear::dem
