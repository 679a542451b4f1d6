#pragma once
// The scene's walls as labelled triangle surfaces in metres, built from the Scene subsection
// (scene_parameters.h) and checked before any particle exists.
#include "dem/scene/scene_parameters.h"
#include "meshes/cad_import.h"

#include <string>
#include <vector>

namespace wear::dem {

struct SceneWall {
  SceneWallParameters parameters;
  meshes::CadSurface surface; ///< [m] triangles, one label per CAD surface or primitive face
};

/// Every wall of the scene, in the order of Scene/Walls. Throws std::runtime_error or
/// std::invalid_argument naming `Scene/Wall <name>` and its file when a file is missing or
/// unreadable, a primitive's dimension is wrong, a wearing wall is not a closed solid, or a
/// wall reaches outside Scene/Domain (the message gives its extent and asks about the unit).
std::vector<SceneWall> build_scene_walls(const SceneParameters& scene);

} // namespace wear::dem
