// Catch2 main for test programs that use deal.II's Trilinos wrappers, which need MPI.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <deal.II/base/mpi.h>

int main(int argc, char** argv) {
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return Catch::Session().run(argc, argv);
}
