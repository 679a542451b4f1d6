// Assembly and time loop of the circular wear tester in DEM (docs/wear-tester.md).
//
// Frame: z up, the sector 0 <= theta < Theta about the z axis, the bed (floor and both
// cylinders) rotating at +omega about z, the sample fixed at its placement. The floor, the
// cylinders and the consolidator are exact surfaces of revolution (dem::RevolutionWall): the
// floor and cylinders are full circles, so particles slightly beyond a periodic cut between
// list rebuilds still see them; the consolidator is the annular sector of
// meshes::generate_tester_walls. The sample is a triangle-mesh wall.
// The holder (Geometry/Tester/Holder = frame) is a fixed, non-wearing triangle-mesh wall
// (meshes::generate_holder) placed by the sample's own map, so its rim top lies in the wear
// face's plane and its pocket on the sample's sides and bottom. Both walls name those
// coinciding faces covered (MeshWall): where wear face and rim meet, a particle then has one
// contact, with the face under it, as on one flat wall.
// Filling: random insertion from the PSD into an annular sector `loose_factor` times the
// fill height, leaving out the sample and its holder (with a particle diameter of
// clearance) and the space above the consolidator, then settling with the walls at rest.
// The particle count fills the annulus to the fill height at the assumed packing, less the
// holder frame's volume (the frame is submerged; the bare sample's volume stays counted,
// as it always was).
// A revolution is one pass of the bed through the sector, T = Theta / omega, and
// n = round(T / dt) steps.
// The reference deformation moves the sample's nodes every N_update steps by the removed
// volume accumulated since the previous move (times the declared amplification).
// Over ranks (set_rank_link) every rank builds the same tester and inserts the same bed, of
// which it keeps its slab's particles (the same bed whatever the rank count); the wear
// integrals are summed over the ranks in rank order at every evaluation sample and at the end
// of a revolution, and the evaluation samples the particles over the sample gathered from
// every rank, so that every rank holds the same records.
#include "dem/tester/wear_tester.h"

#include "dem/engine/rank_states.h"
#include "meshes/constants.h"

#include "meshes/sample_frame.h"
#include "meshes/sample_generator.h"
#include "meshes/stopwatch.h"
#include "meshes/tester_walls.h"

#include <omp.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace wear::dem {

namespace {

/// Floor, cylinders and the consolidator as revolution walls about z, at rest; returns the
/// walls that turn with the bed (floor, inner, outer).
std::vector<int> add_tester_walls(System& s, const meshes::TesterGeometry& t, int material) {
  const auto wall = [&](const RevolutionSurface& surface, const char* name) {
    return s.add_wall(RevolutionWall(surface, material, {}, false, name));
  };
  const double ri = t.inner_radius, ro = t.outer_radius;
  std::vector<int> rotating{wall(RevolutionSurface::annulus(0, ri, ro), "floor"),
                            wall(RevolutionSurface::cylinder(ri, 0, t.wall_height), "inner"),
                            wall(RevolutionSurface::cylinder(ro, 0, t.wall_height), "outer")};
  if (t.consolidator) {
    // The plate of meshes::generate_tester_walls: from th0 over its extent e, centred on its
    // angle.
    const double e = t.consolidator_extent_deg * pi / 180;
    const double th0 = t.consolidator_angle_deg * pi / 180 - e / 2;
    wall(RevolutionSurface::annulus(t.consolidator_height, ri, ro, th0, th0 + e), "consolidator");
  }
  return rotating;
}
} // namespace

void validate(const TesterDemParameters& p) {
  validate(static_cast<const DemParameters&>(p));
  require_dem(p.fill_height > 0, "Fill height", "must be positive [m]");
  require_dem(p.rotation_rate_deg > 0 && std::isfinite(p.rotation_rate_deg), "Rotation rate",
              "must be positive [deg/s]");
  require_dem(p.revolutions >= 1, "Revolutions", "must be at least 1");
  require_dem(p.samples_per_revolution >= 2, "Samples per revolution", "must be at least 2");
  require_dem(p.steady_threshold > 0, "Steady threshold", "must be positive");
  require_dem(p.steady_revolutions >= 1, "Steady revolutions", "must be at least 1");
}

