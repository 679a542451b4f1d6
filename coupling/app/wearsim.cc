// wearsim: the command-line entry point. Dispatches to one command per concern; every
// error reaches the user as one message naming the file or parameter, with exit code 1.
#include "coupling/app/bench_command.h"
#include "coupling/app/calibrate_command.h"
#include "coupling/app/compare_command.h"
#include "coupling/app/life_command.h"
#include "coupling/app/mesh_command.h"
#include "coupling/app/run_command.h"
#include "coupling/app/scene_command.h"
#include "coupling/app/scene_run_command.h"
#include "coupling/parameters/case_parameters.h"
#include "coupling/parameters/engine_version.h"
#include "coupling/parameters/tester_scene_case.h"
#include "dem/parallel/mpi_rank_link.h"

#include <deal.II/base/mpi.h>

#include <cstring>
#include <exception>
#include <iostream>
#include <string>

namespace {

void usage(std::ostream& out) {
  out << "usage: wearsim <command> [arguments]\n\n"
         "commands:\n"
         "  mesh <case.prm>          generate the sample (.msh/.stl/.vtu) and the tester walls\n"
         "  scene <case.prm>         build and check the walls of the case's Scene (CAD files,\n"
         "                           primitives): a table per wall and label, <name>.stl each\n"
         "  tester-scene <case.prm>  print the wear tester of a tester case written as a scene\n"
         "                           (walls, sector, consolidator, holder, sample, fill and\n"
         "                           stages in its Scene subsection), for scene-run\n"
         "  scene-run [--resume | --overwrite] <case.prm>\n"
         "                           the case's Scene: walls and their motions, fill, inlets,\n"
         "                           outlets, to Scene/End time, or with a wearing part and\n"
         "                           Scene/Stage duration the staged wear loop on it; writes\n"
         "                           scene_series.csv, particles_<k>.vtu, walls/, parts/<wall>/\n"
         "                           (stages.csv, part_wear.csv, history.xdmf); checkpoints for\n"
         "                           --resume\n"
         "  run [--resume | --overwrite] <case.prm>\n"
         "                           the coupled DEM-FEM wear run of the case's Coupling/Schedule\n"
         "                           (staged, reference or dem-only stages) on its scene; a wear-\n"
         "                           tester case runs as the scene tester-scene writes, its\n"
         "                           sample's tables in parts/sample/ (summary.csv, stages.csv,\n"
         "                           history.h5/.xdmf); checkpoint.h5 beside them; --resume\n"
         "                           continues a stopped run from its last checkpoint (between\n"
         "                           or inside stages); a folder holding a run is refused unless\n"
         "                           --overwrite (the old run is deleted after the new run's\n"
         "                           first checkpoint). SIGINT, SIGTERM and SIGUSR1 stop the\n"
         "                           run with a checkpoint (exit status 128 + signal)\n"
         "  dem [--resume | --overwrite] <case.prm>\n"
         "                           a wear-tester case in DEM alone: its DEM/Revolutions as\n"
         "                           dem-only stages of one revolution, stopping DEM/Revolutions\n"
         "                           after steady after the first steady one; as run\n"
         "  compare [--from <k>] [--part <wall>] <A1> [<A2> ...] -- <B1> [<B2> ...]\n"
         "  compare <runA> <runB>    runs of two sides (several seeds each, or one) side by\n"
         "                           side: wear per revolution after steady state and its\n"
         "                           reduction, per column, per stage peak von Mises and safety\n"
         "                           factor, each as mean +- 95 % interval (across runs, or\n"
         "                           batch means over one run's revolutions); --part <wall>:\n"
         "                           scene runs, that wearing part's wear per stage\n"
         "  calibrate <run> --measured <volume, e.g. 35.2mm^3> --revolutions <n>\n"
         "            [--from <revolution>]\n"
         "                           scale the run's wear coefficient so n steady revolutions\n"
         "                           wear the measured volume; writes <run>/calibration.prm\n"
         "  life <run> [--part <name>]\n"
         "                           the part's convex elements measured again on every kept\n"
         "                           stage surface on their unworn footprints (stage 0), which\n"
         "                           do not move with the worn surfaces' labels; writes\n"
         "                           parts/<part>/element_life.csv\n"
         "  bench dem [--workload annulus|annulus-clumps|sector5k|sector20k|sector45k|\n"
         "                        sample45k|tester]\n"
         "            [--threads N[,M..]] [--settle N] [--warm N] [--steps N] [--repeats N]\n"
         "            [--walls analytic|mesh]                       (annulus, sectors)\n"
         "            [--scale S] [--sample convex|plain] [--case FILE]   (tester)\n"
         "                           DEM benchmark: particle-steps/s, ns per particle-step by\n"
         "                           phase, memory; last line: particle_steps_per_second <value>\n"
         "  bench fem [--mesh-size H] [--degrees 1,2] [--stress-radius R]\n"
         "            [--output DIR]\n"
         "                           FEM benchmark on the reference convex sample: stress\n"
         "                           solves, mesh motion, remeshing\n"
         "  bench evolution [--state FILE] [--scale F] [--sample convex|plain] [--depth D]\n"
         "                  [--holder frame|none]\n"
         "                  [--mesh-size H] [--evolutions explicit-only,implicit,...]\n"
         "                  [--grid-spacing G] [--target-edge E1,E2,...] [--flat-edge F1,...]\n"
         "                  [--step-depth D1,D2,...] [--output DIR]\n"
         "                           one stage of wear by each surface evolution on the same\n"
         "                           sample (a worn stage file, or the unworn sample): time,\n"
         "                           remeshes, volume error, unworn faces' offset, quality,\n"
         "                           the elements' volume left\n"
         "  --print-parameters       list every case-file parameter with default and meaning\n"
         "  --version                the engine version (git describe at build time)\n\n"
         "under mpirun -np N: 'run', 'scene-run', 'dem' and 'bench dem' decompose the bed over\n"
         "the N ranks (a tester case in angular slabs of its sector, a scene as Scene/Rank slabs\n"
         "along says; DEM/Threads or --threads per rank); rank 0 writes and prints\n"
         "  --help                   this text\n";
}

} // namespace

