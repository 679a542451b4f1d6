#pragma once
// The catalogues of a scene wall's Source and Motion: each entry a name the case file
// chooses, what it means (the parameters' documentation is assembled from the entries) and
// the properties the code asks of it, so that the rest of the code asks properties, never
// names. scene_parameters.h reads the names; every user takes the entry (wall_source_of,
// wall_motion_of).
#include <string>
#include <vector>

namespace wear::dem {

struct SceneWallParameters;

enum class WallSource { file, plane, disc, cylinder, cone, box, sample, holder };

struct WallSourceEntry {
  WallSource source;
  const char* name;
  const char* description;
  bool primitive;   ///< meshed from its own parameters at Mesh size (meshes::Primitive)
  bool tester_part; ///< the tester's sample or holder, placed by Geometry/Placement
  bool revolution;  ///< a disc, cylinder or cone: may be an exact surface of revolution
};

enum class WallMotionKind {
  fixed,
  rotation,
  translation,
  oscillation,
  surface_rotation,
  surface_translation
};

struct WallMotionEntry {
  WallMotionKind kind;
  const char* name;
  const char* description;
  bool rigid;   ///< the whole wall moves as a rigid body (dem::RigidMotion)
  bool surface; ///< the geometry stays, its surface moves (dem::WallMotion)
  bool rotates; ///< about Axis point and Rotation axis at Angular velocity
};

const std::vector<WallSourceEntry>& wall_sources();
const std::vector<WallMotionEntry>& wall_motions();

/// "file|plane|disc|..." and "fixed|rotation|...": a selection parameter's choices.
std::string wall_source_names();
std::string wall_motion_names();
/// "name: description; name: description; ...", for the parameters' documentation.
std::string wall_source_descriptions();
std::string wall_motion_descriptions();

/// The entry of wall w's Source and Motion; throws std::invalid_argument naming the wall's
/// parameter and the choices for a name the catalogue does not hold.
const WallSourceEntry& wall_source_of(const SceneWallParameters& w);
const WallMotionEntry& wall_motion_of(const SceneWallParameters& w);

} // namespace wear::dem
