// Catch2 main of the DEM-over-ranks tests: MPI around the session. Every rank runs every test
// in the same order (the engine's messages are collective); a test's checks compare values
// reduced over the ranks, so all ranks pass or fail together and none waits for another.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <mpi.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const int result = Catch::Session().run(argc, argv);
  int worst = result;
  MPI_Allreduce(&result, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return worst;
}
