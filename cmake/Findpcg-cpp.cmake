# pcg-cpp is header-only (Debian: libpcg-cpp-dev).
find_path(pcg-cpp_INCLUDE_DIR pcg_random.hpp)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(pcg-cpp REQUIRED_VARS pcg-cpp_INCLUDE_DIR)
if(pcg-cpp_FOUND AND NOT TARGET pcg-cpp::pcg-cpp)
  add_library(pcg-cpp::pcg-cpp INTERFACE IMPORTED)
  set_target_properties(pcg-cpp::pcg-cpp PROPERTIES INTERFACE_INCLUDE_DIRECTORIES
                        "${pcg-cpp_INCLUDE_DIR}")
endif()
