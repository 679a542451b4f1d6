#pragma once
// Labels on a new worn surface whose faces took the label of the nearest old face (the
// implicit recession's): straight boundaries, no islands, elements worn away and teeth of no
// width joined to the label around them. Each works on a closed manifold surface in place.
#include "meshes/surface_mesh.h"

#include <vector>

namespace wear::meshes {

/// A face whose neighbours across two or three of its edges carry one other label takes it,
/// in `passes` sweeps (each reads the labels the sweep before left).
void smooth_label_boundaries(SurfaceMesh& m, int passes);

/// Each connected piece of a label whose area is below `fraction` of that label's largest
/// piece joins the label it shares most edges with (up to 3 rounds).
void merge_label_islands(SurfaceMesh& m, double fraction);

/// Each convex element label (C<j><k>, meshes/part_life.h) whose highest vertex stands at most
/// `height` [m] above its foot joins the label it shares most edges with. Returns the labels
/// removed.
std::vector<int> merge_vanished_elements(SurfaceMesh& m, double height);

/// A face of no width (triangle quality below 1e-3) two of whose edges, meeting at its tip,
/// border faces of one other label, while the tip has no other face of the face's own label,
/// joins that label and takes the patch (`patch_of_face`, per face) of its neighbour across
/// the first of those edges. Returns the faces joined.
std::size_t join_label_teeth(SurfaceMesh& m, std::vector<int>& patch_of_face);

} // namespace wear::meshes
