// Walls whose geometry moves (rigid_motion.h): the pose is exact, a particle resting on a
// translating or rotating wall moves with it, the loads land on the wall's faces in its own
// frame, and a run with moving walls resumes bit for bit.
#include "dem/engine/rigid_motion.h"
#include "dem/scene/scene_parameters.h"
#include "dem_fixtures.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace wear::dem;
using namespace wear::dem::testing;
using wear::meshes::cross;
using wear::meshes::dot;
using wear::meshes::norm;
using wear::meshes::SurfaceMesh;

namespace {

/// The parallelogram corner + a u + b v (a, b in [0, 1]) as two triangles, facing u x v.
SurfaceMesh rectangle(const Vec3& corner, const Vec3& u, const Vec3& v) {
  SurfaceMesh m;
  m.vertices = {corner, corner + u, corner + u + v, corner + v};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.face_labels.assign(2, wear::meshes::label::wall);
  return m;
}

/// The rectangle [x0, x1] x [y0, y1] at height z, facing +z.
SurfaceMesh floor_plate(double x0, double x1, double y0, double y1, double z) {
  return rectangle({x0, y0, z}, {x1 - x0, 0, 0}, {0, y1 - y0, 0});
}

/// The rectangle x = x0, [y0, y1] x [z0, z1], facing -x.
SurfaceMesh side_plate(double x0, double y0, double y1, double z0, double z1) {
  return rectangle({x0, y0, z0}, {0, 0, z1 - z0}, {0, y1 - y0, 0});
}

/// [m] Hertz overlap of a sphere of radius r pressed on a wall by force f (E* of the pair).
double hertz_overlap(double f, double e_star, double r) {
  return std::pow(3 * f / (4 * e_star * std::sqrt(r)), 2.0 / 3.0);
}

} // namespace

TEST_CASE("rigid motion: an oscillating wall's displacement is exact, a rotation is a rotation") {
  RigidMotion osc;
  osc.amplitude = {0.01, -0.004, 0.002};
  osc.frequency = 5;
  osc.start_time = 0.1;
  MeshWall wall(floor_plate(0, 1, 0, 1, 0), 0, WallMotion{}, false, "shaker");
  wall.set_rigid_motion(osc);
  REQUIRE(wall.moving());
  for (double t : {0.0, 0.1, 0.13, 0.27, 1.0, 12.345}) {
    wall.move_to(t);
    const double tau = std::max(0.0, t - osc.start_time);
    const Vec3 shift = osc.amplitude * std::sin(2 * pi * osc.frequency * tau);
    const auto moved = wall.world_vertices();
    for (std::size_t k = 0; k < moved.size(); ++k)
      CHECK(norm(moved[k] - (wall.mesh().vertices[k] + shift)) <= 1e-15);
    const Vec3 v =
        t >= osc.start_time
            ? osc.amplitude * (2 * pi * osc.frequency * std::cos(2 * pi * osc.frequency * tau))
            : Vec3{};
    CHECK(norm(wall.velocity_at({0.3, 0.2, 0}) - v) <= 1e-15 * (1 + norm(v)));
  }

  RigidMotion rot;
  rot.axis_point = {0.1, -0.2, 0.3};
  rot.axis = {1, 1, 1};
  rot.angular_velocity = 2;
  rot.velocity = {0.01, 0.02, -0.03};
  const Vec3 a = wear::meshes::normalized(rot.axis);
  const Vec3 body{0.4, 0.5, -0.6};
  for (double t : {0.3, 1.7, 40.0}) {
    const RigidPose pose = pose_at(rot, t);
    // Rodrigues by components: the part along the axis stays, the rest turns by omega t.
    const Vec3 d = body - rot.axis_point, along = a * dot(a, d);
    const double th = rot.angular_velocity * t;
    const Vec3 expected = rot.axis_point + rot.velocity * t + along + (d - along) * std::cos(th) +
                          cross(a, d) * std::sin(th);
    CHECK(norm(pose.to_world(body) - expected) <= 1e-14);
    CHECK(norm(pose.to_body(pose.to_world(body)) - body) <= 1e-14);
    // The material velocity is the time derivative of the pose (central difference).
    const double h = 1e-6;
    const Vec3 dxdt =
        (pose_at(rot, t + h).to_world(body) - pose_at(rot, t - h).to_world(body)) / (2 * h);
    const Vec3 v = pose.velocity_at(pose.to_world(body));
    CHECK(norm(v - dxdt) <= 1e-8 * norm(v));
  }
}

