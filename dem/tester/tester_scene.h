#pragma once
// The wear tester as a scene (docs/wear-tester.md, "The tester as a scene"): the walls,
// sector, consolidator, holder, sample, fill and stages of a tester case written as the Scene
// subsection any equipment uses, so that `wearsim scene-run` runs the tester as one scene
// among others. `wearsim tester-scene <case.prm>` prints the case so written.
#include "dem/scene/scene_parameters.h"
#include "dem/tester/tester_parameters.h"
#include "meshes/geometry_parameters.h"

namespace wear::dem {

/// The scene of the tester that `geometry` and `dem` describe, with stages of
/// `revolutions_per_stage` passes of the bed through the sector:
/// - floor (an annulus), inner and outer cylinder: primitives turning under the bed about z at
///   the rotation rate (`surface rotation`), exact surfaces of revolution as the tester's;
/// - the sector as Scene/Periodic sector (none for 360 degrees);
/// - the consolidator (when the tester has one): a fixed plate at its height, centred on its
///   angle, radially from 0.5 mm outside the inner cylinder to 1 mm inside the outer one,
///   as wide as its angular extent at the annulus' mid radius (the tester's plate is an
///   annular sector; the scene's primitives are flat), its column left empty by the fill;
/// - the holder (when the tester has one, meshed at the walls' size as the tester's) and the
///   sample, placed by Geometry/Placement, the sample wearing;
/// - the fill: the annulus 0.1 mm clear of the walls, to the fill height, settled, placed
///   loosely up to the walls' top or the loose fill's (DEM/Loose factor), whichever is higher;
/// - a record every 1/(Samples per revolution) of a revolution, no particle snapshots;
/// - the domain of the built-in tester (the annulus with 50 mm to spare, up to the walls'
///   height plus the loose fill's).
/// Throws std::invalid_argument naming the parameter when the geometry or DEM is invalid.
SceneParameters tester_scene(const meshes::GeometryParameters& geometry,
                             const TesterDemParameters& dem, int revolutions_per_stage);

} // namespace wear::dem
