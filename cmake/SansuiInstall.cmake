# `cmake --install BUILD [--prefix DIR]`: the programs, the libraries (static) with their headers
# under include/sansui/ (as `#include "terrain/midpoint.hpp"`), a CMake package
# (`find_package(Sansui)`, target Sansui::sansui) and a pkg-config file (sansui.pc), the manual
# page and bash completion made by the built program, and the data tables and example scenes for
# reference (the program reads no data file at run time: data/*.toml are compiled in).
include(CMakePackageConfigHelpers)

set(SANSUI_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Sansui)
set(sansui_libraries sansui_core sansui_terrain sansui_water sansui_solid sansui_mesh sansui_vegetation sansui_contour sansui_io
    sansui_look sansui_render sansui_scene)

install(TARGETS sansui_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS sansui_viewer RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} OPTIONAL)
install(TARGETS ${sansui_libraries} sansui sansui_options sansui_geotiff sansui_mesh_cgal
  EXPORT SansuiTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  OBJECTS DESTINATION ${CMAKE_INSTALL_LIBDIR}/sansui/objects)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sansui FILES_MATCHING PATTERN "*.hpp")
install(EXPORT SansuiTargets NAMESPACE Sansui:: DESTINATION ${SANSUI_CMAKE_DIR})
configure_package_config_file(cmake/SansuiConfig.cmake.in ${PROJECT_BINARY_DIR}/SansuiConfig.cmake INSTALL_DESTINATION ${SANSUI_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/SansuiConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/SansuiConfig.cmake ${PROJECT_BINARY_DIR}/SansuiConfigVersion.cmake DESTINATION ${SANSUI_CMAKE_DIR})

# sansui.pc: prefix relative to the file itself, so a tree installed with --prefix anywhere works.
file(RELATIVE_PATH SANSUI_PC_PREFIX /root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /root)
set(SANSUI_PC_LIBS "")
foreach(library IN ITEMS sansui_scene sansui_render sansui_look sansui_io sansui_contour sansui_terrain sansui_mesh sansui_solid sansui_vegetation
                         sansui_water sansui_core)
  string(APPEND SANSUI_PC_LIBS " -l${library}")
endforeach()
set(SANSUI_PC_SANITIZE "")
if(SANSUI_SANITIZE)
  set(SANSUI_PC_SANITIZE " -fsanitize=address,undefined")
endif()
configure_file(cmake/sansui.pc.in ${PROJECT_BINARY_DIR}/sansui.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/sansui.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

install(FILES ${PROJECT_BINARY_DIR}/sansui.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${PROJECT_BINARY_DIR}/sansui.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME sansui)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION ${CMAKE_INSTALL_DATADIR}/sansui/data)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/sansui/examples/scenes)

# `cpack -G DEB` in the build directory: a Debian package of the installed tree (programs,
# static libraries and headers, manual page, completion, data) under /usr, its dependencies
# found by dpkg-shlibdeps from the programs' shared libraries. gzip: xz takes minutes on the
# libraries. Tested by installing it into an empty root (tests/install/deb_test.sh).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME sansui)
set(CPACK_PACKAGE_VENDOR Sansui)
set(CPACK_PACKAGE_CONTACT "Sansui developers <sansui@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# GDAL is opened with dlopen when a DEM is first read through it (io/gdal_api.hpp), so
# dpkg-shlibdeps does not see it: named here, by the package of the soname the build compiled in.
string(REGEX REPLACE "^libgdal\\.so\\.([0-9]+)$" "libgdal\\1" sansui_gdal_package "${sansui_gdal_soname}")
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${sansui_gdal_package}")
# The Python module (lib/python3/dist-packages/sansui) imports numpy; the programs need neither.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3 (>= 3.11), python3-numpy")
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)
include(CPack)
