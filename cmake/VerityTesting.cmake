# verity_discover_tests(TARGET [NAME name] [PREFIX prefix] [FILTER gtest-filter]
#                       [RESOURCE_LOCK lock] [COST seconds] [THREADS n]
#                       [WHOLE_SUITES suite...] LABELS label...):
# registers a GoogleTest executable's tests (those FILTER selects) with CTest and gives every
# discovered test all the labels. NAME tells apart several registrations of one target.
# Labels are set after discovery because CMake 3.25's gtest discovery flattens list values
# passed through PROPERTIES (`LABELS "quick;renderer"` would keep only "quick"). A target with
# label quick joins the `quick_tests` target (see verity_add_quick_tests_target).
# Each of WHOLE_SUITES is left out of the discovery and registered as one CTest test named
# after it, which runs the suite whole: for a suite whose tests share renders that its
# SetUpTestSuite makes once per process (registered test by test, each test's process made them
# again). A failure names the test; a suite that selects no test (renamed, say) fails rather
# than passing with nothing run. RESOURCE_LOCK keeps the tests from running at the same time
# as any other test holding the same lock. COST is each test's time in seconds, about: CTest
# starts the costliest tests first (a clean build has no record of past times), so that a
# test of minutes does not start last, beside an idle core. THREADS sets VERITY_TEST_THREADS
# in each test's environment, which an executable that reads it (chi2/suite/tests/
# test_threads.cpp) takes as its cap on oneTBB's threads: for many short tests that `ctest -j`
# already runs side by side on every core, where more threads per test only contend.
function(verity_discover_tests target)
  cmake_parse_arguments(ARG "" "NAME;PREFIX;FILTER;RESOURCE_LOCK;COST;THREADS" "WHOLE_SUITES;LABELS"
                        ${ARGN})
  if(NOT ARG_NAME)
    set(ARG_NAME ${target})
  endif()
  foreach(suite ${ARG_WHOLE_SUITES})
    # gtest filters read POSITIVE-NEGATIVE, the negative patterns joined by ':'.
    if(ARG_FILTER MATCHES "-")
      string(APPEND ARG_FILTER ":${suite}.*")
    else()
      string(APPEND ARG_FILTER "-${suite}.*")
    endif()
    add_test(NAME ${suite} COMMAND ${target} --gtest_filter=${suite}.*)
    set_tests_properties(${suite} PROPERTIES LABELS "${ARG_LABELS}"
                                             FAIL_REGULAR_EXPRESSION "Running 0 tests from")
  endforeach()
  set(options)
  if(ARG_PREFIX)
    list(APPEND options TEST_PREFIX ${ARG_PREFIX})
  endif()
  if(ARG_FILTER)
    list(APPEND options TEST_FILTER ${ARG_FILTER})
  endif()
  gtest_discover_tests(${target} ${options} DISCOVERY_TIMEOUT 120 TEST_LIST ${ARG_NAME}_TESTS)
  list(JOIN ARG_LABELS ";" labels)
  set(file ${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}_labels.cmake)
  # A target left unbuilt (a build of quick_tests alone) has no test list.
  set(lock "")
  if(ARG_RESOURCE_LOCK)
    set(lock " RESOURCE_LOCK ${ARG_RESOURCE_LOCK}")
  endif()
  if(ARG_COST)
    string(APPEND lock " COST ${ARG_COST}")
  endif()
  if(ARG_THREADS)
    string(APPEND lock " ENVIRONMENT VERITY_TEST_THREADS=${ARG_THREADS}")
  endif()
  file(WRITE ${file} "if(${ARG_NAME}_TESTS)\n"
                     "  set_tests_properties(\${${ARG_NAME}_TESTS} PROPERTIES LABELS \"${labels}\"${lock})\n"
                     "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${file})
  if("quick" IN_LIST ARG_LABELS)
    set_property(GLOBAL APPEND PROPERTY VERITY_QUICK_TEST_TARGETS ${target})
  endif()
endfunction()

# verity_test_runs_program(TARGET): TARGET's tests run the `verity` program as a child process,
# named to them by VERITY_BINARY. TARGET is linked after the program, so that a test executable
# always runs a program built from the same sources; its files compile without waiting for it.
# (add_dependencies would hold back their compilation until the program is linked: at the end
# of a clean build on two cores, one core idled while app_tests compiled.)
function(verity_test_runs_program target)
  target_compile_definitions(${target} PRIVATE VERITY_BINARY="$<TARGET_FILE:verity>")
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS $<TARGET_FILE:verity>)
endfunction()

# verity_add_quick_tests_target(TARGET...): `quick_tests` builds what `ctest -L quick` runs:
# the executables registered with label quick, and the TARGETs the other quick tests need
# (the package tests install the program and the packaged libraries). The sanitizer job
# builds it alone.
function(verity_add_quick_tests_target)
  get_property(targets GLOBAL PROPERTY VERITY_QUICK_TEST_TARGETS)
  list(REMOVE_DUPLICATES targets)
  add_custom_target(quick_tests)
  add_dependencies(quick_tests ${targets} ${ARGN})
endfunction()
