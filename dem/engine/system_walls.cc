// The System's wall table: mesh walls (MeshWall) and revolution walls (RevolutionWall) in one
// numbering w, which the wall candidates ((w << 24) | face), the wall-contact slots and the
// wear accumulators use. wall_kind_[w] says which array holds wall w, wall_local_[w] where.
// A revolution wall has one candidate "face", 0, for its exact closest point; its wear
// integrals are kept per face of its accounting triangulation.
//
// A mesh wall with a rigid motion is queried in its body frame: particle centres are taken
// there (MeshWall::to_body) and distances are the same in both frames.
//
// Push-out from a new wall surface: a bed particle lies outside the wall, and one stage moves the
// surface by far less than a radius, so its centre is still outside: it goes along closest point
// -> centre (the face normal's sign is no test of side at a convex edge or vertex) to touch.
//
// Elastic energy of a wall contact: the Hertz term 8/15 E* sqrt(R) delta^(5/2) of every
// contact the force pass would count before merging, junction contacts excepted (the
// tangential springs of wall contacts are left out, as they always were).
#include "dem/engine/system.h"

#include "meshes/surface_locator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wear::dem {

int System::register_wall(WallKind kind, std::size_t local, const std::string& name, int material) {
  if (set_up_)
    throw std::logic_error("walls must be added before setup()");
  if (material < 0 || material >= materials.n_materials())
    throw std::invalid_argument("wall '" + name + "' refers to an unknown material");
  // The wall number takes the top 8 bits of a wall candidate ((w << 24) | face).
  if (n_walls() >= (1 << 8))
    throw std::invalid_argument("wall '" + name + "': at most 256 walls");
  wall_kind_.push_back(kind);
  wall_local_.push_back(std::int32_t(local));
  return n_walls() - 1;
}

int System::add_wall(const RevolutionWall& wall) {
  const int w =
      register_wall(WallKind::revolution, revolution_walls_.size(), wall.name(), wall.material());
  revolution_walls_.push_back(wall);
  return w;
}

const MeshWall& System::wall(int w) const {
  return walls_[mesh_index(w, "wall")];
}

const RevolutionWall& System::revolution_wall(int w) const {
  if (wall_kind(w) != WallKind::revolution)
    throw std::invalid_argument("System::revolution_wall: wall " + std::to_string(w) + " ('" +
                                wall_name(w) + "') is a mesh wall");
  return revolution_walls_[std::size_t(wall_local_[w])];
}

std::size_t System::mesh_index(int w, const char* what) const {
  if (wall_kind(w) != WallKind::mesh)
    throw std::invalid_argument(std::string("System::") + what + ": wall " + std::to_string(w) +
                                " ('" + wall_name(w) +
                                "') is a revolution wall, which has no triangle mesh");
  return std::size_t(wall_local_[w]);
}

void System::set_wall_motion(int w, const WallMotion& m) {
  if (wall_kind(w) == WallKind::mesh)
    walls_[std::size_t(wall_local_[w])].set_motion(m);
  else
    revolution_walls_[std::size_t(wall_local_[w])].set_motion(m);
}

bool System::has_moving_walls() const {
  return std::any_of(walls_.begin(), walls_.end(), [](const MeshWall& w) { return w.moving(); });
}

void System::move_walls(double t) {
  for (auto& w : walls_)
    w.move_to(t);
  wall_time_ = t;
}

double System::wall_displacement() const {
  double d = 0;
  for (const auto& w : walls_)
    d = std::max(d, w.displacement());
  return d;
}

const std::string& System::wall_name(int w) const {
  const std::size_t k = std::size_t(wall_local_.at(w));
  return wall_kind_[w] == WallKind::mesh ? walls_[k].name() : revolution_walls_[k].name();
}

bool System::wall_wearing(int w) const {
  const std::size_t k = std::size_t(wall_local_.at(w));
  return wall_kind_[w] == WallKind::mesh ? walls_[k].wearing() : revolution_walls_[k].wearing();
}

std::size_t System::wall_faces(int w) const {
  const std::size_t k = std::size_t(wall_local_.at(w));
  return wall_kind_[w] == WallKind::mesh ? walls_[k].n_faces() : revolution_walls_[k].n_faces();
}

void System::size_wear_accumulators() {
  wear_acc_.assign(n_threads_, {});
  for (auto& t : wear_acc_) {
    t.resize(wall_kind_.size());
    for (int w = 0; w < n_walls(); ++w)
      if (wall_wearing(w))
        t[w].assign(n_wear_values * (wall_faces(w) + 1), 0.0);
  }
}

PushReport System::push_out_of_wall(int w, const meshes::SurfaceMesh& mesh, double tolerance) {
  const MeshWall& wall = walls_[mesh_index(w, "push_out_of_wall")];
  PushReport report;
  auto& p = particles;
  if (p.n_real > 0) {
    const meshes::SurfaceLocator locator(mesh);
    const auto normals = meshes::face_normals(mesh);
    const auto box = meshes::bounding_box(mesh);
    double r_max = 0;
    for (std::size_t i = 0; i < p.n_real; ++i)
      r_max = std::max(r_max, p.radius[i]);
    for (std::size_t i = 0; i < p.n_real; ++i) {
      const Vec3 x = wall.to_body(p.position[i]);
      if (x.x < box.min.x - r_max || x.y < box.min.y - r_max || x.z < box.min.z - r_max ||
          x.x > box.max.x + r_max || x.y > box.max.y + r_max || x.z > box.max.z + r_max)
        continue;
      const auto near = locator.nearest(x);
      if (near.face < 0)
        continue;
      const double r = p.radius[i];
      const double overlap = r - near.distance;
      if (overlap <= tolerance * r)
        continue;
      const Vec3 out =
          near.distance > 0 ? (x - near.point) / near.distance : normals[std::size_t(near.face)];
      const Vec3 moved = near.point + out * r;
      report.max_distance = std::max(report.max_distance, meshes::norm(moved - x));
      p.position[i] = wall.to_world(moved);
      ++report.n_pushed;
    }
  }
  if (rank_link_) {
    double pushed[2] = {double(report.n_pushed), report.max_distance};
    rank_link_->sum_in_rank_order(pushed, 1);
    rank_link_->max_over_ranks(pushed + 1, 1);
    report.n_pushed = int(pushed[0]);
    report.max_distance = pushed[1];
  }
  return report;
}

} // namespace wear::dem
