// The wear loop on a scene's wearing part (issue 33, item 3): a plate read from STEP slides
// under a bed of particles held by a fixed frame. Checked: the CAD surfaces keep their
// numbers under their roles in both the DEM and the FEM meshes, the part's volume and
// surface areas are the CAD solid's, the stage's removed volume is the amplified Archard
// law of the DEM's own per-label records, the FEM receives the DEM's force on the part, the
// geometry loses exactly the removed volume, only the wearing surface wears, and the DEM wall
// carries the worn surface afterwards. Bad wear-loop set-ups are refused naming the parameter.
#include "coupling/app/run_command.h"
#include "coupling/app/scene_run_command.h"
#include "coupling/loop/scene_coupled_run.h"
#include "coupling/output/hdf5_file.h"
#include "dem/scene/scene_walls.h"
#include "error_of.h"
#include "fem/sample_triangulation.h"
#include "meshes/gmsh_session.h"
#include "plate_scene.h"
#include "wearsim_process.h"

#include <catch2/catch.hpp>

#include <gmsh.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <thread>
#include <vector>

using namespace wear;
using namespace wear::coupling;

namespace {

// The Archard load-distance per label of wall `wall` in scene_wear.csv's windows ending
// after `after` [s].
std::map<std::string, double> archard_after(const std::string& path, const std::string& wall,
                                            double after) {
  std::map<std::string, double> sum;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string t, w, label, a;
    std::getline(s, t, ',');
    std::getline(s, w, ',');
    std::getline(s, label, ',');
    std::getline(s, a, ',');
    if (w == wall && std::stod(t) > after + 1e-9)
      sum[label] += std::stod(a);
  }
  return sum;
}

