# Unity builds: CMake compiles each library's, the Python module's and the program's sources
# in batches of sixteen per translation unit, so the headers they share (Eigen, fmt,
# Boost.Math, CLI11, nlohmann-json, pybind11 and the project's own) are parsed, and their
# templates instantiated, once per batch rather than once per file. Test executables compile file by file: each test file keeps
# its helpers in its own anonymous namespace without knowing which other files a batch would
# put beside it. A batch can hide a missing include (an earlier file of the batch included it):
# VERITY_UNITY_BUILD=OFF, with VERITY_PRECOMPILED_HEADERS=OFF, compiles every file on its own
# and shows it, and suits editing one file (only that file recompiles). Sixteen rather than
# CMake's eight, and the cost with and without batches: reports/build-times.md.
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
    if(type MATCHES "^(STATIC_LIBRARY|MODULE_LIBRARY|EXECUTABLE)$" AND NOT "GTest::gtest_main" IN_LIST links)
      set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 16)
    endif()
  endforeach()
endfunction()
