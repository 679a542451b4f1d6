// A run's output folder (run_folder.h). A folder holds a run once a run has written its series,
// its tables or a checkpoint there; --overwrite moves that run aside rather than deleting it, so
// that a new run which fails before its first checkpoint loses nothing.
#include "coupling/loop/run_folder.h"

#include "meshes/atomic_file.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace wear::coupling {

namespace {

bool holds_run(const std::string& dir) {
  for (const char* f :
       {"scene_series.csv", "stages.csv", "summary.csv", "checkpoint.h5", "checkpoint.previous.h5"})
    if (std::filesystem::exists(dir + "/" + f))
      return true;
  return false;
}

} // namespace

std::string prepare_run_folder(const CaseParameters& p, const RunOptions& options,
                               std::ostream& log) {
  const std::string& dir = p.output.directory;
  std::string aside;
  if (!options.resume && holds_run(dir)) {
    if (!options.overwrite)
      throw std::runtime_error(
          "Output/Directory: '" + dir +
          "' holds a run (its series, tables or a checkpoint); continue "
          "it with --resume, replace it with --overwrite, or set another Output/Directory");
    aside = dir + ".replaced";
    if (std::filesystem::exists(aside))
      throw std::runtime_error("--overwrite: '" + aside +
                               "' already holds a run an earlier "
                               "--overwrite moved aside and could not delete; look at it and "
                               "remove it first");
    std::error_code ec;
    std::filesystem::rename(dir, aside, ec);
    if (ec)
      throw std::runtime_error("--overwrite: cannot move the run in '" + dir + "' to '" + aside +
                               "' (" + ec.message() + ")");
    log << "the run in '" << dir << "' is moved to '" << aside
        << "'; it is deleted when this run has written its first checkpoint" << std::endl;
  }
  try {
    meshes::ensure_directory(dir);
    write_resolved_parameters(p, dir + "/parameters.prm");
  } catch (const std::exception& e) {
    throw std::runtime_error("Output/Directory: cannot write into '" + dir + "' (" + e.what() +
                             ")");
  }
  return aside;
}

} // namespace wear::coupling
