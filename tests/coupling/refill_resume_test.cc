// A run continued from a checkpoint kept without its particle bed (Checkpoint::has_bed, what
// cases/reference-study/keep_running.sh carries between machines): the small tester case of
// the stop-and-resume test (30-degree sector, s = 4, wear amplified 20 times) with two
// dem-only and two staged stages, run to the end of stage 3 and continued twice, once from its
// checkpoint with the bed (the uninterrupted run) and once from the same checkpoint without
// it (nor the sample's volume mesh). The second meshes the sample from its kept surface,
// fills the bed anew on the worn surface, runs it for the schedule's two dem-only stages and
// then wears stage 4 from the same surface: stages 1 to 3 stay as they were, bit for bit;
// stage 4's wear-law volume lies within 50 % of the uninterrupted run's mean per stage (the
// same flow, another bed: measured +9 %, where the uninterrupted stages themselves scatter by
// +-24 %); the volume applied is the amplified DEM volume, taken off the kept surface's
// volume; the checkpoint after it holds a bed and a volume mesh again. A checkpoint without
// its bed written inside a stage is refused, naming the file.
#include "coupling/app/run_command.h"
#include "coupling/output/checkpoint.h"
#include "coupling/parameters/tester_scene_case.h"
#include "meshes/surface_mesh.h"
#include "wearsim_process.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace wear::coupling;
namespace fs = std::filesystem;

namespace {

int run_case(const std::string& case_file, const RunOptions& options, std::ostream& log) {
  return run_scene_case(run_case_of(read_case(case_file)), log, options);
}

// Column `name` of stages.csv's row for stage `stage` (1-based) as a number.
double stage_value(const std::vector<std::vector<std::string>>& rows, int stage,
                   const std::string& name) {
  const auto& header = rows.at(0);
  const auto at = std::find(header.begin(), header.end(), name);
  REQUIRE(at != header.end());
  return std::stod(rows.at(std::size_t(stage)).at(std::size_t(at - header.begin())));
}

// The small tester case in folder `dir` with two dem-only and two staged stages, run until
// `stages` are done: its case file's name, and its checkpoint then.
std::pair<std::string, Checkpoint> run_until(const std::string& dir, int stages,
                                             std::ostream& log) {
  fs::remove_all(dir);
  const std::string case_file = dir + ".prm";
  std::ofstream(case_file) << small_tester_case_file(dir, "2 dem-only, 2 staged");
  RunOptions stop;
  stop.stop_after = stages;
  REQUIRE(run_case(case_file, stop, log) == 0);
  Checkpoint c = read_checkpoint(dir + "/checkpoint.h5");
  REQUIRE(c.stages_done == stages);
  return {case_file, c};
}

// The checkpoint as keep_running.sh keeps it: no bed, the sample without its volume mesh.
void strip_bed(Checkpoint& c) {
  c.has_bed = false;
  c.dem = {};
  auto& sample = c.scene.parts.at(0).sample;
  sample.vertices.clear();
  sample.tetrahedra.clear();
  sample.boundary_faces.clear();
  sample.boundary_ids.clear();
}

} // namespace

