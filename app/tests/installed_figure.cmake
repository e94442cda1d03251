# An installed `verity` draws a chi-square figure with the script it installed, found beside
# it at run time: installs the build to a fresh prefix, moves the prefix elsewhere (so no
# path compiled into the program can be what finds the script), runs `verity chi2 -o` there,
# and expects the PNG, or, where no Python it tries has matplotlib (python3 on PATH, then
# /usr/bin/python3), an error that names it. With VERITY_PYTHON naming a program that is not
# there, the error must name VERITY_PYTHON and not fall back to another Python.
# Arguments: BUILD_DIR, WORK_DIR.
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/first"
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status})")
endif()
file(RENAME "${WORK_DIR}/first" "${WORK_DIR}/moved")
set(verity "${WORK_DIR}/moved/bin/verity")
if(NOT EXISTS "${verity}" OR NOT EXISTS "${WORK_DIR}/moved/share/verity/plot_chi2.py")
  message(FATAL_ERROR "the install has no bin/verity or share/verity/plot_chi2.py")
endif()
set(material [[{"type":"lambertian","albedo":0.5}]])
execute_process(COMMAND "${verity}" chi2 --material "${material}" --samples 20000
                        -o "${WORK_DIR}/figures/lambertian"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(has_matplotlib FALSE)
foreach(python python3 /usr/bin/python3)
  execute_process(COMMAND ${python} -c "import matplotlib" RESULT_VARIABLE no_matplotlib
                  OUTPUT_QUIET ERROR_QUIET)
  if(no_matplotlib EQUAL 0)
    set(has_matplotlib TRUE)
  endif()
endforeach()
if(has_matplotlib)
  if(NOT status EQUAL 0 OR NOT EXISTS "${WORK_DIR}/figures/lambertian.png")
    message(FATAL_ERROR "no figure from the installed program (status ${status}):\n${out}${err}")
  endif()
elseif(status EQUAL 0 OR NOT err MATCHES "matplotlib")
  message(FATAL_ERROR "without matplotlib the error must name it (status ${status}):\n${err}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E env VERITY_PYTHON=${WORK_DIR}/no-such-python
                        "${verity}" chi2 --material "${material}" --samples 20000
                        -o "${WORK_DIR}/figures/nopython"
                RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
if(status EQUAL 0 OR NOT err MATCHES "VERITY_PYTHON" OR NOT err MATCHES "no-such-python"
   OR EXISTS "${WORK_DIR}/figures/nopython.png")
  message(FATAL_ERROR "with VERITY_PYTHON missing the error must name it (status ${status}):\n${err}")
endif()
message(STATUS "the installed verity drew ${WORK_DIR}/figures/lambertian.png")
