#pragma once
// The scene's walls as labelled triangle surfaces in metres, built from the Scene subsection
// (scene_parameters.h) and checked before any particle exists.
#include "dem/engine/revolution_wall.h"
#include "dem/scene/scene_parameters.h"
#include "meshes/cad_import.h"
#include "meshes/geometry_parameters.h"

#include <optional>
#include <string>
#include <vector>

namespace wear::dem {

struct SceneWall {
  SceneWallParameters parameters;
  meshes::CadSurface surface; ///< [m] triangles, one label per CAD surface or primitive face
  /// Labels of faces held flush against another wall (MeshWall): the tester's sample's sides
  /// and bottom and its holder's pocket, when both are walls of the scene.
  std::vector<int> covered_labels;
};

/// The exact surface of revolution of wall `w` in the scene's frame, or none when it is a
/// triangle wall: a disc (an annulus with Inner radius; its plane through Origin normal to
/// Axis), a cylinder without Caps (radius Radius about Axis from Origin over |Axis|) or a
/// cone without Caps (Radius at Origin to Top radius at Origin + Axis) with Exact surface, that
/// does not wear (a wearing part's surface changes stage by stage) and moves at most by a surface
/// motion (its geometry stays where it is).
std::optional<RevolutionSurface> revolution_surface(const SceneWallParameters& w);

/// Every wall of the scene, in the order of Scene/Walls. Throws std::runtime_error or
/// std::invalid_argument naming `Scene/Wall <name>` and its file when a file is missing or
/// unreadable, a primitive's dimension is wrong, a wearing wall is not a closed solid, or a
/// wall reaches outside Scene/Domain (the message gives its extent and asks about the unit).
/// `geometry`: the Geometry subsection, for walls with Source = sample or holder (the
/// tester's sample and holder, placed as in the tester).
std::vector<SceneWall> build_scene_walls(const SceneParameters& scene,
                                         const meshes::GeometryParameters& geometry = {});

} // namespace wear::dem