TEST_CASE("wearsim run: a checkpoint kept without its particle bed continues with the bed "
          "filled anew",
          "[coupling][run][stop][refill]") {
  const std::string dir = "refill_run", kept = dir + ".kept", full = dir + ".full";
  for (const auto& d : {kept, full})
    fs::remove_all(d);
  std::ostringstream log;
  auto [case_file, c] = run_until(dir, 3, log);
  const std::string checkpoint = dir + "/checkpoint.h5";
  REQUIRE(c.scene.parts.at(0).open.duration == 0);
  fs::copy(dir, kept, fs::copy_options::recursive);

  // The uninterrupted run: stage 4 from the checkpoint with its bed.
  RunOptions resume;
  resume.resume = true;
  REQUIRE(run_case(case_file, resume, log) == 0);
  fs::rename(dir, full);

  // The same run continued from the checkpoint without its bed.
  fs::rename(kept, dir);
  const double volume_kept = wear::meshes::enclosed_volume(c.scene.parts.at(0).sample.surface);
  strip_bed(c); // kept without its volume mesh too
  write_checkpoint(checkpoint, c);
  fs::remove(dir + "/checkpoint.previous.h5"); // the write kept the one with the bed
  CHECK_FALSE(read_checkpoint(checkpoint).has_bed);
  std::ostringstream refilled;
  REQUIRE(run_case(case_file, resume, refilled) == 0);
  INFO(refilled.str());
  CHECK_THAT(refilled.str(), Catch::Contains("a checkpoint without its particle bed") &&
                                 Catch::Contains("warm-up of the new bed") &&
                                 Catch::Contains("stage 4 staged done"));

  const std::string stages = "/parts/sample/stages.csv";
  const auto a = physical_columns(full + stages), b = physical_columns(dir + stages);
  REQUIRE(a.size() == 5);
  REQUIRE(b.size() == 5);
  for (int k = 1; k <= 3; ++k)
    CHECK(a[std::size_t(k)] == b[std::size_t(k)]);
  // The uninterrupted run's wear per stage after the first scatters by about a quarter about
  // its mean (a small bed: measured 2.57e-11 to 4.32e-11 m^3 in stages 2 to 4); the continued
  // stage is held to that mean within twice as much. Counting the warm-up's two stages, or
  // a stage with no bed, would be out by 100 % or more.
  double uninterrupted = 0;
  for (int k = 2; k <= 4; ++k)
    uninterrupted += stage_value(a, k, "dem_wear_volume_m3") / 3;
  const double continued = stage_value(b, 4, "dem_wear_volume_m3");
  INFO("wear-law volume: the uninterrupted run's mean over stages 2 to 4 "
       << uninterrupted << " m^3, the continued stage 4 " << continued << " m^3");
  REQUIRE(uninterrupted > 0);
  CHECK(std::abs(continued / uninterrupted - 1) < 0.5);
  CHECK(stage_value(b, 4, "applied_volume_m3") ==
        Approx(20 * continued).epsilon(1e-8)); // the amplified DEM volume, as in every stage
  // The part meshed anew from its kept surface encloses the same volume: stage 4 takes the
  // volume it applied off the kept one (the stage's own volume change is exact to 1e-3).
  const Checkpoint after = read_checkpoint(checkpoint);
  const double volume_after = wear::meshes::enclosed_volume(after.scene.parts.at(0).sample.surface);
  CHECK(volume_kept - volume_after ==
        Approx(stage_value(b, 4, "geometry_volume_change_m3")).epsilon(1e-6));
  CHECK(after.stages_done == 4);
  CHECK_FALSE(after.scene.parts.at(0).sample.tetrahedra.empty());
  CHECK(after.has_bed);
  CHECK_FALSE(after.dem.position.empty());

  // Without its bed and inside a stage: refused before anything runs, the file named.
  c.scene.parts.at(0).open.duration = 0.1;
  write_checkpoint(checkpoint, c);
  CHECK_THROWS_WITH(run_case(case_file, resume, log),
                    Catch::Contains(checkpoint) && Catch::Contains("holds no particle bed") &&
                        Catch::Contains("inside stage 4"));
}

TEST_CASE("wearsim run: a run continued without its scene tables resumes again from its full "
          "checkpoint",
          "[coupling][run][stop][refill]") {
  // keep_running.sh carries a checkpoint without its bed and without the scene tables; the
  // continued run starts them again at its next record. Stopped again after a stage, its full
  // checkpoint says which record the tables start at, and --resume reads them from there:
  // counted from record 1 they held fewer rows than the checkpoint's records, and the run was
  // refused ("scene_series.csv holds 51 records, the checkpoint 111").
  const std::string dir = "refill_tables";
  std::ostringstream log;
  auto [case_file, c] = run_until(dir, 2, log);
  const std::string checkpoint = dir + "/checkpoint.h5";
  const int kept_records = c.scene.n_records;
  REQUIRE(kept_records > 0);
  CHECK(c.scene.first_table_record == 1);
  // As keep_running.sh keeps it: no bed, no volume mesh, no scene tables.
  strip_bed(c);
  write_checkpoint(checkpoint, c);
  for (const auto* f : {"/checkpoint.previous.h5", "/scene_series.csv", "/scene_wear.csv"})
    fs::remove(dir + f);

  RunOptions resume_one;
  resume_one.resume = true;
  resume_one.stop_after = 1;
  std::ostringstream continued;
  REQUIRE(run_case(case_file, resume_one, continued) == 0);
  INFO(continued.str());
  REQUIRE_THAT(continued.str(), Catch::Contains("tables start again at record " +
                                                std::to_string(kept_records + 1)) &&
                                    Catch::Contains("stopped after stage 3 as asked"));
  const Checkpoint after_three = read_checkpoint(checkpoint);
  CHECK(after_three.scene.first_table_record == kept_records + 1);

  RunOptions resume;
  resume.resume = true;
  std::ostringstream resumed;
  REQUIRE(run_case(case_file, resume, resumed) == 0);
  INFO(resumed.str());
  CHECK_THAT(resumed.str(), Catch::Contains("stage 4 staged done"));
  const Checkpoint end = read_checkpoint(checkpoint);
  CHECK(end.stages_done == 4);
  CHECK(end.scene.first_table_record == kept_records + 1);
  // One row per record from the first the tables hold.
  CHECK(int(physical_columns(dir + "/scene_series.csv").size()) - 1 ==
        end.scene.n_records - kept_records);
}