WearTester::WearTester(const meshes::GeometryParameters& geometry, const TesterDemParameters& dem,
                       const WearLawParameters& wear_law,
                       const ReferenceDeformationParameters& deformation,
                       const meshes::SurfaceMesh& sample)
    : geometry_(geometry), dem_(dem), deformation_parameters_(deformation),
      law_(make_wear_law(wear_law)) {
  meshes::validate(geometry_);
  validate(dem_);
  if (deformation.enabled) {
    if (deformation.update_interval < 1)
      throw std::invalid_argument("Deformation/Update interval: must be at least one step");
    if (!(deformation.amplification > 0))
      throw std::invalid_argument("Deformation/Amplification: must be positive");
  }
  const auto& t = geometry_.tester;
  sector_ = t.sector_angle_deg * pi / 180;
  auto& m = system_.materials;
  particle_material_ = m.add(engine_material("particle", dem_.particle));
  const int sample_material = m.add(engine_material("sample", dem_.sample));
  const int wall_material = m.add(engine_material("walls", dem_.walls));
  m.set_pair(particle_material_, particle_material_, dem_.particle_particle);
  m.set_pair(particle_material_, sample_material, dem_.particle_wall);
  m.set_pair(particle_material_, wall_material, dem_.particle_wall);
  m.set_pair(sample_material, sample_material, dem_.particle_wall); // walls never meet
  m.set_pair(sample_material, wall_material, dem_.particle_wall);
  m.set_pair(wall_material, wall_material, dem_.particle_wall);

  rotating_walls_ = add_tester_walls(system_, t, wall_material);
  const meshes::SampleFrame frame(geometry_.sample, geometry_.placement);
  const auto placed = frame.place_in_tester(sample);
  // The sample wall keeps its number with and without a holder.
  std::vector<int> covered;
  if (t.holder)
    covered = {meshes::label::side, meshes::label::bottom};
  sample_wall_ =
      system_.add_wall(MeshWall(placed, sample_material, {}, true, "sample", std::move(covered)));
  if (t.holder) {
    const int holder_material = m.add(engine_material("holder", dem_.holder));
    m.set_pair(particle_material_, holder_material, dem_.particle_wall);
    for (int other : {sample_material, wall_material, holder_material})
      m.set_pair(holder_material, other, dem_.particle_wall); // walls never meet
    holder_wall_ = system_.add_wall(
        MeshWall(frame.place_in_tester(meshes::generate_holder(geometry_.sample, t)),
                 holder_material, {}, false, "holder", {meshes::label::pocket}));
  }

  auto& s = system_.settings;
  s.time_step_fraction = dem_.time_step_fraction;
  s.max_speed = dem_.max_speed;
  s.periodic = {t.sector_angle_deg < 360, sector_};
  const double ro = t.outer_radius + 0.05;
  s.domain = {{-ro, -ro, -0.05}, {ro, ro, t.wall_height + dem_.fill_height * dem_.loose_factor}};
  revolution_time_ = sector_ / (dem_.rotation_rate_deg * pi / 180);

  const double mean_d = dem_.psd.mean_diameter();
  spreading_ = dem::load_spreading(dem_.wall_loads, dem_.psd);
  evaluation_ =
      std::make_unique<TesterEvaluation>(sample, geometry_.sample, geometry_.placement, mean_d,
                                         dem_.steady_threshold, dem_.steady_revolutions);
  if (deformation.enabled)
    deformation_ = std::make_unique<ReferenceDeformation>(placed);
  cumulative_removed_.assign(placed.n_faces(), 0);
}

void WearTester::set_rank_link(RankLink* link) {
  if (!link || link->n_ranks() < 2) {
    system_.set_rank_link(nullptr, nullptr);
    return;
  }
  if (!link->ring())
    throw std::invalid_argument("WearTester over ranks: the ranks must form a ring (the periodic "
                                "seam or the full circle joins the last rank to the first)");
  const double angle = geometry_.tester.sector_angle_deg < 360 ? sector_ : 2 * pi;
  slabs_ =
      SlabDecomposition::uniform_angular(angle, link->n_ranks(), geometry_.tester.inner_radius);
  system_.set_rank_link(link, &slabs_);
}

