# Unity builds: CMake compiles each library's, program's and test executable's sources in
# batches of sixteen per translation unit, so the headers they share (Eigen, fmt, Boost.Math,
# CLI11, nlohmann-json, GoogleTest and the project's own) are parsed, and their templates
# instantiated, once per batch rather than once per file. Measured in README.md ("What the two
# commands cost"). File-local names of a batch's files share one translation unit: a test file
# whose constants or helpers repeat another's (kSpp, kTileSize, renderTiles) keeps them in a
# namespace named after the file, since an anonymous namespace is one per translation unit. A
# batch can also hide a missing include (an earlier file of the batch included it):
# VERITY_UNITY_BUILD=OFF, with VERITY_PRECOMPILED_HEADERS=OFF, compiles every file on its own
# and shows it, and suits editing one file (only that file recompiles).
# Sixteen rather than CMake's eight: a clean Release build on 2 cores took 346 s (663 CPU-s)
# against 396 s (759 CPU-s), measured one after the other; 32 was no faster (343 s) and puts
# more files' local names in one translation unit.
include(VerityTargets)

option(VERITY_UNITY_BUILD "Compile each target's sources in batches (a unity build)" ON)

# verity_unity_build(): called once every target is defined.
function(verity_unity_build)
  if(NOT VERITY_UNITY_BUILD)
    return()
  endif()
  verity_targets_below(${PROJECT_SOURCE_DIR} targets)
  foreach(target ${targets})
    get_target_property(type ${target} TYPE)
    get_target_property(links ${target} LINK_LIBRARIES)
    if(type MATCHES "^(STATIC_LIBRARY|EXECUTABLE)$" AND NOT "GTest::gtest_main" IN_LIST links)
      set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 16)
    endif()
  endforeach()
endfunction()
