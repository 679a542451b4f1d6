// The catalogues of a scene wall's Source and Motion (wall_catalogue.h).
#include "dem/scene/wall_catalogue.h"

#include "dem/scene/scene_parameters.h"

#include <stdexcept>

namespace wear::dem {

const std::vector<WallSourceEntry>& wall_sources() {
  static const std::vector<WallSourceEntry> entries{
      {WallSource::file, "file",
       "a STEP, IGES, BREP or STL file (File, Unit; CAD surfaces meshed at Mesh size)", false,
       false, false},
      {WallSource::plane, "plane", "a parallelogram from Origin along Edge u and Edge v", true,
       false, false},
      {WallSource::disc, "disc",
       "a disc of Radius about Origin, normal Axis, with a central hole of Inner radius", true,
       false, true},
      {WallSource::cylinder, "cylinder",
       "a cylinder of Radius from Origin along Axis, open or with Caps", true, false, true},
      {WallSource::cone, "cone",
       "a cone from Radius at Origin to Top radius along Axis, open or with Caps", true, false,
       true},
      {WallSource::box, "box", "a box from its lower corner Origin of size Axis", true, false,
       false},
      {WallSource::sample, "sample",
       "the wear tester's parametric sample (Geometry/Sample: plain or convex pattern, meshed "
       "at its own sizes) where Geometry/Placement puts it; it keeps its labels (base and "
       "C<j><k> wear, its sides are free, its bottom is clamped)",
       false, true, false},
      {WallSource::holder, "holder",
       "the tester's holder: a frame of Geometry/Tester/Holder rim width around and under that "
       "sample, meshed at Mesh size; with it the sample's sides and bottom rest in its pocket",
       false, true, false}};
  return entries;
}

const std::vector<WallMotionEntry>& wall_motions() {
  static const std::vector<WallMotionEntry> entries{
      {WallMotionKind::fixed, "fixed", "at rest", false, false, false},
      {WallMotionKind::rotation, "rotation",
       "the whole wall turns about Axis point and Rotation axis at Angular velocity", true, false,
       true},
      {WallMotionKind::translation, "translation", "the whole wall moves at Velocity", true, false,
       false},
      {WallMotionKind::oscillation, "oscillation",
       "the whole wall moves by A sin(2 pi f (t - t0)) of Amplitude A and Frequency f", true, false,
       false},
      {WallMotionKind::surface_rotation, "surface rotation",
       "the geometry stays, its surface turns about Axis point and Rotation axis at Angular "
       "velocity (a turntable or drum turning about its own axis of symmetry)",
       false, true, true},
      {WallMotionKind::surface_translation, "surface translation",
       "the geometry stays, its surface moves at Velocity (a conveyor belt)", false, true, false}};
  return entries;
}

namespace {

template <typename Entry>
std::string names(const std::vector<Entry>& entries) {
  std::string s;
  for (const auto& e : entries)
    s += (s.empty() ? "" : "|") + std::string(e.name);
  return s;
}

template <typename Entry>
std::string descriptions(const std::vector<Entry>& entries) {
  std::string s;
  for (const auto& e : entries)
    s += (s.empty() ? "" : "; ") + std::string(e.name) + ": " + e.description;
  return s;
}

template <typename Entry>
const Entry& entry(const std::vector<Entry>& entries, const std::string& name,
                   const std::string& what) {
  for (const auto& e : entries)
    if (name == e.name)
      return e;
  throw std::invalid_argument(what + " = '" + name + "': not one of " + names(entries));
}

} // namespace

std::string wall_source_names() {
  return names(wall_sources());
}
std::string wall_motion_names() {
  return names(wall_motions());
}
std::string wall_source_descriptions() {
  return descriptions(wall_sources());
}
std::string wall_motion_descriptions() {
  return descriptions(wall_motions());
}

const WallSourceEntry& wall_source_of(const SceneWallParameters& w) {
  return entry(wall_sources(), w.source, scene_wall_path(w) + "/Source");
}

const WallMotionEntry& wall_motion_of(const SceneWallParameters& w) {
  return entry(wall_motions(), w.motion, scene_wall_path(w) + "/Motion");
}

} // namespace wear::dem
