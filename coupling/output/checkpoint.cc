// Checkpoints of a coupled run in HDF5.
//
// Layout of checkpoint.h5:
//   attributes on /: stages_done, has_scene = 1; /parameters: the resolved case (text as
//                   bytes; an attribute in checkpoints of older engines)
//   /dem/...        every array of dem::SystemState (Vec3 arrays as n x 3), attributes time,
//                   n_steps, n_rebuilds, next_id, and its continuation part
//                   (/dem/continuation/...: reference positions with the attribute
//                   wall_reference_time, wall candidates, cost estimate, the threads' wear
//                   window; attribute n_threads); written over N ranks instead: attribute
//                   n_ranks = N on /dem and each rank's part in /dem/rank_<r>/... (its rank
//                   fields as attributes, rank_ghosts, rank_sent_up, its continuation),
//                   gathered to rank 0 and written by it. A reader on N ranks takes its own
//                   part; on another count all parts, merged into the bed of one process
//                   (dem::merge_rank_states), which it decomposes again. Absent in a
//                   checkpoint kept without its bed (Checkpoint::has_bed), whose root has
//                   the attribute without_bed = 1; a bed of clumps also holds
//                   /dem/clumps/... (the bodies: pose, motion, last force, mass properties,
//                   member ranges, member ids and body-frame offsets)
//   /scene/...      the scene run's own part and its wearing parts (scene_checkpoint.cc)
// The checkpoint a write replaces is kept as checkpoint.previous.h5 (a hard link taken
// before the rename), and a resume falls back to it when the latest one does not read.
// Every value is stored in its binary form, so a read gives back the same bits. The file is
// written to a temporary name and renamed over the previous one only when complete.
#include "coupling/output/checkpoint.h"

#include "coupling/output/hdf5_file.h"
#include "dem/engine/rank_states.h"

#include <filesystem>

#include <stdexcept>

