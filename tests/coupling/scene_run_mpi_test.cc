// `wearsim scene-run` under mpiexec: a small hopper (1,500 spheres of 6 mm in a 200 mm bin,
// the plug of its 50 mm orifice dropping at 0.15 s, an outlet below), one thread per rank,
// each run in its own folder:
// - twice on 2 ranks, by `wearsim scene-run` and by `wearsim run` (which takes any scene): the
//   series (every column) and the last particles bit for bit;
// - stopped by SIGTERM on 2 ranks after a checkpoint and resumed on 2: the same bits as the
//   uninterrupted run;
// - stopped on 3 ranks and resumed on 2, and stopped on 2 and resumed as one process: they
//   finish, say the scene is decomposed again, and keep the count balance (filled = in the
//   scene + taken by the outlet) in every record.
// - two wearing parts (the plate scene of plate_scene.h with its north side wearing) on 2
//   ranks: each part's stages run on every rank's copy (checked the same bit for bit by the
//   run), rank 0 writes each part's tables, and each part's staged load is its wall's contact
//   force the DEM recorded over the ranks (window-weighted, to 1e-8: the part's load is
//   summed face by face over the ranks, the series' force as a total, and both are read from
//   tables of 10 digits).
// - the node-moving (reference) scheme on the plate on 2 ranks: every rank moves the nodes on
//   the same steps by the wear summed over the ranks, and the moves add up to the amplified
//   wear-law volume of each stage (1e-8: tables of 10 digits).
// The rank counts' discharges within the seeds' spread: cases/hopper/README.md (a study).
#include "plate_scene.h"
#include "wearsim_process.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <thread>

namespace fs = std::filesystem;

namespace {

const char* const hopper = R"(subsection Scene
  set Walls = bin, floor, plug
  set Outlets = below
  set Domain minimum = -0.3, -0.3, -0.5
  set Domain maximum = 0.3, 0.3, 0.5
  set End time = 0.45
  set Output interval = 0.05
  subsection Wall bin
    set Source = cylinder
    set Axis = 0, 0, 0.4
    set Radius = 0.1
    set Mesh size = 0.01
  end
  subsection Wall floor
    set Source = disc
    set Radius = 0.1
    set Inner radius = 0.025
    set Mesh size = 0.005
  end
  subsection Wall plug
    set Source = disc
    set Radius = 0.025
    set Mesh size = 0.005
    set Motion = translation
    set Velocity = 0, 0, -2
    set Start time = 0.15
    set End time = 0.3
  end
  subsection Fill
    set Region = box
    set Minimum = -0.068, -0.068, 0.003
    set Maximum = 0.068, 0.068, 0.08
    set Count = 1500
  end
  subsection Outlet below
    set Minimum = -0.3, -0.3, -0.5
    set Maximum = 0.3, 0.3, -0.1
  end
end
subsection DEM
  set PSD diameters = 0.006
  set PSD mass fractions = 1
  set Scaling factor = 1
  set Particle shear modulus = 1e7
  set Rolling friction particle-particle = 0.05
  set Rolling friction particle-wall = 0.05
  set Threads = 1
end
subsection Output
  set Directory = out
  set Checkpoint interval = 0.05
end
)";

/// A fresh folder with the hopper's case: of spheres, or of 300 clumps ('crushed stone 4').
std::string fresh(const std::string& dir, bool clumps = false) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string text = hopper;
  if (clumps) {
    text.replace(text.find("set Count = 1500"), 16, "set Count = 300");
    text.insert(text.find("  set Threads = 1"), "  set Particle shape = crushed stone 4\n");
  }
  std::ofstream(dir + "/case.prm") << text;
  return dir;
}

/// A run on `n_ranks` stopped by SIGTERM once it wrote a checkpoint: true when it stopped
/// (mpiexec exits with 1 when its ranks exit with 128 + the signal: the log tells).
bool stop_after_checkpoint(const std::string& dir, int n_ranks) {
  const pid_t pid = start_in(dir, n_ranks, "", "case.prm", "stop.log", "scene-run");
  for (;;) {
    if (waitpid(pid, nullptr, WNOHANG) == pid)
      return false;
    if (fs::exists(dir + "/out/checkpoint.h5"))
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGTERM);
  return wait_for(pid) > 0 &&
         file_text(dir + "/stop.log").find("stopped by SIGTERM") != std::string::npos;
}

