# Unity builds: CMake compiles each target's sources (the libraries, the Python module, the
# programs and the test executables) in batches of sixteen per translation unit, so the headers
# they share (Eigen, fmt, Boost.Math, CLI11, nlohmann-json, pybind11, GoogleTest and the
# project's own) are parsed, and their templates instantiated, once per batch rather than once
# per file; the tests' objects were most of the build's time. The files of a batch share one
# anonymous namespace: a test file whose file-scope helpers or constants have the name of
# another test file's in the same executable keeps them in a namespace named after the file
# (namespace verity::sampler_uniformity_test { namespace { ... } }), whichever batches the two
# files fall in, since adding a file moves the others between batches. A batch can hide a
# missing include (an earlier file of the batch included it): VERITY_UNITY_BUILD=OFF, with
# VERITY_PRECOMPILED_HEADERS=OFF, compiles every file on its own and shows it, and suits
# editing one file (only that file recompiles). Sixteen rather than CMake's eight, and the cost
# with and without batches: reports/build-times.md.
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
    if(type MATCHES "^(STATIC_LIBRARY|MODULE_LIBRARY|EXECUTABLE)$")
      set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 16)
    endif()
  endforeach()
endfunction()