std::string WearTester::rank_layout() const {
  const RankLink* link = system_.rank_link();
  const int n = link ? link->n_ranks() : 1;
  const double angle =
      geometry_.tester.sector_angle_deg < 360 ? geometry_.tester.sector_angle_deg : 360.0;
  char b[160];
  std::snprintf(b, sizeof b, "over %d MPI rank(s), %s each: angular slabs of %.2f degrees", n,
                dem_.n_threads > 0 ? (std::to_string(dem_.n_threads) + " thread(s)").c_str()
                                   : "the cores it is given (DEM/Threads = 0)",
                angle / n);
  return b;
}

void WearTester::count_particles() {
  n_particles_ = system_.n_particles_over_ranks();
}

const Particles& WearTester::particles_for_evaluation() {
  return gather_particles(true);
}

const Particles& WearTester::bed_particles() {
  return gather_particles(false);
}

// Every rank's particles (or those over the sample), in rank order, on every rank.
const Particles& WearTester::gather_particles(bool only_over_sample) {
  RankLink* link = system_.rank_link();
  if (!link)
    return system_.particles;
  const Particles& p = system_.particles;
  std::function<bool(std::size_t)> keep;
  if (only_over_sample)
    keep = [&](std::size_t i) { return evaluation_->over_sample(p.position[i]); };
  gathered_ = dem::gather_particles(p, link, GatherTo::every_rank, keep, dem_.particle.density);
  return gathered_;
}

FillReport WearTester::fill_and_settle(const std::function<void(const TesterProgress&)>& progress) {
  const auto& t = geometry_.tester;
  const auto& g = geometry_.sample;
  const meshes::SampleFrame frame(g, geometry_.placement);
  const double d_max = dem_.psd.max_diameter();
  const double element_h = g.convex ? g.pattern.h : 0;
  const double rim = t.holder ? t.holder_rim_width : 0; // the holder around and under it
  const double ri = t.inner_radius, ro = t.outer_radius, Th = sector_;
  const auto make_region = [&, frame, d_max, element_h, rim](double z_top) {
    FillRegion base =
        annular_sector_region(ri, ro, Th, 0, std::min(z_top, t.wall_height), 0.5 * d_max);
    const auto inside = base.inside;
    base.inside = [=](const Vec3& x) {
      if (!inside(x))
        return false;
      const Vec3 q = frame.point_to_sample(x);
      const double c = d_max;
      if (std::abs(q.x) < g.width / 2 + rim + c && std::abs(q.y) < g.length / 2 + rim + c &&
          q.z > -rim - c && q.z < g.thickness + element_h + c)
        return false;
      if (t.consolidator && x.z > t.consolidator_height - c) {
        double th = std::atan2(x.y, x.x);
        if (th < 0)
          th += 2 * pi;
        const double half = 0.5 * t.consolidator_extent_deg * pi / 180 + c / ri;
        if (std::abs(th - t.consolidator_angle_deg * pi / 180) < half)
          return false;
      }
      return true;
    };
    return base;
  };
  use_thread_count();
  // The bed fills the sector's annulus up to the fill height less what the holder's frame
  // occupies there (its rim top is the wear face's edge, below the bed's surface): the count
  // is that of the annulus with the frame's volume taken out, so the bed settles at the same
  // height with and without the holder (the bare sample's own volume is left in, as before).
  const double frame_volume =
      t.holder ? (g.width + 2 * rim) * (g.length + 2 * rim) * (g.thickness + rim) -
                     g.width * g.length * g.thickness
               : 0.0;
  const double area = 0.5 * Th * (ro * ro - ri * ri) - frame_volume / dem_.fill_height;
  const meshes::Stopwatch wall_clock;
  const auto report = fill_to_height(
      system_, make_region, area, 0, dem_.fill_height, dem_.psd, dem_.particle.density,
      particle_material_, dem_.seed, dem_.loose_factor, settled_mean_speed, dem_.settle_time,
      [&](double time) {
        count_particles(); // every rank, before the progress that only some show
        if (!progress)
          return;
        const double wall = wall_clock.seconds();
        TesterProgress pr;
        pr.phase = "settling";
        pr.time = time;
        pr.fraction = time / dem_.settle_time;
        pr.particle_steps_per_second =
            wall > 0 ? double(system_.n_steps()) * double(n_particles_) / wall : 0;
        progress(pr);
      },
      dem_.assumed_packing);
  steps_per_revolution_ = std::uint64_t(std::llround(revolution_time_ / system_.time_step()));
  count_particles();
  return report;
}

