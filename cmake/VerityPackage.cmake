# The installable part of Verity: libraries that other renderers link to test their own
# code (find_package(Verity CONFIG) gives Verity::chi2 and Verity::stats). Each packaged
# library keeps its headers in include/verity/<name>/ beside its src/ and tests/, includes
# nothing outside it but system and third-party headers, and is read as
# <verity/<name>/header.h> in the tree as once installed.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(VERITY_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Verity)

# verity_package_library(TARGET target EXPORT_NAME name): installs the target's archive and
# the headers of the calling folder's include/verity/<name>/, and exports it as Verity::<name>.
function(verity_package_library)
  cmake_parse_arguments(ARG "" "TARGET;EXPORT_NAME" "" ${ARGN})
  set_target_properties(${ARG_TARGET} PROPERTIES EXPORT_NAME ${ARG_EXPORT_NAME})
  target_include_directories(${ARG_TARGET} INTERFACE
                             $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  add_library(Verity::${ARG_EXPORT_NAME} ALIAS ${ARG_TARGET})
  install(TARGETS ${ARG_TARGET} EXPORT VerityTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  file(GLOB headers CONFIGURE_DEPENDS
       ${CMAKE_CURRENT_SOURCE_DIR}/include/verity/${ARG_EXPORT_NAME}/*.h)
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/verity/${ARG_EXPORT_NAME})
endfunction()

# The export set, its config file and version; called once, after every packaged library.
function(verity_install_package)
  install(EXPORT VerityTargets NAMESPACE Verity:: DESTINATION ${VERITY_PACKAGE_DIR}
          FILE VerityTargets.cmake)
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/VerityConfig.cmake.in
                                ${PROJECT_BINARY_DIR}/VerityConfig.cmake
                                INSTALL_DESTINATION ${VERITY_PACKAGE_DIR})
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/VerityConfigVersion.cmake
                                   COMPATIBILITY SameMinorVersion)
  # pcg-cpp ships no CMake package; the config finds it with the module the build uses.
  install(FILES ${PROJECT_BINARY_DIR}/VerityConfig.cmake
                ${PROJECT_BINARY_DIR}/VerityConfigVersion.cmake
                ${PROJECT_SOURCE_DIR}/cmake/Findpcg-cpp.cmake
          DESTINATION ${VERITY_PACKAGE_DIR})
endfunction()
