# Fails when a module includes what it must not (links go one way):
#   meshes/ includes no other module and no deal.II;
#   dem/ never includes deal.II, fem/ or coupling/; its engine never includes what runs on
#   it (dem/wear/, dem/scene/, dem/tester/) nor the ranks' MPI layer (dem/parallel/); the
#   wall loads and wear laws (dem/wear/) and the evaluations (dem/evaluation/) include
#   neither the scenes nor the tester, and the scenes never include the tester; only
#   dem/parallel includes mpi.h;
#   fem/ never includes dem/ or coupling/;
#   inside coupling/, only the command line (app/) sees everything: the loop and the run
#   output never include app/, the parameters include neither the loop, the output nor
#   the command line, and the statistics (analysis/) include no other part and no deal.II.
set(rules
  "meshes|deal\\.II/|fem/|dem/|coupling/"
  "dem|deal\\.II/|fem/|coupling/"
  "dem/engine|dem/tester/|dem/scene/|dem/wear/|dem/evaluation/|dem/parallel/|mpi\\.h"
  "dem/wear|dem/tester/|dem/scene/|mpi\\.h"
  "dem/evaluation|dem/tester/|dem/scene/|mpi\\.h"
  "dem/scene|dem/tester/|mpi\\.h"
  "dem/tester|mpi\\.h"
  "dem/validation|mpi\\.h"
  "fem|dem/|coupling/"
  "coupling/loop|coupling/app/"
  "coupling/output|coupling/app/"
  "coupling/parameters|coupling/app/|coupling/loop/|coupling/output/"
  "coupling/analysis|coupling/app/|coupling/loop/|coupling/output/|coupling/parameters/|deal\\.II/|dem/|fem/|meshes/")
set(violations "")
foreach(rule IN LISTS rules)
  string(REPLACE "|" ";" parts "${rule}")
  list(POP_FRONT parts module)
  file(GLOB_RECURSE files "${ROOT}/${module}/*.h" "${ROOT}/${module}/*.cc")
  foreach(f IN LISTS files)
    file(STRINGS "${f}" includes REGEX "^[ \t]*#[ \t]*include")
    foreach(inc IN LISTS includes)
      foreach(forbidden IN LISTS parts)
        if(inc MATCHES "[<\"]${forbidden}")
          string(APPEND violations "\n  ${f}: ${inc}")
        endif()
      endforeach()
    endforeach()
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "module rule broken (see the rules at the top of tests/check_module_dependencies.cmake):${violations}")
endif()
message(STATUS "module dependencies respected")
