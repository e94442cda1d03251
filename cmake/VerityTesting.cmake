# verity_discover_tests(TARGET LABELS label...): registers a GoogleTest executable's tests
# with CTest and gives every discovered test all the labels. Labels are set after discovery
# because CMake 3.25's gtest discovery flattens list values passed through PROPERTIES
# (`LABELS "quick;renderer"` would keep only "quick").
function(verity_discover_tests target)
  cmake_parse_arguments(ARG "" "" "LABELS" ${ARGN})
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 120 TEST_LIST ${target}_TESTS)
  list(JOIN ARG_LABELS ";" labels)
  set(file ${CMAKE_CURRENT_BINARY_DIR}/${target}_labels.cmake)
  file(WRITE ${file} "set_tests_properties(\${${target}_TESTS} PROPERTIES LABELS \"${labels}\")\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${file})
endfunction()