/// Every record of a run keeps filled = in the scene + removed (columns 2 and 4 of the series).
void check_count_balance(const std::string& out, long filled = 1500, long drained = 100) {
  const auto rows = physical_columns(out + "/scene_series.csv");
  REQUIRE(rows.size() > 5);
  CHECK(rows[0].at(1) == "n_particles");
  CHECK(rows[0].at(3) == "n_removed");
  for (std::size_t k = 1; k < rows.size(); ++k)
    CHECK(std::stol(rows[k].at(1)) + std::stol(rows[k].at(3)) == filled);
  CHECK(std::stol(rows.back().at(3)) > drained); // it drained
}

/// The index of column `c` in a table's header row.
std::size_t column_index(const std::vector<std::vector<std::string>>& rows, const std::string& c) {
  const auto at = std::find(rows.at(0).begin(), rows[0].end(), c);
  REQUIRE(at != rows[0].end());
  return std::size_t(at - rows[0].begin());
}

} // namespace

TEST_CASE(
    "wearsim scene-run and run over ranks: the same bits twice and through a checkpoint, resumed "
    "on another rank count",
    "[coupling][mpi]") {
  const std::string a = fresh("scene_mpi_a"), twice = fresh("scene_mpi_twice");
  REQUIRE(run_in(a, 2, "", "case.prm", "run.log", "scene-run") == 0);
  INFO(file_text(a + "/run.log"));
  CHECK_THAT(file_text(a + "/run.log"),
             Catch::Contains("over 2 MPI rank(s): balanced slabs along x"));
  check_count_balance(a + "/out");
  REQUIRE(run_in(twice, 2, "", "case.prm", "run.log", "run") == 0); // any scene
  CHECK_THAT(file_text(twice + "/run.log"),
             Catch::Contains("over 2 MPI rank(s): balanced slabs along x"));
  CHECK(file_text(twice + "/out/scene_series.csv") == file_text(a + "/out/scene_series.csv"));
  CHECK(file_text(twice + "/out/particles_9.vtu") == file_text(a + "/out/particles_9.vtu"));

  const std::string b = fresh("scene_mpi_b");
  if (stop_after_checkpoint(b, 2)) {
    REQUIRE(run_in(b, 2, "--resume", "case.prm", "resume.log", "scene-run") == 0);
    INFO(file_text(b + "/resume.log"));
    CHECK(file_text(b + "/out/scene_series.csv") == file_text(a + "/out/scene_series.csv"));
    CHECK(file_text(b + "/out/particles_9.vtu") == file_text(a + "/out/particles_9.vtu"));
  } else {
    WARN("the 2-rank run ended before the signal; nothing to resume");
  }

  for (const auto& [stop_on, resume_on] : {std::pair{3, 2}, std::pair{2, 0}}) {
    const std::string dir =
        fresh("scene_mpi_" + std::to_string(stop_on) + "_to_" + std::to_string(resume_on));
    if (!stop_after_checkpoint(dir, stop_on)) {
      WARN("the " << stop_on << "-rank run ended before the signal; nothing to resume");
      continue;
    }
    REQUIRE(run_in(dir, resume_on, "--resume", "case.prm", "resume.log", "scene-run") == 0);
    const std::string log = file_text(dir + "/resume.log");
    INFO(log);
    CHECK_THAT(log, Catch::Contains("the scene is decomposed again"));
    check_count_balance(dir + "/out");
  }
}

