// The System's wall table: mesh walls (MeshWall) and revolution walls (RevolutionWall) in one
// numbering w, which the wall candidates ((w << 24) | face), the wall-contact slots and the
// wear accumulators use. wall_kind_[w] says which array holds wall w, wall_local_[w] where.
// A revolution wall has one candidate "face", 0, for its exact closest point; its wear
// integrals are kept per face of its accounting triangulation.
//
// A mesh wall with a rigid motion is queried in its body frame: particle centres are taken
// there (MeshWall::to_body) and distances are the same in both frames.
//
// Elastic energy of a wall contact: the Hertz term 8/15 E* sqrt(R) delta^(5/2) of every
// contact the force pass would count before merging, junction contacts excepted (the
// tangential springs of wall contacts are left out, as they always were).
#include "dem/engine/system.h"

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

} // namespace wear::dem
