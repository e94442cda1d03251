# Unity builds of the libraries: CMake compiles each static library's sources in batches of
# eight per translation unit, so the headers they share (Eigen, fmt, Boost.Math, CLI11,
# nlohmann-json and the project's own) are parsed, and their templates instantiated, once per
# batch rather than once per file. Measured in README.md ("What the two commands cost").
# Test executables keep one file per translation unit: test files define file-local names
# that repeat between files (kSpp, kTileSize in anonymous namespaces), which a batch would
# put side by side. A batch can also hide a missing include (an earlier file of the batch
# included it): VERITY_UNITY_BUILD=OFF, with VERITY_PRECOMPILED_HEADERS=OFF, compiles every
# file on its own and shows it, and suits editing one file (only that file recompiles).
option(VERITY_UNITY_BUILD "Compile each library's sources in batches (a unity build)" ON)

# verity_unity_build(): called once every target is defined.
function(verity_unity_build)
  if(NOT VERITY_UNITY_BUILD)
    return()
  endif()
  verity_targets_below(${PROJECT_SOURCE_DIR} targets)
  foreach(target ${targets})
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "STATIC_LIBRARY")
      set_target_properties(${target} PROPERTIES UNITY_BUILD ON)
    endif()
  endforeach()
endfunction()