int main(int argc, char** argv) {
  using namespace wear::coupling;
  // MPI for deal.II's Trilinos solvers and, under mpirun, for the DEM over ranks.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
  if (argc < 2) {
    usage(std::cerr);
    return 2;
  }
  const std::string cmd = argv[1];
  int rank = 0, n_ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &n_ranks);
  try {
    if (n_ranks > 1 && (cmd == "scene-run" || cmd == "run" || cmd == "dem")) {
      // A scene's slabs are a ring along a period or an angle (the tester's sector), a line
      // otherwise.
      const std::vector<std::string> args(argv + 2, argv + argc);
      RunOptions options;
      std::ostream unheard(nullptr); // the command reads the case again and warns then
      const CaseParameters c = read_case(parse_run_arguments(args, cmd, options), unheard);
      const CaseParameters p = cmd == "dem" ? dem_case_of(c) : run_case_of(c);
      wear::dem::MpiRankLink ranks(MPI_COMM_WORLD, wear::dem::rank_ring(p.scene));
      if (cmd == "dem")
        return run_dem_command(args, std::cout, &ranks);
      return cmd == "run" ? run_run_command(args, std::cout, &ranks)
                          : run_scene_run_command(args, std::cout, &ranks);
    }
    if (n_ranks > 1) {
      // The benchmark's tester, sectors and annulus are rings of angular slabs.
      wear::dem::MpiRankLink ranks(MPI_COMM_WORLD, true);
      if (cmd == "bench" && argc >= 3 && std::string(argv[2]) == "dem")
        return run_bench_command({argv + 2, argv + argc}, std::cout, &ranks);
      throw std::invalid_argument(
          "under mpirun (" + std::to_string(n_ranks) +
          " ranks) wearsim decomposes 'run <case.prm>', 'scene-run <case.prm>', 'dem <case.prm>' "
          "and 'bench dem'; run "
          "the other commands as one process");
    }
    if (cmd == "--help" || cmd == "-h") {
      usage(std::cout);
      return 0;
    }
    if (cmd == "--version") {
      std::cout << "wearsim " << engine_version() << "\n";
      return 0;
    }
    if (cmd == "--print-parameters") {
      print_parameters(std::cout);
      return 0;
    }
    if (cmd == "mesh") {
      if (argc != 3) {
        std::cerr << "wearsim mesh: expected one case file\n";
        return 2;
      }
      const CaseParameters p = read_case(argv[2]);
      require_no_scene(p, "mesh");
      run_mesh_command(p, std::cout);
      return 0;
    }
    if (cmd == "scene") {
      if (argc != 3) {
        std::cerr << "wearsim scene: expected one case file\n";
        return 2;
      }
      run_scene_command(read_case(argv[2]), std::cout);
      return 0;
    }
    if (cmd == "tester-scene") {
      if (argc != 3) {
        std::cerr << "wearsim tester-scene: expected one case file (the scene goes to stdout)\n";
        return 2;
      }
      CaseParameters s = tester_scene_case(read_case(argv[2]));
      s.output.directory += "-scene"; // beside the tester case's own run
      std::cout << tester_scene_text(s, argv[2]);
      return 0;
    }
    if (cmd == "scene-run")
      return run_scene_run_command({argv + 2, argv + argc}, std::cout);
    if (cmd == "run")
      return run_run_command({argv + 2, argv + argc}, std::cout);
    if (cmd == "dem")
      return run_dem_command({argv + 2, argv + argc}, std::cout);
    if (cmd == "compare")
      return run_compare_command({argv + 2, argv + argc}, std::cout);
    if (cmd == "calibrate")
      return run_calibrate_command({argv + 2, argv + argc}, std::cout);
    if (cmd == "life")
      return run_life_command({argv + 2, argv + argc}, std::cout);
    if (cmd == "bench")
      return run_bench_command({argv + 2, argv + argc}, std::cout);
    std::cerr << "wearsim: unknown command '" << cmd << "'\n";
    usage(std::cerr);
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "wearsim " << cmd << ": error"
              << (n_ranks > 1 ? " on rank " + std::to_string(rank) : std::string()) << ": "
              << e.what() << "\n";
    // The other ranks may wait in a message of the step loop: stop them all.
    if (n_ranks > 1)
      MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
}