TEST_CASE("rigid motion: a scene wall's Motion and Start time become its rigid motion") {
  SceneWallParameters w;
  w.name = "screen";
  w.motion = "oscillation";
  w.amplitude = {0, 0, 0.003};
  w.frequency = 12;
  w.velocity = {1, 0, 0}; // not the chosen motion: ignored
  w.start_time = 0.5;
  const RigidMotion m = rigid_motion(w);
  for (double t : {0.2, 0.5, 0.61}) {
    const double tau = std::max(0.0, t - 0.5);
    CHECK(norm(pose_at(m, t).translation - Vec3{0, 0, 0.003 * std::sin(2 * pi * 12 * tau)}) <=
          1e-15);
  }
  w.motion = "rotation";
  w.axis_point = {1, 0, 0};
  w.angular_velocity = 2;
  const RigidPose turned = pose_at(rigid_motion(w), 0.5 + pi / 4); // a quarter turn about x = 1
  CHECK(norm(turned.to_world({2, 0, 0}) - Vec3{1, 1, 0}) <= 1e-15);
  // A gate: it moves between its start and end times, then stays where it got to.
  w.motion = "translation";
  w.velocity = {0, 0, -0.5};
  w.end_time = 0.6;
  const RigidMotion gate = rigid_motion(w);
  CHECK(pose_at(gate, 0.55).translation.z == Approx(-0.025));
  CHECK(pose_at(gate, 2.0).translation.z == Approx(-0.05));
  CHECK(pose_at(gate, 2.0).velocity == Vec3{});
  CHECK(pose_at(gate, 0.55).velocity == Vec3{0, 0, -0.5});
  w.motion = "fixed";
  CHECK_FALSE(rigid_motion(w).moves());
}

TEST_CASE("rigid motion: bad motions are refused with the wall's name") {
  MeshWall wall(floor_plate(0, 1, 0, 1, 0), 0, WallMotion{}, false, "chute liner");
  RigidMotion m;
  m.angular_velocity = 1;
  m.axis = {0, 0, 0};
  CHECK_THROWS_WITH(wall.set_rigid_motion(m),
                    Catch::Contains("chute liner") && Catch::Contains("rotation axis"));
  m = {};
  m.amplitude = {0, 0, 0.01};
  CHECK_THROWS_WITH(wall.set_rigid_motion(m), Catch::Contains("frequency"));
  WallMotion surface;
  surface.angular_velocity = 1;
  MeshWall belt(floor_plate(0, 1, 0, 1, 0), 0, surface, false, "belt");
  m = {};
  m.velocity = {1, 0, 0};
  CHECK_THROWS_WITH(belt.set_rigid_motion(m),
                    Catch::Contains("belt") && Catch::Contains("surface motion"));
}

// The particle-wall pairs of these tests have no rolling friction: the constant torque of
// The rolling friction of docs/theory.md section 2 chatters about zero relative spin (a few 1e-6
// rad/s at rest on a plate, fixed or moving alike), which would hide the 1e-6 relative these checks
// ask.

TEST_CASE("moving walls: a particle resting on a plate that starts to rise rises with it") {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0);
  MeshWall plate(floor_plate(-0.05, 0.05, -0.05, 0.05, 0), g, WallMotion{}, false, "lift");
  RigidMotion up;
  up.velocity = {0, 0, 0.05};
  up.start_time = 0.05; // settled first
  plate.set_rigid_motion(up);
  s.add_wall(plate);
  const double r = 0.005;
  s.particles.add({0.01, -0.02, r}, {}, r, 2650, g);
  s.setup();
  const auto steps = [&](double t) { return std::uint64_t(std::ceil(t / s.time_step())); };
  s.run(steps(0.3));
  const Vec3 v = s.particles.velocity[0];
  INFO("velocity " << v.x << " " << v.y << " " << v.z);
  CHECK(norm(v - up.velocity) <= 1e-6 * norm(up.velocity));
  // It rose with the plate (resting on it by its own weight's overlap) and stayed put.
  const double lift = up.velocity.z * (s.time() - up.start_time);
  CHECK(s.particles.position[0].z == Approx(r + lift).margin(2e-5));
  CHECK(std::abs(s.particles.position[0].x - 0.01) <= 1e-9);
  CHECK(s.n_rebuilds() > 5); // the plate's own displacement triggered the candidate lists
}

