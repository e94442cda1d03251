# Installs the Python module alone (the `python` component) from a build tree to a fresh
# prefix, then runs pytest on TESTS with that prefix's module directory first on the path,
# so that a module left out of the install, or installed where python3 does not look, fails.
# The tests check that `verity` was imported from the prefix. A TESTS that names a .py file
# is run as a program instead (an example). Run by CTest as
#   cmake -DBUILD_DIR=<build> -DWORK_DIR=<scratch> -DPYTHON=<python3> -DINSTALL_DIR=<relative>
#         -DTESTS=<folder or script.py> -P TestInstalledPython.cmake
foreach(var BUILD_DIR WORK_DIR PYTHON INSTALL_DIR TESTS)
  if(NOT ${var})
    message(FATAL_ERROR "TestInstalledPython: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix}
                        --component python RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "TestInstalledPython: installing the python component failed (${rc})")
endif()
# No bytecode or pytest cache in the source tree; the scratch folder goes afterwards.
set(ENV{PYTHONPATH} ${prefix}/${INSTALL_DIR})
set(ENV{PYTHONDONTWRITEBYTECODE} 1)
set(ENV{VERITY_EXPECTED_PREFIX} ${prefix})
# The command, for the tests that check the module against it (test_compare.py).
if(VERITY_EXECUTABLE)
  set(ENV{VERITY_EXECUTABLE} ${VERITY_EXECUTABLE})
endif()
# Run from the scratch folder: `python3 -m` puts the working directory first on the path,
# and CTest's (the build's python/) holds the module as built.
if(TESTS MATCHES "\\.py$")
  execute_process(COMMAND ${PYTHON} ${TESTS} WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc)
else()
  execute_process(COMMAND ${PYTHON} -m pytest -q -p no:cacheprovider ${TESTS}
                  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc)
endif()
file(REMOVE_RECURSE ${WORK_DIR})
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "TestInstalledPython: ${TESTS} failed (${rc})")
endif()