TEST_CASE("wearsim scene-run over ranks: a hopper of clumps drains whole bodies, resumes bit for "
          "bit and as one process",
          "[coupling][mpi][clump]") {
  // 300 clumps of 4 spheres: a body that leaves through the outlet leaves whole and counts
  // once (filled = in the scene + removed, in clumps), with the booked mass of whole bodies.
  const std::string a = fresh("scene_mpi_clumps", true);
  REQUIRE(run_in(a, 2, "", "case.prm", "run.log", "scene-run") == 0);
  INFO(file_text(a + "/run.log"));
  CHECK_THAT(file_text(a + "/run.log"), Catch::Contains("set up with 300 particles"));
  check_count_balance(a + "/out", 300, 20);
  const auto rows = physical_columns(a + "/out/scene_series.csv");
  const std::size_t removed = column_index(rows, "n_removed"),
                    mass = column_index(rows, "outlet_below_mass_kg");
  const double body =
      2650 * 3.14159265358979 / 6 * 0.006 * 0.006 * 0.006; // [kg], equivalent sphere
  CHECK(std::stod(rows.back().at(mass)) ==
        Approx(std::stol(rows.back().at(removed)) * body).epsilon(1e-6));
  CHECK_THAT(file_text(a + "/out/particles_9.vtu"), Catch::Contains("body orientation"));
  for (const int resume_on : {2, 0}) {
    const std::string dir = fresh("scene_mpi_clumps_" + std::to_string(resume_on), true);
    if (!stop_after_checkpoint(dir, 2)) {
      WARN("the 2-rank run ended before the signal; nothing to resume");
      continue;
    }
    REQUIRE(run_in(dir, resume_on, "--resume", "case.prm", "resume.log", "scene-run") == 0);
    INFO(file_text(dir + "/resume.log"));
    if (resume_on == 2) {
      CHECK(file_text(dir + "/out/scene_series.csv") == file_text(a + "/out/scene_series.csv"));
      CHECK(file_text(dir + "/out/particles_9.vtu") == file_text(a + "/out/particles_9.vtu"));
    } else {
      CHECK_THAT(file_text(dir + "/resume.log"), Catch::Contains("the scene is decomposed again"));
      check_count_balance(dir + "/out", 300, 20);
    }
  }
}

TEST_CASE("wearsim scene-run over ranks: two wearing parts, each worn on every rank",
          "[coupling][mpi]") {
  const std::string dir = "scene_mpi_parts";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_plate(dir + "/wear_plate.step");
  std::string text = two_part_case(plate_case("out"));
  text.insert(text.find("  set Output interval"), "  set Particle snapshots = false\n");
  std::ofstream(dir + "/case.prm") << text;
  REQUIRE(run_in(dir, 2, "", "case.prm", "run.log", "scene-run") == 0);
  INFO(file_text(dir + "/run.log"));
  for (const auto& [name, force] :
       {std::pair{"plate", "wall_plate_fz_N"}, std::pair{"north", "wall_north_fz_N"}}) {
    INFO("part " << name);
    const auto rows = physical_columns(dir + "/out/parts/" + name + "/stages.csv");
    REQUIRE(rows.size() == 3); // header, the settling stage, the staged one
    const auto column = [&](const std::string& c) { return column_index(rows, c); };
    const double settled = std::stod(rows[1].at(column("time_s")));
    CHECK(std::stod(rows[2].at(column("applied_volume_m3"))) > 0);
    CHECK(std::stod(rows[2].at(column("mean_force_z_N"))) ==
          Approx(window_weighted(dir + "/out/scene_series.csv", force, settled)).epsilon(1e-8));
    CHECK(fs::exists(dir + "/out/parts/" + std::string(name) + "/part_wear.csv"));
  }
}

TEST_CASE("wearsim scene-run over ranks: the reference scheme moves the nodes on every rank",
          "[coupling][mpi]") {
  const std::string dir = "scene_mpi_reference";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_plate(dir + "/wear_plate.step");
  std::string text = reference_plate_case("out", "2 reference");
  text.insert(text.find("  set Output interval"), "  set Particle snapshots = false\n");
  std::ofstream(dir + "/case.prm") << text;
  REQUIRE(run_in(dir, 2, "", "case.prm", "run.log", "scene-run") == 0);
  INFO(file_text(dir + "/run.log"));
  const auto rows = physical_columns(dir + "/out/parts/plate/stages.csv");
  REQUIRE(rows.size() == 3);
  const auto column = [&](const std::string& c) { return column_index(rows, c); };
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const double dem_wear = std::stod(rows[k].at(column("dem_wear_volume_m3")));
    CHECK(dem_wear > 0);
    CHECK(std::stod(rows[k].at(column("applied_volume_m3"))) ==
          Approx(100 * dem_wear).epsilon(1e-8)); // tables of 10 digits
  }
}
