# Precompiled headers. Most translation units include Eigen and fmt, and every test includes
# GoogleTest: parsing them again in each file was most of the build's time. They are compiled
# once per build instead, into two headers:
#   - the library header, made by verity_renderer and reused by every target that links it;
#   - the test header (the library header's contents, nlohmann-json and GoogleTest), made by
#     the object library verity_test_precompiled and reused by every test that links
#     verity_renderer.
# nlohmann-json is left out of the library header: loading it costs each file about a second
# (GCC 12), a third of parsing it, and two thirds of the library's files do not use it; most
# tests do. CLI11 stays out of both: its header defines objects in every file that includes it.
# Reuse needs the same compiler flags, so the position-independent installed libraries
# (verity_chi2, verity_stats) and the targets that do not link verity_renderer compile
# without them. A header is included before each file's own includes, which is harmless here
# (no file defines a macro before its includes). VERITY_PRECOMPILED_HEADERS=OFF compiles every
# file on its own, which shows a missing include. ccache reuses its results for these files
# only with CCACHE_SLOPPINESS=pch_defines,time_macros; without it, it compiles them.
include(VerityTargets)

option(VERITY_PRECOMPILED_HEADERS "Precompile the third-party headers most files include" ON)

set(VERITY_PRECOMPILED_LIBRARY_HEADERS
    <Eigen/Core> <Eigen/Geometry> <fmt/format.h> <algorithm> <array>
    <cmath> <cstdint> <filesystem> <fstream> <functional> <limits> <map> <memory> <optional>
    <stdexcept> <string> <vector>)

# verity_precompile_headers(): called once every target is defined. verity_renderer makes the
# library header; each other library, program and test that links it, directly or through
# another Verity library, reuses the library or the test header. Targets with their own
# compile options (beyond the project's) or position-independent code would need a header of
# their own and compile without one.
function(verity_precompile_headers)
  if(NOT VERITY_PRECOMPILED_HEADERS OR NOT TARGET verity_renderer)
    return()
  endif()
  target_precompile_headers(verity_renderer PRIVATE ${VERITY_PRECOMPILED_LIBRARY_HEADERS})
  # The test header's host: one empty source with the tests' usage requirements.
  set(source ${PROJECT_BINARY_DIR}/verity_test_precompiled.cpp)
  if(NOT EXISTS ${source})
    file(WRITE ${source} "// Makes the precompiled test header; compiles to nothing.\n")
  endif()
  add_library(verity_test_precompiled OBJECT ${source})
  target_link_libraries(verity_test_precompiled PRIVATE verity_renderer GTest::gtest)
  target_precompile_headers(verity_test_precompiled PRIVATE
                            ${VERITY_PRECOMPILED_LIBRARY_HEADERS} <nlohmann/json.hpp>
                            <gtest/gtest.h>)

  verity_targets_below(${PROJECT_SOURCE_DIR} targets)
  # The targets that link verity_renderer, directly or through a library that does.
  set(linking verity_renderer)
  set(changed TRUE)
  while(changed)
    set(changed FALSE)
    foreach(target ${targets})
      get_target_property(links ${target} LINK_LIBRARIES)
      if(NOT target IN_LIST linking AND links)
        foreach(library ${linking})
          if(library IN_LIST links)
            list(APPEND linking ${target})
            set(changed TRUE)
            break()
          endif()
        endforeach()
      endif()
    endforeach()
  endwhile()
  list(REMOVE_ITEM linking verity_renderer verity_test_precompiled)
  get_target_property(renderer_options verity_renderer COMPILE_OPTIONS)

  foreach(target ${linking})
    get_target_property(type ${target} TYPE)
    get_target_property(options ${target} COMPILE_OPTIONS)
    get_target_property(pic ${target} POSITION_INDEPENDENT_CODE)
    get_target_property(links ${target} LINK_LIBRARIES)
    if(NOT type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|OBJECT_LIBRARY)$"
       OR NOT "${options}" STREQUAL "${renderer_options}" OR pic)
      continue()
    endif()
    if("GTest::gtest_main" IN_LIST links OR "GTest::gtest" IN_LIST links)
      target_precompile_headers(${target} REUSE_FROM verity_test_precompiled)
    else()
      target_precompile_headers(${target} REUSE_FROM verity_renderer)
    endif()
  endforeach()
endfunction()