TEST_CASE("moving walls: a ball on a plate that starts to slide rolls at 2/7 of its speed") {
  // A plate at rest under a resting ball starts to translate at V. Friction at the contact
  // gives the ball an impulse J: v = J / m, and a spin omega = J x z r / I, |omega| =
  // 5/2 |J| / (m r). It slips until its contact point moves with the plate, v + r |omega| = V:
  // then v = 2/7 V and omega = 5/7 V x z / r, whatever the contact law's details (the tangential
  // spring's last swing is damped out).
  System s;
  const int g = add_gravel(s, 0.5, 0.3, 0);
  MeshWall plate(floor_plate(-0.05, 0.05, -0.05, 0.05, 0), g, WallMotion{}, false, "conveyor");
  RigidMotion slide;
  slide.velocity = {0.08, -0.06, 0}; // V = 0.1 m/s
  slide.start_time = 0.05;
  plate.set_rigid_motion(slide);
  s.add_wall(plate);
  const double r = 0.005;
  s.particles.add({0, 0, r}, {}, r, 2650, g);
  s.setup();
  s.run(std::uint64_t(std::ceil(0.3 / s.time_step())));
  const Vec3 v = s.particles.velocity[0], w = s.particles.angular_velocity[0];
  const Vec3 v_expected = slide.velocity * (2.0 / 7.0);
  const Vec3 w_expected = cross(slide.velocity, Vec3{0, 0, 1}) * (5.0 / 7.0 / r);
  INFO("velocity " << v.x << " " << v.y << " " << v.z << ", spin " << w.x << " " << w.y);
  CHECK(norm(v - v_expected) <= 1e-6 * norm(v_expected));
  CHECK(norm(w - w_expected) <= 1e-6 * norm(w_expected));
  // Its contact point moves with the plate, which has left it behind by 5/7 of its travel.
  CHECK(norm(v + cross(w, Vec3{0, 0, -r}) - slide.velocity) <= 1e-6 * norm(slide.velocity));
}

