# Installs Verity from a build tree to a fresh prefix, then configures, builds and tests
# examples/external-bsdf against that prefix alone, so that a broken install rule (a header
# or library left out, a wrong include path, a dependency the package config does not find)
# fails the suite. Run by CTest as
#   cmake -DBUILD_DIR=<build> -DSOURCE_DIR=<source> -DWORK_DIR=<scratch> [-DGENERATOR=...]
#         [-DCXX_COMPILER=...] [-DCXX_COMPILER_LAUNCHER=...] [-DCXX_FLAGS=...]
#         [-DEXE_LINKER_FLAGS=...] -P TestInstalledPackage.cmake
#
# With -DCHECKS_ONLY=ON, BUILD_DIR is not needed: the package is first configured and built
# here from SOURCE_DIR with VERITY_CHECKS_ONLY (no renderer, Embree, OpenEXR or MPI), so that
# the installed libraries are shown to build without the renderer. With -DPYTHON=<python3>
# -DPYTHON_INSTALL_DIR=<relative> as well, its Python module is built for that python3 and
# run from a fresh install (TestInstalledPython.cmake, python/tests/checks_only.py).
set(required SOURCE_DIR WORK_DIR)
if(NOT CHECKS_ONLY)
  list(APPEND required BUILD_DIR)
endif()
foreach(var ${required})
  if(NOT ${var})
    message(FATAL_ERROR "TestInstalledPackage: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
set(example_build ${WORK_DIR}/external-bsdf)

function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "TestInstalledPackage: ${step} failed (${rc}): ${ARGN}")
  endif()
endfunction()

# The settings of the build under test, for every project configured here.
set(settings -DCMAKE_BUILD_TYPE=Release)
if(GENERATOR)
  list(APPEND settings -G ${GENERATOR})
endif()
if(CXX_COMPILER)
  list(APPEND settings -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()
if(CXX_COMPILER_LAUNCHER)
  list(APPEND settings -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_COMPILER_LAUNCHER})
endif()
# The build's own flags (a sanitizer build's library needs its runtime in the example too).
if(CXX_FLAGS)
  list(APPEND settings "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}")
endif()
if(EXE_LINKER_FLAGS)
  list(APPEND settings "-DCMAKE_EXE_LINKER_FLAGS=${EXE_LINKER_FLAGS}")
endif()

if(CHECKS_ONLY)
  set(BUILD_DIR ${WORK_DIR}/verity-checks-only)
  set(python_settings)
  if(PYTHON)
    set(python_settings -DPython3_EXECUTABLE=${PYTHON}
                        -DVERITY_PYTHON_INSTALL_DIR=${PYTHON_INSTALL_DIR})
  endif()
  run(configure-checks-only ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BUILD_DIR}
      -DVERITY_CHECKS_ONLY=ON ${settings} ${python_settings})
  run(build-checks-only ${CMAKE_COMMAND} --build ${BUILD_DIR})
endif()
run(install ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
run(configure ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/external-bsdf -B ${example_build}
    -DCMAKE_PREFIX_PATH=${prefix} ${settings})
run(build ${CMAKE_COMMAND} --build ${example_build})
run(test ${CMAKE_CTEST_COMMAND} --test-dir ${example_build} --output-on-failure)
message(STATUS "TestInstalledPackage: examples/external-bsdf built and passed against ${prefix}")
if(CHECKS_ONLY AND PYTHON)
  run(python ${CMAKE_COMMAND} -DBUILD_DIR=${BUILD_DIR} -DWORK_DIR=${WORK_DIR}/python
      -DPYTHON=${PYTHON} -DINSTALL_DIR=${PYTHON_INSTALL_DIR}
      -DTESTS=${SOURCE_DIR}/python/tests/checks_only.py
      -P ${CMAKE_CURRENT_LIST_DIR}/TestInstalledPython.cmake)
elseif(CHECKS_ONLY)
  message(STATUS "TestInstalledPackage: the Python module was built but not imported "
                 "(no -DPYTHON: this build has no module, as a sanitizer build)")
endif()