namespace wear::coupling {

namespace {

// One field list per record type drives packing and unpacking.
template <typename V>
void visit(dem::RevolutionRecord& r, V& v) {
  v(r.revolution), v(r.time), v(r.wear_volume), v(r.wear_volume_other);
  v(r.wear_volume_cumulative), v(r.contact_total_wear_volume), v(r.column_wear);
  v(r.element_wear), v(r.mean_element_increment), v(r.normal_force), v(r.column_normal_force);
  v(r.bottom_speed), v(r.bottom_spin), v(r.bottom_count), v(r.speed_over_sample);
  v(r.bed_height), v(r.wear_rate), v(r.steady), v(r.steady_revolution);
  v(r.fits.a), v(r.fits.r2_linear), v(r.fits.b), v(r.fits.c), v(r.fits.r2_quadratic);
  v(r.fits.n_points), v(r.fits_from), v(r.swept_volume), v(r.applied_volume);
  v(r.enclosed_volume_loss), v(r.min_angle_deg), v(r.wall_seconds);
  v(r.particle_steps_per_second);
}

template <typename V>
void visit(StageRecord& r, V& v) {
  v("stage", r.stage);
  v("scheme", r.scheme);
  v("first_revolution", r.first_revolution);
  v("last_revolution", r.last_revolution);
  v("time_s", r.time);
  v("amplification", r.amplification);
  v("dem_wear_volume_m3", r.dem_wear_volume);
  v("applied_volume_m3", r.applied_volume);
  v("geometry_volume_change_m3", r.geometry_volume_change);
  v("cumulative_applied_m3", r.cumulative_applied);
  v("max_depth_m", r.max_depth);
  v("max_depth_fraction", r.max_depth_fraction);
  v("mean_stress_factor", r.mean_stress_factor);
  v("increments", r.increments);
  v("remeshes", r.n_remeshes);
  v("total_remeshes", r.total_remeshes);
  v("first_attempt_remeshes", r.n_first_attempt_remeshes);
  v("spread_volume_m3", r.spread_volume);
  v("worn_through_volume_m3", r.worn_through_volume);
  v("worn_through_faces", r.n_worn_through);
  v("tetrahedra", r.n_tetrahedra);
  v("surface_faces", r.n_surface_faces);
  v("pushed_particles", r.n_pushed);
  v("max_push_m", r.max_push);
  v("min_scaled_jacobian", r.min_scaled_jacobian);
  v("max_von_mises_ball_Pa", r.max_von_mises_ball);
  v("von_mises_p99_Pa", r.von_mises_p99);
  v("von_mises_p999_Pa", r.von_mises_p999);
  v("max_von_mises_qp_Pa", r.max_von_mises_qp);
  v("stress_averaging_radius_m", r.stress_averaging_radius);
  v("safety_factor", r.safety_factor);
  v("max_displacement_m", r.max_displacement);
  v("mean_force_z_N", r.mean_force_z);
  v("wear_face_force_z_N", r.wear_face_force_z);
  v("wear_face_normal_force_N", r.wear_face_normal_force);
  v("volume_points", r.volume_points);
  v("volume_cells", r.volume_cells);
  v("dem_s", r.dem_seconds);
  v("wear_s", r.wear_seconds);
  v("fem_solve_s", r.fem_solve_seconds);
  v("mesh_motion_s", r.motion_seconds);
  v("remesh_s", r.remesh_seconds);
  v("output_s", r.output_seconds);
}

struct Packer {
  std::vector<double>& out;
  template <typename T>
  void operator()(const char*, T& x) {
    (*this)(x);
  }
  void operator()(double& x) { out.push_back(x); }
  void operator()(int& x) { out.push_back(x); }
  void operator()(bool& x) { out.push_back(x ? 1 : 0); }
  void operator()(Scheme& s) { out.push_back(scheme_index(s)); }
  void operator()(dem::Statistic& s) { out.push_back(s.mean), out.push_back(s.std); }
  void operator()(std::vector<double>& v) {
    out.push_back(double(v.size()));
    out.insert(out.end(), v.begin(), v.end());
  }
  void operator()(std::vector<dem::Statistic>& v) {
    out.push_back(double(v.size()));
    for (auto& s : v)
      (*this)(s);
  }
  void operator()(std::map<int, double>& m) {
    out.push_back(double(m.size()));
    for (auto& [k, x] : m)
      out.push_back(k), out.push_back(x);
  }
};

struct Unpacker {
  const double* in;
  std::size_t n, pos = 0;
  template <typename T>
  void operator()(const char*, T& x) {
    (*this)(x);
  }
  double next() {
    if (pos >= n)
      throw std::runtime_error("a record is shorter than its fields");
    return in[pos++];
  }
  std::size_t count() {
    const double c = next();
    if (!(c >= 0 && c <= double(n)))
      throw std::runtime_error("a record holds an impossible length");
    return std::size_t(c);
  }
  void operator()(double& x) { x = next(); }
  void operator()(int& x) { x = int(next()); }
  void operator()(bool& x) { x = next() != 0; }
  void operator()(Scheme& s) { s = scheme_from_index(int(next())); }
  void operator()(dem::Statistic& s) { s.mean = next(), s.std = next(); }
  void operator()(std::vector<double>& v) {
    v.resize(count());
    for (auto& x : v)
      x = next();
  }
  void operator()(std::vector<dem::Statistic>& v) {
    v.resize(count());
    for (auto& s : v)
      (*this)(s);
  }
  void operator()(std::map<int, double>& m) {
    m.clear();
    for (std::size_t k = count(); k > 0; --k) {
      const int key = int(next());
      m[key] = next();
    }
  }
};

template <typename R>
std::vector<double> pack_one(const R& r) {
  R copy = r;
  std::vector<double> out;
  Packer p{out};
  visit(copy, p);
  return out;
}

const char separator = '\x1f';

template <typename R>
void write_records(Hdf5File& h5, const std::string& group, const std::vector<R>& records) {
  std::vector<double> data;
  std::vector<std::int64_t> offsets{0};
  std::string distortions;
  for (const auto& r : records) {
    const auto packed = pack_one(r);
    data.insert(data.end(), packed.begin(), packed.end());
    offsets.push_back(std::int64_t(data.size()));
    distortions += r.distortion + separator;
  }
  h5.write(group + "/data", data, {data.size()});
  h5.write(group + "/offsets", offsets, {offsets.size()});
  h5.attribute(group, "distortions", distortions);
}

template <typename R>
std::vector<R> read_records(const Hdf5Reader& h5, const std::string& group) {
  const auto data = h5.doubles(group + "/data");
  const auto offsets = h5.int64s(group + "/offsets");
  const auto distortions = h5.text_attribute(group, "distortions");
  std::vector<R> out;
  std::size_t d = 0;
  for (std::size_t k = 0; k + 1 < offsets.size(); ++k) {
    if (offsets[k] < 0 || offsets[k + 1] < offsets[k] || std::size_t(offsets[k + 1]) > data.size())
      throw std::runtime_error("offsets of '" + group + "' do not fit its data");
    R r;
    Unpacker u{data.data() + offsets[k], std::size_t(offsets[k + 1] - offsets[k])};
    visit(r, u);
    if (u.pos != u.n)
      throw std::runtime_error("a record of '" + group + "' is longer than its fields");
    const auto end = distortions.find(separator, d);
    if (end == std::string::npos)
      throw std::runtime_error("distortions of '" + group + "' do not match the records");
    r.distortion = distortions.substr(d, end - d);
    d = end + 1;
    out.push_back(std::move(r));
  }
  return out;
}

void write_continuation(Hdf5File& h5, const std::string& dem_group, const dem::SystemState& d) {
  const std::string g = dem_group + "/continuation";
  write_vec3(h5, g + "/reference_position", d.reference_position);
  h5.write(g + "/wall_candidate_offset", wide(d.wall_candidate_offset),
           {d.wall_candidate_offset.size()});
  h5.write(g + "/wall_candidate", wide(d.wall_candidate), {d.wall_candidate.size()});
  write_doubles(h5, g + "/particle_cost", d.particle_cost);
  write_doubles(h5, g + "/wear_window", d.wear_window);
  h5.attribute(g + "/particle_cost", "n_threads", double(d.n_threads));
  h5.attribute(g + "/reference_position", "wall_reference_time", d.wall_reference_time);
}

void read_continuation(const Hdf5Reader& h5, const std::string& dem_group, dem::SystemState& d) {
  const std::string g = dem_group + "/continuation";
  d.reference_position = vec3s(h5.doubles(g + "/reference_position"), "reference_position");
  d.wall_candidate_offset = narrow<std::uint32_t>(h5.int64s(g + "/wall_candidate_offset"));
  d.wall_candidate = narrow<std::uint32_t>(h5.int64s(g + "/wall_candidate"));
  d.particle_cost = h5.doubles(g + "/particle_cost");
  d.wear_window = h5.doubles(g + "/wear_window");
  d.n_threads = int(h5.attribute(g + "/particle_cost", "n_threads"));
  // Absent from checkpoints written before walls could move; no wall moved then.
  if (h5.has_attribute(g + "/reference_position", "wall_reference_time"))
    d.wall_reference_time = h5.attribute(g + "/reference_position", "wall_reference_time");
}

// The rigid bodies of a DEM state in group g: per body the pose, motion, last force and mass
// properties (the orientation as w, x, y, z), per member its particle's id and body-frame
// offset; member_begin[b] is body b's first member.
void write_clumps(Hdf5File& h5, const std::string& g, const dem::ClumpsState& c) {
  write_vec3(h5, g + "/position", c.position);
  write_vec3(h5, g + "/velocity", c.velocity);
  std::vector<double> q;
  for (const auto& o : c.orientation)
    q.insert(q.end(), {o.w, o.x, o.y, o.z});
  h5.write(g + "/orientation", q, {c.orientation.size(), 4});
  write_vec3(h5, g + "/angular_momentum", c.angular_momentum);
  write_vec3(h5, g + "/force", c.force);
  write_vec3(h5, g + "/torque", c.torque);
  h5.write(g + "/mass", c.mass, {c.mass.size()});
  write_vec3(h5, g + "/moments", c.moments);
  h5.write(g + "/member_begin", wide(c.member_begin), {c.member_begin.size()});
  h5.write(g + "/member_id", c.member_id, {c.member_id.size()});
  write_vec3(h5, g + "/member_offset", c.member_offset);
}

dem::ClumpsState read_clumps(const Hdf5Reader& h5, const std::string& g) {
  dem::ClumpsState c;
  c.position = vec3s(h5.doubles(g + "/position"), "clump position");
  c.velocity = vec3s(h5.doubles(g + "/velocity"), "clump velocity");
  const auto q = h5.doubles(g + "/orientation");
  if (q.size() % 4 != 0)
    throw std::runtime_error("'" + g + "/orientation' does not hold 4 values per body");
  for (std::size_t k = 0; k < q.size(); k += 4)
    c.orientation.push_back({q[k], q[k + 1], q[k + 2], q[k + 3]});
  c.angular_momentum = vec3s(h5.doubles(g + "/angular_momentum"), "clump angular_momentum");
  c.force = vec3s(h5.doubles(g + "/force"), "clump force");
  c.torque = vec3s(h5.doubles(g + "/torque"), "clump torque");
  c.mass = h5.doubles(g + "/mass");
  c.moments = vec3s(h5.doubles(g + "/moments"), "clump moments");
  c.member_begin = narrow<std::uint32_t>(h5.int64s(g + "/member_begin"));
  c.member_id = h5.int64s(g + "/member_id");
  c.member_offset = vec3s(h5.doubles(g + "/member_offset"), "clump member_offset");
  return c;
}

// The DEM state in group g (without its continuation part); over ranks also the part's rank
// fields.
void write_dem(Hdf5File& h5, const std::string& g, const dem::SystemState& d) {
  const std::size_t n = d.position.size();
  write_vec3(h5, g + "/position", d.position);
  write_vec3(h5, g + "/velocity", d.velocity);
  write_vec3(h5, g + "/angular_velocity", d.angular_velocity);
  write_vec3(h5, g + "/force", d.force);
  write_vec3(h5, g + "/torque", d.torque);
  h5.write(g + "/radius", d.radius, {n});
  h5.write(g + "/mass", d.mass, {n});
  h5.write(g + "/inertia", d.inertia, {n});
  h5.write(g + "/material", d.material, {n});
  h5.write(g + "/id", d.id, {n});
  h5.write(g + "/ghost_owner", wide(d.ghost_owner), {d.ghost_owner.size()});
  h5.write(g + "/pair_i", wide(d.pair_i), {d.pair_i.size()});
  h5.write(g + "/pair_j", wide(d.pair_j), {d.pair_j.size()});
  write_vec3(h5, g + "/pair_history", d.pair_history);
  h5.write(g + "/wall_particles", wide(d.wall_particles), {d.wall_particles.size()});
  write_vec3(h5, g + "/slot_normal", d.slot_normal);
  write_vec3(h5, g + "/slot_delta", d.slot_delta);
  h5.write(g + "/slot_wall", std::vector<int>(d.slot_wall.begin(), d.slot_wall.end()),
           {d.slot_wall.size()});
  h5.attribute(g, "time", d.time);
  h5.attribute(g, "n_steps", double(d.n_steps));
  h5.attribute(g, "n_rebuilds", double(d.n_rebuilds));
  h5.attribute(g, "next_id", double(d.next_id)); // exact below 2^53
  if (d.n_ranks > 1) {
    write_doubles(h5, g + "/rank_ghosts", d.rank_ghosts);
    h5.write(g + "/rank_sent_up", wide(d.rank_sent_up), {d.rank_sent_up.size()});
    h5.attribute(g, "rank", double(d.rank));
    h5.attribute(g, "n_ranks", double(d.n_ranks));
    h5.attribute(g, "n_periodic_ghosts", double(d.n_periodic_ghosts));
    h5.attribute(g, "n_image_ghosts", double(d.n_image_ghosts));
  }
  if (!d.clumps.empty())
    write_clumps(h5, g + "/clumps", d.clumps);
}

dem::SystemState read_dem(const Hdf5Reader& h5, const std::string& g) {
  dem::SystemState d;
  d.position = vec3s(h5.doubles(g + "/position"), "position");
  d.velocity = vec3s(h5.doubles(g + "/velocity"), "velocity");
  d.angular_velocity = vec3s(h5.doubles(g + "/angular_velocity"), "angular_velocity");
  d.force = vec3s(h5.doubles(g + "/force"), "force");
  d.torque = vec3s(h5.doubles(g + "/torque"), "torque");
  d.radius = h5.doubles(g + "/radius");
  d.mass = h5.doubles(g + "/mass");
  d.inertia = h5.doubles(g + "/inertia");
  d.material = h5.ints(g + "/material");
  d.id = h5.int64s(g + "/id");
  d.ghost_owner = narrow<std::uint32_t>(h5.int64s(g + "/ghost_owner"));
  d.pair_i = narrow<std::uint32_t>(h5.int64s(g + "/pair_i"));
  d.pair_j = narrow<std::uint32_t>(h5.int64s(g + "/pair_j"));
  d.pair_history = vec3s(h5.doubles(g + "/pair_history"), "pair_history");
  d.wall_particles = narrow<std::uint32_t>(h5.int64s(g + "/wall_particles"));
  d.slot_normal = vec3s(h5.doubles(g + "/slot_normal"), "slot_normal");
  d.slot_delta = vec3s(h5.doubles(g + "/slot_delta"), "slot_delta");
  const auto walls = h5.ints(g + "/slot_wall");
  d.slot_wall.assign(walls.begin(), walls.end());
  d.time = h5.attribute(g, "time");
  d.n_steps = std::uint64_t(h5.attribute(g, "n_steps"));
  d.n_rebuilds = std::uint64_t(h5.attribute(g, "n_rebuilds"));
  // Absent from checkpoints written before particles could be inserted: one past the largest
  // id then, which the import takes anyway.
  if (h5.has_attribute(g, "next_id"))
    d.next_id = std::int64_t(h5.attribute(g, "next_id"));
  if (h5.has_attribute(g, "n_ranks")) {
    d.rank_ghosts = h5.doubles(g + "/rank_ghosts");
    d.rank_sent_up = narrow<std::uint32_t>(h5.int64s(g + "/rank_sent_up"));
    d.rank = int(h5.attribute(g, "rank"));
    d.n_ranks = int(h5.attribute(g, "n_ranks"));
    d.n_periodic_ghosts = std::uint64_t(h5.attribute(g, "n_periodic_ghosts"));
    d.n_image_ghosts = std::uint64_t(h5.attribute(g, "n_image_ghosts"));
  }
  if (h5.has_object(g + "/clumps"))
    d.clumps = read_clumps(h5, g + "/clumps");
  return d;
}

std::string rank_group(int r) {
  return "/dem/rank_" + std::to_string(r);
}

// The evaluation's samples: scalars in one dataset, in this order.
void write_samples(Hdf5File& h5, const std::string& g, const dem::RevolutionSamples& s) {
  write_doubles(
      h5, g + "/scalars",
      {s.start_time, s.last_time, s.bottom_n, s.bottom_v, s.bottom_v2, s.bottom_w, s.bottom_w2});
  write_doubles(h5, g + "/last_removed", s.last_removed);
  write_doubles(h5, g + "/last_impulse", s.last_impulse);
  write_doubles(h5, g + "/force", s.force);
  write_doubles(h5, g + "/speed", s.speed);
  write_doubles(h5, g + "/height", s.height);
  write_doubles(h5, g + "/rate", s.rate);
  write_doubles(h5, g + "/bottom_count", s.bottom_count);
  std::vector<double> columns;
  for (const auto& c : s.column_force)
    columns.insert(columns.end(), c.begin(), c.end());
  h5.write(g + "/column_force", columns, {s.column_force.size(), s.force.size()});
}

dem::RevolutionSamples read_samples(const Hdf5Reader& h5, const std::string& g) {
  dem::RevolutionSamples s;
  const auto x = h5.doubles(g + "/scalars");
  if (x.size() != 7)
    throw std::runtime_error("'" + g + "/scalars' does not hold 7 values");
  s.start_time = x[0], s.last_time = x[1], s.bottom_n = x[2], s.bottom_v = x[3];
  s.bottom_v2 = x[4], s.bottom_w = x[5], s.bottom_w2 = x[6];
  s.last_removed = h5.doubles(g + "/last_removed");
  s.last_impulse = h5.doubles(g + "/last_impulse");
  s.force = h5.doubles(g + "/force");
  s.speed = h5.doubles(g + "/speed");
  s.height = h5.doubles(g + "/height");
  s.rate = h5.doubles(g + "/rate");
  s.bottom_count = h5.doubles(g + "/bottom_count");
  const auto dims = h5.dims(g + "/column_force");
  const auto columns = h5.doubles(g + "/column_force");
  if (dims.size() != 2 || dims[1] != s.force.size())
    throw std::runtime_error("'" + g + "/column_force' is not n_columns x n_samples");
  s.column_force.resize(dims[0]);
  for (std::size_t c = 0; c < dims[0]; ++c)
    s.column_force[c].assign(columns.begin() + std::ptrdiff_t(c * dims[1]),
                             columns.begin() + std::ptrdiff_t((c + 1) * dims[1]));
  return s;
}

} // namespace

void write_stage_records(Hdf5File& h5, const std::string& g, const std::vector<StageRecord>& r) {
  write_records(h5, g, r);
}

void write_revolution_records(Hdf5File& h5, const std::string& g,
                              const std::vector<dem::RevolutionRecord>& r) {
  write_records(h5, g, r);
}

std::vector<dem::RevolutionRecord> read_revolution_records(const Hdf5Reader& h5,
                                                           const std::string& g) {
  return read_records<dem::RevolutionRecord>(h5, g);
}

void write_revolution_samples(Hdf5File& h5, const std::string& g, const dem::RevolutionSamples& s) {
  write_samples(h5, g, s);
}

dem::RevolutionSamples read_revolution_samples(const Hdf5Reader& h5, const std::string& g) {
  return read_samples(h5, g);
}

std::vector<StageRecord> read_stage_records(const Hdf5Reader& h5, const std::string& g) {
  return read_records<StageRecord>(h5, g);
}

std::vector<double> pack(const dem::RevolutionRecord& r) {
  return pack_one(r);
}
std::vector<double> pack(const StageRecord& r) {
  return pack_one(r);
}

namespace {
struct Names {
  std::vector<std::string> out;
  template <typename T>
  void operator()(const char* name, T&) {
    out.push_back(name);
  }
};
} // namespace

std::vector<std::string> stage_columns() {
  Names names;
  StageRecord r;
  visit(r, names);
  return names.out;
}

void write_checkpoint(const std::string& path, const Checkpoint& c,
                      const std::vector<dem::SystemState>& dem_parts) {
  Hdf5File h5(path);
  if (!c.has_bed) {
    if (!dem_parts.empty())
      throw std::invalid_argument("write_checkpoint: DEM parts given for a checkpoint without "
                                  "its bed");
  } else if (dem_parts.empty()) {
    write_dem(h5, "/dem", c.dem);
    write_continuation(h5, "/dem", c.dem);
  } else {
    for (std::size_t r = 0; r < dem_parts.size(); ++r) {
      write_dem(h5, rank_group(int(r)), dem_parts[r]);
      write_continuation(h5, rank_group(int(r)), dem_parts[r]);
    }
    h5.attribute("/dem", "n_ranks", double(dem_parts.size()));
  }
  h5.attribute("/", "stages_done", double(c.stages_done));
  h5.write_text("/parameters", c.parameters); // a resolved case is longer than an attribute holds
  h5.attribute("/", "has_scene", 1.0);
  if (!c.has_bed)
    h5.attribute("/", "without_bed", 1.0);
  write_scene(h5, c.scene);
  h5.commit(previous_checkpoint_path(path));
}

void require_same_case(const Checkpoint& c, const std::string& parameters,
                       const std::string& path) {
  if (c.parameters != parameters)
    throw std::runtime_error("--resume: the case differs from the one checkpoint '" + path +
                             "' was written with; resume with the same case file (the run's "
                             "parameters.prm holds it)");
}

std::string previous_checkpoint_path(const std::string& path) {
  const std::string ext = ".h5";
  const bool h5 =
      path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0;
  return (h5 ? path.substr(0, path.size() - ext.size()) : path) + ".previous.h5";
}

Checkpoint read_latest_checkpoint(const std::string& path, std::ostream& warnings,
                                  const DemPart& part) {
  const std::string previous = previous_checkpoint_path(path);
  try {
    return read_checkpoint(path, part);
  } catch (const std::exception& e) {
    if (!std::filesystem::exists(previous))
      throw;
    Checkpoint c = read_checkpoint(previous, part);
    warnings << "warning: " << e.what() << "; resuming from the checkpoint before it, '" << previous
             << "' (after stage " << c.stages_done << ")" << std::endl;
    return c;
  }
}

Checkpoint read_checkpoint(const std::string& path, const DemPart& part) {
  const Hdf5Reader h5(path);
  if (!h5.has_attribute("/", "has_scene") || h5.attribute("/", "has_scene") == 0)
    throw std::runtime_error("checkpoint '" + path +
                             "' was written by the built-in wear tester of an older engine, "
                             "which the tester as a scene cannot continue; run the case again "
                             "with --overwrite");
  Checkpoint c;
  try {
    c.stages_done = int(h5.attribute("/", "stages_done"));
    // Written as an attribute by engines before the case outgrew one.
    c.parameters = h5.has_object("/parameters") ? h5.text("/parameters")
                                                : h5.text_attribute("/", "parameters");
    c.has_bed = !h5.has_attribute("/", "without_bed") || h5.attribute("/", "without_bed") == 0;
    c.scene = read_scene(h5);
    if (!c.has_bed)
      return c;
    if (!h5.has_object("/dem"))
      throw std::runtime_error("/dem is missing (and the attribute without_bed is not set)");
    c.dem_ranks = h5.has_attribute("/dem", "n_ranks") ? int(h5.attribute("/dem", "n_ranks")) : 1;
    if (c.dem_ranks < 1)
      throw std::runtime_error("/dem: n_ranks below 1");
    const auto part_of = [&](int r) {
      const std::string g = c.dem_ranks == 1 ? "/dem" : rank_group(r);
      dem::SystemState d = read_dem(h5, g);
      read_continuation(h5, g, d);
      return d;
    };
    if (c.dem_ranks == part.n_ranks) {
      c.dem = part_of(part.rank);
    } else { // another rank count: the bed as one process holds it
      std::vector<dem::SystemState> parts;
      for (int r = 0; r < c.dem_ranks; ++r)
        parts.push_back(part_of(r));
      c.dem = dem::merge_rank_states(parts);
    }
  } catch (const std::exception& e) {
    throw std::runtime_error("checkpoint '" + path + "' is damaged or incomplete: " + e.what());
  }
  return c;
}

} // namespace wear::coupling
