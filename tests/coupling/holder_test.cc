// The sample holder in the DEM tester (issue 32): with Geometry/Tester/Holder = frame the
// sample's sides and underside see no particle over a window of the settled, turning bed;
// with Holder = none they do. The small tester (small_tester.h, plain sample, s = 4), as the
// scene `wearsim run` runs it, is filled, settled and turned for one revolution; the window's
// contact-steps per face of the sample wall are summed by label.
//
// With the frame, what could fail: a particle reaching a side or the bottom (a gap in the
// frame, the frame misplaced, the fill inserting particles inside it) gives face contacts
// there, which the covered labels do not hide (dem/engine/mesh_wall.h); a particle sitting
// on the rim at the wear face's edge would put half its edge contact on a side if the flush
// junction were counted; and a particle pressed into the frame or the sample deeper than a
// contact's overlap shows the frame is not holding the bed. Tolerances: exactly zero
// contact-steps on sides and bottom (no contact is a count, not a measurement); no sphere
// overlapping the frame's outer box by more than 10 % of its radius (settled Hertz overlaps at
// this load are below 1 %).
#include "coupling/parameters/tester_scene_case.h"
#include "dem/scene/scene_run.h"
#include "dem/scene/scene_walls.h"
#include "meshes/constants.h"
#include "meshes/sample_frame.h"
#include "small_tester.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace wear;

namespace {
struct Window {
  double wear_face_steps = 0; ///< [-] contact-steps on the base top (and elements)
  double side_steps = 0;      ///< [-] on the sides
  double bottom_steps = 0;    ///< [-] on the underside
  double worst_overlap = 0;   ///< [-] deepest sphere overlap with the frame's box / radius
  int holder_wall = -1;       ///< the holder's wall number
};

Window settled_window(bool holder) {
  auto p = small_tester_case("holder_test", false);
  p.geometry.tester.holder = holder;
  const auto c = coupling::tester_scene_case(p);
  dem::SceneRun scene(c.scene, c.dem, dem::build_scene_walls(c.scene, c.geometry));
  scene.setup();
  const double revolution = p.geometry.tester.sector_angle_deg / p.dem.rotation_rate_deg; // [s]
  const dem::SceneWindow turned = scene.advance(scene.time() + revolution);
  Window w;
  const auto holder_wall = dem::scene_wall_index(c.scene, "holder");
  w.holder_wall = holder_wall ? int(*holder_wall) : -1;
  const std::size_t sample_wall = dem::scene_wall_index(c.scene, "sample").value();
  const auto law = dem::make_wear_law(c.wear_law);
  const auto loads = scene.wall_loads(sample_wall, *law, turned);
  const auto& mesh = scene.walls()[sample_wall].surface.mesh;
  const auto& labels = mesh.face_labels;
  for (std::size_t f = 0; f < labels.size(); ++f) {
    const double n = loads.contact_steps[f];
    if (mesh.face_wears(f))
      w.wear_face_steps += n;
    else if (labels[f] == meshes::label::side)
      w.side_steps += n;
    else if (labels[f] == meshes::label::bottom)
      w.bottom_steps += n;
  }
  // The frame's outer box in the sample frame (the sample's own box without a holder).
  const auto& g = p.geometry.sample;
  const double rim = holder ? p.geometry.tester.holder_rim_width : 0;
  const meshes::Vec3 lo{-g.width / 2 - rim, -g.length / 2 - rim, -rim},
      hi{g.width / 2 + rim, g.length / 2 + rim, g.thickness};
  const meshes::SampleFrame frame(g, p.geometry.placement);
  const auto& particles = scene.system().particles;
  for (std::size_t i = 0; i < particles.n_real; ++i) {
    const auto q = frame.point_to_sample(particles.position[i]);
    // Distance from the centre to the box (0 inside); inside counts as a full overlap.
    const meshes::Vec3 d{std::max({lo.x - q.x, 0.0, q.x - hi.x}),
                         std::max({lo.y - q.y, 0.0, q.y - hi.y}),
                         std::max({lo.z - q.z, 0.0, q.z - hi.z})};
    const double r = particles.radius[i];
    w.worst_overlap = std::max(w.worst_overlap, (r - meshes::norm(d)) / r);
  }
  return w;
}
} // namespace

TEST_CASE("with the holder no particle touches the sample's sides or underside, without it they do",
          "[coupling][holder]") {
  const Window frame = settled_window(true);
  INFO("frame: wear face " << frame.wear_face_steps << ", sides " << frame.side_steps << ", bottom "
                           << frame.bottom_steps << " contact-steps; deepest "
                           << "overlap with the frame " << frame.worst_overlap << " radii");
  CHECK(frame.holder_wall >= 0);
  CHECK(frame.wear_face_steps > 0);
  CHECK(frame.side_steps == 0);
  CHECK(frame.bottom_steps == 0);
  CHECK(frame.worst_overlap < 0.1);

  const Window none = settled_window(false);
  INFO("none: wear face " << none.wear_face_steps << ", sides " << none.side_steps << ", bottom "
                          << none.bottom_steps << " contact-steps");
  CHECK(none.holder_wall == -1);
  CHECK(none.wear_face_steps > 0);
  CHECK(none.side_steps > 0);
}