// Waits until the run `pid` writing into `dir` has checkpointed inside its stage 2 (stage 1
// done, more than 5 records); false when it ended before.
bool inside_stage_2(pid_t pid, const std::string& dir) {
  while (waitpid(pid, nullptr, WNOHANG) == 0) {
    try {
      const Checkpoint c = read_checkpoint(dir + "/checkpoint.h5");
      if (c.stages_done == 1 && c.scene.n_records > 5)
        return true;
    } catch (const std::exception&) {
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

} // namespace

TEST_CASE("scene wear loop: a STEP plate worn by a bed it slides under", "[coupling][scene]") {
  write_plate("wear_plate.step");
  std::filesystem::remove_all("scene_wear_out");
  const auto p = read_text("scene_wear.prm", plate_case("scene_wear_out"));
  std::ostringstream log;
  SceneCoupledRun run(p, log);
  REQUIRE(run.run() == 0);
  INFO(log.str());
  REQUIRE(run.parts().size() == 1);
  const auto& part = run.parts()[0].sample();
  const auto& surface = part.surface();

  // Labels: each CAD surface by number under its role, in the FEM and the DEM alike.
  std::map<int, double> area;
  const auto areas = meshes::face_areas(surface);
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    area[surface.face_labels[f]] += areas[f];
  using meshes::label::part_surface;
  using PartRole = meshes::FaceRole;
  REQUIRE(area.size() == 6);
  CHECK(area.at(part_surface(PartRole::clamped, 5)) == Approx(120e-3 * 60e-3).epsilon(1e-9));
  // A side loses the strip its top edge receded by (the wear depth, below 0.1 mm here).
  CHECK(area.at(part_surface(PartRole::free, 1)) == Approx(60e-3 * 10e-3).epsilon(1e-2));
  // The worn top keeps its area to the recession's tilt of the faces (second order).
  CHECK(area.at(part_surface(PartRole::wearing, 6)) == Approx(120e-3 * 60e-3).epsilon(1e-5));
  const auto boundary_ids = part.triangulation().get_boundary_ids();
  CHECK(boundary_ids.size() == 6);
  const auto& wall_mesh = run.scene().walls()[0].surface.mesh;
  CHECK(wall_mesh.revision() == surface.revision());
  CHECK(run.scene().system().wall(0).mesh().n_faces() == surface.n_faces());

  // Stages: the first settles the bed on the resting plate and wears nothing.
  REQUIRE(run.parts()[0].stages().size() == 2);
  const auto& settle = run.parts()[0].stages()[0];
  const auto& staged = run.parts()[0].stages()[1];
  CHECK(settle.applied_volume == 0);
  REQUIRE(staged.applied_volume > 0);
  // The removed volume is A alpha times the Archard load-distance the DEM recorded on the
  // wearing surface over the stage's windows (scene_wear.csv, 9 digits).
  const auto archard = archard_after("scene_wear_out/scene_wear.csv", "plate", settle.time);
  REQUIRE(archard.count("S6") == 1);
  CHECK(staged.dem_wear_volume == Approx(1e-7 * archard.at("S6")).epsilon(1e-7));
  CHECK(staged.applied_volume == Approx(100 * staged.dem_wear_volume).epsilon(1e-12));
  // The geometry lost what was asked, and the mesh's volume is the CAD plate's less that.
  CHECK(staged.geometry_volume_change == Approx(staged.applied_volume).epsilon(2e-3));
  CHECK(fem::mesh_volume(part.triangulation()) ==
        Approx(120e-3 * 60e-3 * 10e-3 - staged.geometry_volume_change).epsilon(1e-9));
  // Only the wearing surface wears.
  for (std::size_t f = 0; f < surface.n_faces(); ++f)
    if (surface.face_labels[f] != part_surface(PartRole::wearing, 6))
      REQUIRE(part.removed_volume()[f] == 0);
  CHECK(run.parts()[0].removed_per_label().at(part_surface(PartRole::wearing, 6)) ==
        Approx(staged.applied_volume).epsilon(1e-12));
  // The FEM took the bed's weight on the plate: the DEM's force, downwards, and the plate
  // bends under it.
  const auto fz = series_after("scene_wear_out/scene_series.csv", "wall_plate_fz_N", settle.time);
  REQUIRE(fz.size() == 2); // two windows of equal length
  CHECK(staged.mean_force_z == Approx(0.5 * (fz[0] + fz[1])).epsilon(1e-6));
  CHECK(staged.mean_force_z < 0);
  CHECK(staged.max_displacement > 0);
  CHECK(staged.max_von_mises_ball > 0);
  CHECK(std::filesystem::exists("scene_wear_out/parts/plate/history.xdmf"));
  CHECK(std::filesystem::exists("scene_wear_out/parts/plate/part_wear.csv"));
  CHECK(std::filesystem::exists("scene_wear_out/walls_4/plate.vtu"));
  CHECK(std::filesystem::exists("scene_wear_out/particles_4.vtu")); // Particle snapshots
  // The binned fields of the last window: every particle is inside the frame's grid.
  const Hdf5Reader fields("scene_wear_out/fields/record_0004.h5");
  CHECK(fields.dims("solid_fraction") == std::vector<std::size_t>{3, 2, 2});
  CHECK(fields.dims("velocity") == std::vector<std::size_t>{3, 2, 2, 3});
  double count = 0;
  for (double n : fields.doubles("occupancy"))
    count += n;
  CHECK(count == Approx(150).epsilon(1e-12));
  CHECK(std::filesystem::exists("scene_wear_out/fields.xdmf"));
}

TEST_CASE("scene wear loop: two wearing parts, each with its own stages, stress and tables",
          "[coupling][scene]") {
  write_plate("wear_plate.step");
  std::filesystem::remove_all("scene_two_out");
  // Without particle snapshots (Scene/Particle snapshots = false): the tables and walls only.
  std::string text = two_part_case(plate_case("scene_two_out"));
  text.insert(text.find("  set Output interval"), "  set Particle snapshots = false\n");
  const auto p = read_text("scene_two.prm", text);
  std::ostringstream log;
  SceneCoupledRun run(p, log);
  REQUIRE(run.run() == 0);
  INFO(log.str());
  REQUIRE(run.parts().size() == 2);
  using meshes::label::part_surface;
  using PartRole = meshes::FaceRole;
  const struct {
    std::string name, wearing_label, force_column;
    int wearing;
    double volume; ///< [m^3] of the CAD solid
  } expected[2] = {{"plate", "S6", "wall_plate_fz_N", 6, 120e-3 * 60e-3 * 10e-3},
                   {"north", "S3", "wall_north_fz_N", 3, 50e-3 * 6e-3 * 50e-3}};
  double settled = 0;
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& e = expected[i];
    const auto& part = run.parts()[i];
    INFO("part " << e.name);
    CHECK(part.name() == e.name);
    CHECK(part.wall() == (i == 0 ? 0u : 4u));
    // Its own stages: the settling stage wears nothing, the staged one what its own DEM
    // records give, through its own FEM and geometry update.
    REQUIRE(part.stages().size() == 2);
    const auto& settle = part.stages()[0];
    const auto& staged = part.stages()[1];
    settled = settle.time;
    CHECK(settle.applied_volume == 0);
    REQUIRE(staged.applied_volume > 0);
    const auto archard = archard_after("scene_two_out/scene_wear.csv", e.name, settle.time);
    REQUIRE(archard.count(e.wearing_label) == 1);
    CHECK(staged.dem_wear_volume == Approx(1e-7 * archard.at(e.wearing_label)).epsilon(1e-7));
    CHECK(staged.applied_volume == Approx(100 * staged.dem_wear_volume).epsilon(1e-12));
    CHECK(staged.geometry_volume_change == Approx(staged.applied_volume).epsilon(2e-3));
    CHECK(fem::mesh_volume(part.sample().triangulation()) ==
          Approx(e.volume - staged.geometry_volume_change).epsilon(1e-9));
    // Its loads sum to the contact forces the DEM recorded on its wall: the stage's mean is
    // the windows' means weighted by their lengths.
    CHECK(staged.mean_force_z ==
          Approx(window_weighted("scene_two_out/scene_series.csv", e.force_column, settle.time))
              .epsilon(1e-9));
    CHECK(staged.max_von_mises_ball > 0);
    // Only its wearing surface wears, and the DEM wall carries its worn surface.
    const auto& surface = part.surface();
    for (std::size_t f = 0; f < surface.n_faces(); ++f)
      if (surface.face_labels[f] != part_surface(PartRole::wearing, e.wearing))
        REQUIRE(part.sample().removed_volume()[f] == 0);
    CHECK(part.removed_per_label().at(part_surface(PartRole::wearing, e.wearing)) ==
          Approx(staged.applied_volume).epsilon(1e-12));
    CHECK(run.scene().walls()[part.wall()].surface.mesh.revision() == surface.revision());
    // Its own table: one row per stage for its wearing surface only.
    const std::string table = file_text("scene_two_out/parts/" + e.name + "/part_wear.csv");
    CHECK(std::count(table.begin(), table.end(), '\n') == 3);
    CHECK_THAT(table, Catch::Contains("," + e.wearing_label + ","));
    CHECK_THAT(table, !Catch::Contains(i == 0 ? ",S3," : ",S6,"));
    CHECK(std::filesystem::exists("scene_two_out/parts/" + e.name + "/history.xdmf"));
  }
  CHECK(std::filesystem::exists("scene_two_out/scene_series.csv"));
  CHECK(!std::filesystem::exists("scene_two_out/particles_1.vtu"));
  // The bed presses on the box's wearing face: its normal load is the wall's y force.
  const auto& north = run.parts()[1].stages()[1];
  CHECK(north.wear_face_normal_force ==
        Approx(window_weighted("scene_two_out/scene_series.csv", "wall_north_fy_N", settled))
            .epsilon(1e-9));
  CHECK(north.wear_face_normal_force > 0);
}

TEST_CASE("scene wear loop: the reference scheme moves a part's nodes inside the DEM",
          "[coupling][scene]") {
  write_plate("wear_plate.step");
  const std::string dir = "scene_reference_out";
  std::filesystem::remove_all(dir);
  const std::string text = reference_plate_case(dir, "2 reference");
  const auto p = read_text(dir + ".prm", text);
  std::ostringstream log;
  SceneCoupledRun run(p, log);
  REQUIRE(run.run() == 0);
  INFO(log.str());
  const auto& part = run.parts().at(0);
  const dem::WallNodeMoves* moves = run.scene().node_moves(part.wall());
  REQUIRE(moves != nullptr);
  const auto& moved = moves->deformation();
  REQUIRE(part.stages().size() == 2);
  double dem_wear = 0, lost = 0;
  for (const auto& r : part.stages()) {
    INFO("stage " << r.stage);
    CHECK(r.distortion.empty());
    REQUIRE(r.dem_wear_volume > 0);
    // The moves add up to the amplified wear-law volume of the stage's windows.
    CHECK(r.applied_volume == Approx(100 * r.dem_wear_volume).epsilon(1e-9));
    dem_wear += r.dem_wear_volume;
    lost += r.geometry_volume_change;
  }
  CHECK(part.stages().back().cumulative_applied == Approx(100 * dem_wear).epsilon(1e-9));
  // The area-weighted node recession removes the asked volume to first order: the plate's
  // enclosed volume lost about that (its free sides tilt at the receding top edge).
  CHECK(lost == Approx(part.stages().back().cumulative_applied).epsilon(0.05));
  CHECK(lost == Approx(moved.enclosed_volume_loss()).epsilon(1e-12));
  // Every 50 engine steps a move (and one at each window's end): 0.2 s at the plate case's
  // step, less the settling before the first window.
  const double steps = 0.2 / run.scene().system().time_step();
  CHECK(double(moved.n_updates()) >= 0.9 * steps / 50);
  CHECK(double(moved.n_updates()) <= steps / 50 + 4 + 1);
  // The DEM's wall, the scene's wall and the node moves are one surface; the FEM sample is
  // untouched, its nodes where they were.
  const auto& wall = run.scene().walls()[part.wall()].surface.mesh;
  CHECK(run.scene().system().wall(int(part.wall())).mesh().vertices == moved.mesh().vertices);
  CHECK(wall.vertices == moved.mesh().vertices);
  CHECK(part.surface().vertices != moved.mesh().vertices);
  CHECK(meshes::enclosed_volume(part.surface()) == Approx(120e-3 * 60e-3 * 10e-3).epsilon(1e-9));
  // The clamped bottom keeps its place.
  for (std::size_t v = 0; v < wall.n_vertices(); ++v)
    if (part.surface().vertices[v].z < 1e-9)
      REQUIRE(wall.vertices[v] == part.surface().vertices[v]);
  const auto in_folder = [&](const std::string& folder) {
    std::filesystem::remove_all(folder);
    std::string t = text;
    return t.replace(t.find("set Directory = " + dir), 16 + dir.size(),
                     "set Directory = " + folder);
  };

  // Checkpointed as any scene run: stopped after stage 1 and resumed, the nodes move as in
  // the run without a stop, bit for bit.
  const std::string split = dir + "_split";
  const auto split_case = read_text(split + ".prm", in_folder(split));
  {
    std::ostringstream first_log;
    SceneCoupledRun first(split_case, first_log, {false, 1});
    REQUIRE(first.run() == 0);
    REQUIRE(first.parts()[0].stages().size() == 1);
  }
  std::ostringstream resumed_log;
  SceneCoupledRun resumed(split_case, resumed_log, {true, 0});
  REQUIRE(resumed.run() == 0);
  INFO(resumed_log.str());
  REQUIRE(resumed.parts()[0].stages().size() == 2);
  const auto& moved_again = resumed.scene().node_moves(0)->deformation();
  CHECK(moved_again.mesh().vertices == moved.mesh().vertices);
  CHECK(moved_again.n_updates() == moved.n_updates());
  CHECK(moved_again.swept_volume() == moved.swept_volume());
  CHECK(resumed.parts()[0].stages()[1].applied_volume == part.stages()[1].applied_volume);
  CHECK(file_text(split + "/parts/plate/part_wear.csv") ==
        file_text(dir + "/parts/plate/part_wear.csv"));
  CHECK(physical_columns(split + "/scene_series.csv") ==
        physical_columns(dir + "/scene_series.csv"));

  // At an amplification that recedes the top through the plate the surface distorts: the
  // surface stays the last valid one and the run stops after that stage, saying where.
  std::string worn = in_folder(dir + "_distorted");
  worn.replace(worn.find("set Amplification = 100"), 23, "set Amplification = 1e7");
  std::ostringstream distorted_log;
  SceneCoupledRun distorted(read_text(dir + "_distorted.prm", worn), distorted_log);
  REQUIRE(distorted.run() == 0);
  INFO(distorted_log.str());
  REQUIRE(distorted.parts()[0].stages().size() == 1);
  CHECK_THAT(distorted.parts()[0].stages()[0].distortion, Catch::Contains("at face"));
  CHECK_THAT(distorted_log.str(), Catch::Contains("the reference method distorted part 'plate'"));
  const auto& frozen = distorted.scene().node_moves(0)->deformation();
  CHECK(meshes::surface_quality(frozen.mesh()).valid());
}

TEST_CASE("scene wear loop: set-ups that cannot run are refused naming the parameter",
          "[coupling][scene]") {
  write_plate("wear_plate.step");
  const auto refused = [](const std::string& name, const std::string& text) {
    return error_of([&] {
      std::ostringstream log;
      SceneCoupledRun run(read_text(name, text), log);
      run.run();
    });
  };
  CHECK(refused("wear_noclamp.prm", plate_case("scene_wear_bad", "    set Clamped surfaces =\n"))
            .find("Scene/Wall plate/Clamped surfaces: the wearing part needs at least one") !=
        std::string::npos);
  CHECK(refused("wear_nosurface.prm",
                plate_case("scene_wear_bad", "    set Clamped surfaces = 5, 9\n"))
            .find("Scene/Wall plate/Clamped surfaces: the part has no surface 9 (its surfaces: "
                  "1, 2, 3, 4, 5, 6)") != std::string::npos);
  CHECK(refused("wear_both.prm", plate_case("scene_wear_bad", "    set Wearing surfaces = 5, 6\n"))
            .find("surface 5 is listed both as wearing and as clamped") != std::string::npos);
  // The node-moving method moves the nodes of a wall that keeps its place.
  CHECK(refused("wear_reference.prm", plate_case("scene_wear_bad", "", "2 reference"))
            .find("Scene/Wall plate/Motion: the node-moving method moves the nodes of a wall "
                  "that keeps its place") != std::string::npos);
  CHECK(refused("wear_word.prm", plate_case("scene_wear_bad", "    set Clamped surfaces = top\n"))
            .find("Scene/Wall plate/Clamped surfaces: 'top' is not a surface number") !=
        std::string::npos);
  CHECK(refused("wear_held.prm", plate_case("scene_wear_bad", "    set Held surfaces = 1, 5\n"))
            .find("surface 5 is listed both as clamped and as held") != std::string::npos);
  CHECK(refused("wear_held9.prm", plate_case("scene_wear_bad", "    set Held surfaces = 9\n"))
            .find("Scene/Wall plate/Held surfaces: the part has no surface 9") !=
        std::string::npos);
}

TEST_CASE("scene part: each surface's role from the case file is carried beside its label",
          "[coupling][scene]") {
  // The plate's sides 1 and 2 held, 5 clamped, 6 wearing, 3 and 4 free: each label's role in
  // the wall's mesh is the one its list gives, and the names say it.
  write_plate("wear_plate.step");
  const auto p =
      read_text("scene_roles.prm", plate_case("scene_roles_out", "    set Held surfaces = 1, 2\n"));
  const auto walls = dem::build_scene_walls(p.scene, p.geometry);
  const auto& mesh = walls.at(0).surface.mesh;
  using meshes::FaceRole;
  const std::map<std::string, FaceRole> expected{
      {"S1-held", FaceRole::held}, {"S2-held", FaceRole::held},       {"S3-free", FaceRole::free},
      {"S4-free", FaceRole::free}, {"S5-clamped", FaceRole::clamped}, {"S6", FaceRole::wearing}};
  std::map<std::string, FaceRole> found;
  for (std::size_t f = 0; f < mesh.n_faces(); ++f)
    found[meshes::label::name(mesh.face_labels[f])] = mesh.face_role(f);
  CHECK(found == expected);
}

TEST_CASE("scene wear loop: stopped by a signal or killed inside a stage, resumed bit for bit",
          "[coupling][scene]") {
  write_plate("wear_plate.step");
  // Windows of 0.02 s, a checkpoint after each (the interval is shorter than a window's work).
  const auto case_of = [](const std::string& dir) {
    std::string text = two_part_case(
        plate_case(dir, "", "1 dem-only, 2 staged", "  set Checkpoint interval = 1e-6\n"));
    const auto at = text.find("  set Output interval = 0.05\n");
    return text.replace(at, 29, "  set Output interval = 0.02\n");
  };
  const std::string a = "scene_resume_a";
  std::filesystem::remove_all(a);
  std::ofstream(a + ".prm") << case_of(a);
  REQUIRE(run_wearsim(a + ".prm", "", a + ".log", "scene-run") == 0);
  INFO(file_text(a + ".log"));
  std::mt19937 rng(Catch::rngSeed());
  for (const int signal : {SIGTERM, SIGKILL}) {
    const std::string b = std::string("scene_resume_") + (signal == SIGTERM ? "term" : "kill");
    std::filesystem::remove_all(b);
    std::ofstream(b + ".prm") << case_of(b);
    const pid_t pid = start_wearsim(b + ".prm", "", b + ".log", "scene-run");
    // Inside stage 2: its first checkpoint is there, then a random moment.
    REQUIRE(inside_stage_2(pid, b));
    std::this_thread::sleep_for(std::chrono::milliseconds(rng() % 200));
    kill(pid, signal);
    const int status = wait_for(pid);
    INFO(file_text(b + ".log"));
    if (signal == SIGTERM && status == 128 + SIGTERM)
      CHECK_THAT(file_text(b + ".log"),
                 Catch::Contains("continue with wearsim scene-run --resume"));
    else if (status == 0)
      WARN("the run ended before the signal came; its resume below has nothing left to do");
    REQUIRE(run_wearsim(b + ".prm", "--resume", b + ".resumed.log", "scene-run") == 0);
    INFO(file_text(b + ".resumed.log"));
    for (const char* table : {"/parts/plate/stages.csv", "/parts/north/stages.csv",
                              "/scene_series.csv", "/scene_wear.csv"}) {
      INFO(table);
      CHECK(physical_columns(b + table) == physical_columns(a + table));
    }
    for (const char* table : {"/parts/plate/part_wear.csv", "/parts/north/part_wear.csv"})
      CHECK(file_text(b + table) == file_text(a + table));
    const auto ca = read_checkpoint(a + "/checkpoint.h5"),
               cb = read_checkpoint(b + "/checkpoint.h5");
    CHECK(cb.stages_done == 3);
    REQUIRE(ca.scene.parts.size() == 2);
    REQUIRE(cb.scene.parts.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
      const auto &pa = ca.scene.parts[i], &pb = cb.scene.parts[i];
      CHECK(pb.sample.surface.vertices == pa.sample.surface.vertices);
      CHECK(pb.sample.removed_volume == pa.sample.removed_volume);
      CHECK(pb.face_von_mises == pa.face_von_mises);
    }
    CHECK(cb.dem.position == ca.dem.position);
    CHECK(cb.dem.pair_history == ca.dem.pair_history);
  }
  // A folder holding a run is refused without --resume or --overwrite.
  CHECK(run_wearsim(a + ".prm", "", a + ".again.log", "scene-run") == 1);
  CHECK_THAT(file_text(a + ".again.log"),
             Catch::Contains("--resume") && Catch::Contains("--overwrite"));
}

TEST_CASE("scene wear loop: a bed of clumps killed inside a stage resumes bit for bit",
          "[coupling][scene][clump]") {
  // The plate scene with DEM/Particle shape = crushed stone 4: the checkpoint carries the
  // bodies (pose, motion, members) beside their member spheres, and a run killed inside a
  // stage continues as the uninterrupted one. The time step is a fraction of the Rayleigh
  // time of the smallest member (0.35 of the equivalent sphere's would be 0.56 of it, above
  // the engine's limit of 0.4).
  write_plate("wear_plate.step");
  const auto case_of = [](const std::string& dir) {
    std::string text = two_part_case(
        plate_case(dir, "", "1 dem-only, 2 staged", "  set Checkpoint interval = 1e-6\n"));
    text.replace(text.find("  set Output interval = 0.05\n"), 29, "  set Output interval = 0.02\n");
    return text.insert(text.find("subsection DEM\n") + 15,
                       "  set Particle shape = crushed stone 4\n"
                       "  set Time step fraction = 0.35\n");
  };
  const std::string a = "scene_clumps_a", b = "scene_clumps_kill";
  for (const auto& dir : {a, b}) {
    std::filesystem::remove_all(dir);
    std::ofstream(dir + ".prm") << case_of(dir);
  }
  REQUIRE(run_wearsim(a + ".prm", "", a + ".log", "scene-run") == 0);
  INFO(file_text(a + ".log"));
  const pid_t pid = start_wearsim(b + ".prm", "", b + ".log", "scene-run");
  REQUIRE(inside_stage_2(pid, b));
  kill(pid, SIGKILL);
  wait_for(pid);
  REQUIRE(run_wearsim(b + ".prm", "--resume", b + ".resumed.log", "scene-run") == 0);
  INFO(file_text(b + ".resumed.log"));
  const auto ca = read_checkpoint(a + "/checkpoint.h5"), cb = read_checkpoint(b + "/checkpoint.h5");
  CHECK(cb.stages_done == 3);
  REQUIRE(ca.dem.clumps.size() == 150);
  CHECK(ca.dem.position.size() == 600);
  CHECK(cb.dem.position == ca.dem.position);
  CHECK(cb.dem.pair_history == ca.dem.pair_history);
  CHECK(cb.dem.clumps.position == ca.dem.clumps.position);
  CHECK(cb.dem.clumps.angular_momentum == ca.dem.clumps.angular_momentum);
  CHECK(cb.dem.clumps.member_id == ca.dem.clumps.member_id);
  for (std::size_t i = 0; i < ca.scene.parts.size(); ++i)
    CHECK(cb.scene.parts[i].sample.removed_volume == ca.scene.parts[i].sample.removed_volume);
  CHECK(physical_columns(b + "/scene_wear.csv") == physical_columns(a + "/scene_wear.csv"));
}

TEST_CASE("wearsim scene-run: bad options and arguments are refused naming the command",
          "[coupling][scene]") {
  RunOptions o;
  CHECK_THROWS_WITH(parse_run_arguments({"--resme", "a.prm"}, "scene-run", o),
                    Catch::Contains("wearsim scene-run: unknown option '--resme'"));
  CHECK_THROWS_WITH(parse_run_arguments({"a.prm", "b.prm"}, "scene-run", o),
                    Catch::Contains("expected one case file, got 'a.prm' and 'b.prm'"));
  CHECK_THROWS_WITH(parse_run_arguments({}, "scene-run", o),
                    Catch::Contains("wearsim scene-run [--resume | --overwrite] <case.prm>"));
  RunOptions both;
  CHECK_THROWS_WITH(parse_run_arguments({"--resume", "--overwrite", "a.prm"}, "scene-run", both),
                    Catch::Contains("--resume and --overwrite exclude each other"));
  RunOptions ok;
  CHECK(parse_run_arguments({"--resume", "a.prm"}, "scene-run", ok) == "a.prm");
  CHECK(ok.resume);
  // A case without a scene has nothing to run.
  std::ofstream("scene_none.prm") << "subsection Output\n  set Directory = scene_none\nend\n";
  std::ostringstream log;
  CHECK_THROWS_WITH(run_scene_run_command({"scene_none.prm"}, log),
                    Catch::Contains("Scene/Walls is empty: there is no scene to run"));
}