const RevolutionRecord&
WearTester::run_revolution(const std::function<void(const TesterProgress&)>& progress) {
  advance_revolution(progress, {});
  return evaluation_->history().back();
}

void WearTester::open_revolution_now() {
  if (steps_per_revolution_ == 0)
    throw std::logic_error("WearTester::run_revolution before fill_and_settle");
  start_rotation();
  system_.reset_wear_integrals();
  evaluation_->begin_revolution(system_.time());
  node_applied_.assign(cumulative_removed_.size(), 0);
  steps_done_ = 0;
  open_seconds_ = 0;
  open_ = true;
}

// Steps go in chunks that end at every evaluation sample, node update and stop check; the
// engine's run(k) gives the same bits whatever the chunks.
bool WearTester::advance_revolution(const std::function<void(const TesterProgress&)>& progress,
                                    const std::function<bool()>& stop) {
  if (!open_)
    open_revolution_now();
  const std::uint64_t n = steps_per_revolution_;
  const std::uint64_t sample_every = std::max<std::uint64_t>(1, n / dem_.samples_per_revolution);
  const std::uint64_t update_every =
      deformation_ ? std::min<std::uint64_t>(deformation_parameters_.update_interval, n) : n;
  const std::uint64_t check_every = stop ? stop_check_steps : n;
  const meshes::Stopwatch wall_clock;
  std::uint64_t& done = steps_done_;
  const std::uint64_t first = done;
  std::uint64_t next_progress = done;
  while (done < n) {
    if (stop && stop()) {
      open_seconds_ += wall_clock.seconds();
      return false;
    }
    const std::uint64_t k =
        std::min({sample_every - done % sample_every, update_every - done % update_every,
                  check_every - done % check_every, n - done});
    system_.run(k);
    done += k;
    const bool sample = done % sample_every == 0;
    const bool update = deformation_ && (done % update_every == 0 || done == n);
    if (sample || update) {
      const WearIntegrals wi = sample_integrals();
      const auto removed = law_->removed_volume(wi);
      if (sample)
        evaluation_->sample(particles_for_evaluation(), sample_mesh(), system_.time(), removed,
                            wi.normal_impulse);
      if (update) {
        std::vector<double> delta(removed.size());
        for (std::size_t f = 0; f < delta.size(); ++f)
          delta[f] = deformation_parameters_.amplification * (removed[f] - node_applied_[f]);
        node_applied_ = removed;
        system_.set_wall_vertices(sample_wall_, deformation_->update(delta, system_.time()));
      }
    }
    if (progress && (done >= next_progress || done == n)) {
      next_progress = done + n / 100;
      const double wall = wall_clock.seconds();
      TesterProgress pr;
      pr.phase = "revolution";
      pr.revolution = revolution_ + 1;
      pr.fraction = double(done) / double(n);
      pr.time = system_.time();
      pr.particle_steps_per_second =
          wall > 0 ? double(done - first) * double(n_particles_) / wall : 0;
      progress(pr);
    }
  }
  close_revolution(open_seconds_ + wall_clock.seconds());
  return true;
}

const RevolutionRecord& WearTester::close_revolution(double wall) {
  const std::uint64_t n = steps_per_revolution_;
  const WearIntegrals integrals = sample_integrals();
  // The window's duration is the nominal revolution (the step count rounds it to a step).
  last_loads_ = wall_loads(integrals, law_->removed_volume(integrals), sample_mesh(),
                           revolution_time_, spreading_);
  const auto& removed = last_loads_.wear_volume.values();
  for (std::size_t f = 0; f < removed.size(); ++f)
    cumulative_removed_[f] += removed[f];
  RevolutionRecord& r =
      evaluation_->end_revolution(system_.time(), removed, law_->total_removed_volume(integrals));
  r.wall_seconds = wall;
  r.particle_steps_per_second = double(n) * double(n_particles_) / wall;
  if (deformation_) {
    r.swept_volume = deformation_->swept_volume();
    r.applied_volume = deformation_->applied_volume();
    r.enclosed_volume_loss = deformation_->enclosed_volume_loss();
    r.min_angle_deg = deformation_->quality().min_angle_deg;
    r.distortion = deformation_->distortion_text();
  }
  ++revolution_;
  open_ = false;
  return r;
}

