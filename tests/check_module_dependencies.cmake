# Fails when a module includes what it must not: dem/ and meshes/ never include deal.II or
# fem/; fem/ never includes dem/; meshes/ never includes dem/ either (links go one way).
set(rules
  "meshes|deal\\.II/|fem/|dem/|coupling/"
  "dem|deal\\.II/|fem/|coupling/"
  "fem|dem/|coupling/")
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
  message(FATAL_ERROR "module rule broken (dem/meshes without deal.II or fem; fem without dem):${violations}")
endif()
message(STATUS "module dependencies respected")