TEST_CASE("moving walls: a particle in a turning tray turns with it, its loads stay on the faces") {
  // A floor and an outer side wall turning about the z axis at Omega: a particle resting on
  // the floor against the side wall co-rotates, held on its circle by the side wall's normal
  // force m Omega^2 rho, its weight carried by the floor. Started in that state (velocity
  // Omega x x, spin Omega, the Hertz overlaps of both loads), it must stay in it.
  // Without friction: the state needs none, and the transient of the start could otherwise
  // lock a static pair of tangential forces into the corner (floor and side wall pushing
  // against each other), a valid equilibrium with other loads than the analytic ones.
  System s;
  const int g = add_gravel(s, 0.5, 0, 0);
  const double omega = 2, r = 0.005, x_side = 0.2;
  RigidMotion turn;
  turn.angular_velocity = omega;
  MeshWall floor(floor_plate(0, x_side, -0.05, 0.05, 0), g, WallMotion{}, true, "tray floor");
  MeshWall side(side_plate(x_side, -0.05, 0.05, 0, 0.05), g, WallMotion{}, true, "tray side");
  floor.set_rigid_motion(turn);
  side.set_rigid_motion(turn);
  const int w_floor = s.add_wall(floor), w_side = s.add_wall(side);
  const double e_star =
      s.materials.contact_table()[std::size_t(g) * (s.materials.n_materials() + 1)].e_star;
  const double mass = 2650 * 4.0 / 3.0 * pi * r * r * r;
  const double rho = x_side - r; // first guess; refined with the side overlap below
  const double d_side = hertz_overlap(mass * omega * omega * rho, e_star, r);
  const double d_floor = hertz_overlap(mass * 9.81, e_star, r);
  const Vec3 x0{x_side - r + d_side, 0, r - d_floor};
  s.particles.add(x0, Vec3{0, omega * x0.x, 0}, r, 2650, g);
  s.particles.angular_velocity[0] = {0, 0, omega};
  s.setup();
  s.run(std::uint64_t(0.2 / s.time_step())); // the small mismatch of the start decays
  s.reset_wear_integrals();
  const double t0 = s.time();
  s.run(std::uint64_t(1.0 / s.time_step())); // two radians more
  const double window = s.time() - t0;

  const Vec3 x = s.particles.position[0], v = s.particles.velocity[0];
  const Vec3 v_wall = cross(Vec3{0, 0, omega}, x);
  INFO("position " << x.x << " " << x.y << " " << x.z << ", angle " << omega * s.time());
  CHECK(norm(v - v_wall) <= 1e-6 * norm(v_wall));
  CHECK(norm(s.particles.angular_velocity[0] - Vec3{0, 0, omega}) <= 1e-6 * omega);
  // Where it started on the tray (the body frame): within a micrometre.
  const Vec3 on_tray = s.wall(w_floor).to_body(x);
  CHECK(norm(on_tray - x0) <= 1e-6);

  // The window's impulses, kept in the tray's frame: the weight on the floor, the
  // centripetal load on the side wall, each along the face's normal.
  const auto fl = s.wear_integrals(w_floor), sd = s.wear_integrals(w_side);
  const double weight = mass * 9.81 * window, centripetal = mass * omega * omega * x0.x * window;
  CHECK(norm(fl.total_impulse - Vec3{0, 0, -weight}) <= 1e-4 * weight);
  CHECK(norm(sd.total_impulse - Vec3{centripetal, 0, 0}) <= 1e-4 * centripetal);
  // No sliding: the load-weighted mean slip speed on the floor is the integrator's only. The
  // contact law sees the half-step velocity v(t + dt/2) at the positions of t + dt, which on
  // a circle lags by the centripetal acceleration times dt/2, Omega^2 rho dt/2 (1.5e-5 m/s
  // here, 4e-5 of the speed).
  const double lag = omega * omega * x0.x * s.time_step() / 2;
  CHECK(fl.total_archard / fl.total_normal_impulse <= 1.01 * lag);
}

TEST_CASE("moving walls: a tumbling box of particles resumes bit for bit") {
  const auto make = [](System& s) {
    const int g = add_gravel(s, 0.5, 0.5, 0.05);
    MeshWall box(box_walls(0.1), g, WallMotion{}, true, "tumbler");
    RigidMotion tumble;
    tumble.axis_point = {0.05, 0.05, 0.05};
    tumble.axis = {0, 1, 0};
    tumble.angular_velocity = 3;
    tumble.amplitude = {0.002, 0, 0.001};
    tumble.frequency = 4;
    box.set_rigid_motion(tumble);
    s.add_wall(box);
    s.settings.domain = {{-0.1, -0.1, -0.1}, {0.2, 0.2, 0.2}};
    return g;
  };
  System a;
  const int g = make(a);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 3; ++k)
        a.particles.add({0.02 + 0.02 * i, 0.02 + 0.02 * j, 0.015 + 0.02 * k}, {}, 0.006, 2650, g);
  a.setup();
  a.set_n_threads(2);
  a.run(1500);
  const SystemState middle = a.export_state();
  a.run(1500);

  System c;
  make(c);
  add_particles_of(c.particles, middle);
  c.setup();
  c.set_n_threads(2);
  c.resume_state(middle);
  c.run(1500);
  check_same_state(a, c);
  CHECK(a.n_rebuilds() == c.n_rebuilds());
}

TEST_CASE("moving walls: refused in a periodic sector") {
  System s;
  const int g = add_gravel(s, 0.5, 0.5, 0.01);
  MeshWall plate(floor_plate(0.1, 0.2, 0.01, 0.05, 0), g, WallMotion{}, false, "lift");
  RigidMotion up;
  up.velocity = {0, 0, 0.05};
  plate.set_rigid_motion(up);
  s.add_wall(plate);
  s.particles.add({0.15, 0.03, 0.01}, {}, 0.005, 2650, g);
  s.settings.periodic = {true, pi / 6};
  CHECK_THROWS_WITH(s.setup(), Catch::Contains("rigid motion") && Catch::Contains("periodic"));
}