std::optional<OpenRevolution> WearTester::open_revolution() const {
  if (!open_ || deformation_)
    return std::nullopt;
  return OpenRevolution{steps_done_, open_seconds_, evaluation_->open_samples()};
}

void WearTester::use_thread_count() {
  // gmsh may have lowered OpenMP's default thread count: set it explicitly.
  omp_set_num_threads(dem_.n_threads > 0 ? dem_.n_threads : omp_get_num_procs());
}

void WearTester::start_rotation() {
  if (rotating_)
    return;
  WallMotion rotation;
  rotation.angular_velocity = dem_.rotation_rate_deg * pi / 180;
  for (int w : rotating_walls_)
    system_.set_wall_motion(w, rotation);
  rotating_ = true;
}

WearTester::PushReport WearTester::set_sample_surface(const meshes::SurfaceMesh& sample,
                                                      double push_tolerance) {
  if (deformation_)
    throw std::logic_error("WearTester: the sample surface cannot be replaced while the "
                           "reference deformation moves its nodes");
  if (open_)
    throw std::logic_error("WearTester: the sample surface cannot be replaced inside a "
                           "revolution");
  const auto placed =
      meshes::SampleFrame(geometry_.sample, geometry_.placement).place_in_tester(sample);
  const PushReport report = system_.push_out_of_wall(sample_wall_, placed, push_tolerance);
  system_.replace_wall_mesh(sample_wall_, placed);
  evaluation_->set_surface(sample);
  cumulative_removed_.assign(placed.n_faces(), 0);
  last_loads_ = {};
  return report;
}

// A resumed run's tester has no particles yet: those of the state, set up (its own lists and
// forces are then replaced by the state's).
// Over ranks each rank adds either its own part, where the part's last rebuild had it (so
// that setup() moves no particle), or the whole bed, of which setup() keeps the rank's slab.
void WearTester::add_particles_of(const SystemState& state) {
  if (system_.particles.n_real > 0)
    return;
  add_state_particles(system_.particles, state, state.n_ranks > 1, dem_.particle.density);
  use_thread_count();
  system_.setup();
  steps_per_revolution_ = std::uint64_t(std::llround(revolution_time_ / system_.time_step()));
  count_particles();
}

void WearTester::restore(const SystemState& state, int revolutions_done,
                         const std::vector<RevolutionRecord>& records) {
  add_particles_of(state);
  if (revolutions_done > 0)
    start_rotation();
  system_.import_state(state);
  evaluation_->history() = records;
  revolution_ = revolutions_done;
  open_ = false;
}

void WearTester::restore(const SystemState& state, int revolutions_done,
                         const std::vector<RevolutionRecord>& records, const OpenRevolution& open) {
  if (deformation_)
    throw std::logic_error("WearTester: a revolution of the reference deformation cannot be "
                           "continued from a checkpoint");
  add_particles_of(state);
  if (open.steps_done >= steps_per_revolution_)
    throw std::invalid_argument("checkpoint: the open revolution is past its " +
                                std::to_string(steps_per_revolution_) + " steps");
  start_rotation();
  const RankLink* link = system_.rank_link();
  if (continues_exactly(state, link ? link->rank() : 0, link ? link->n_ranks() : 1)) {
    system_.resume_state(state);
  } else { // written on another rank count: the revolution goes on from a rebuild
    system_.import_state(state);
    system_.add_wear_window(state);
  }
  evaluation_->history() = records;
  evaluation_->resume_samples(open.samples);
  revolution_ = revolutions_done;
  steps_done_ = open.steps_done;
  open_seconds_ = open.wall_seconds;
  open_ = true;
}

} // namespace wear::dem
