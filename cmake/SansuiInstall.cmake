# `cmake --install BUILD [--prefix DIR]`: the programs, the libraries (static) with their headers
# under include/sansui/ (as `#include "terrain/midpoint.hpp"`), a CMake package
# (`find_package(Sansui)`, target Sansui::sansui) and a pkg-config file (sansui.pc), the manual
# pages and bash completion made by the built programs, the Python module and the Blender add-on,
# the documentation, and the data tables and example scenes for reference (the program reads no
# data file at run time: data/*.toml are compiled in). Each file belongs to one component, which
# is one Debian package (below): cli, viewer, mpi, dev, python (python/CMakeLists.txt), blender,
# doc. Libraries go to lib/<multiarch> (CMakeLists.txt).
include(CMakePackageConfigHelpers)

set(SANSUI_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Sansui)
set(sansui_libraries sansui_core sansui_terrain sansui_water sansui_solid sansui_mesh sansui_vegetation sansui_contour sansui_io
    sansui_look sansui_render sansui_scene)

# The programs. The viewer is OPTIONAL: `scripts/build sansui_cli` leaves it unbuilt.
install(TARGETS sansui_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cli)
install(TARGETS sansui_viewer RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT viewer OPTIONAL)
install(FILES ${PROJECT_BINARY_DIR}/sansui-viewer.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT viewer OPTIONAL)
if(SANSUI_MPI)
  # The MPI plugin `sansui` loads under mpirun (src/mpi/mpi_plugin.hpp), in a folder of its own.
  install(TARGETS sansui_mpi_plugin LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/sansui COMPONENT mpi)
endif()

# The library for C++ users.
install(TARGETS ${sansui_libraries} sansui sansui_options sansui_geotiff sansui_mesh_cgal
  EXPORT SansuiTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
  OBJECTS DESTINATION ${CMAKE_INSTALL_LIBDIR}/sansui/objects COMPONENT dev)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sansui COMPONENT dev FILES_MATCHING PATTERN "*.hpp")
install(EXPORT SansuiTargets NAMESPACE Sansui:: DESTINATION ${SANSUI_CMAKE_DIR} COMPONENT dev)
configure_package_config_file(cmake/SansuiConfig.cmake.in ${PROJECT_BINARY_DIR}/SansuiConfig.cmake INSTALL_DESTINATION ${SANSUI_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/SansuiConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/SansuiConfig.cmake ${PROJECT_BINARY_DIR}/SansuiConfigVersion.cmake DESTINATION ${SANSUI_CMAKE_DIR}
        COMPONENT dev)

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
install(FILES ${PROJECT_BINARY_DIR}/sansui.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT dev)

# The command line's manual page (compressed, as man reads it) and completion, the tables and
# example scenes for reference.
install(FILES ${PROJECT_BINARY_DIR}/sansui.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT cli)
install(FILES ${PROJECT_BINARY_DIR}/sansui.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME sansui
        COMPONENT cli)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION ${CMAKE_INSTALL_DATADIR}/sansui/data COMPONENT cli)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/sansui/examples/scenes COMPONENT cli)

# The Blender add-on, where Debian's Blender reads its system add-ons (blender-data's
# /usr/share/blender/scripts/addons): Edit > Preferences > Add-ons lists it, ready to tick.
if(SANSUI_PYTHON)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/blender/sansui_terrain DESTINATION ${CMAKE_INSTALL_DATADIR}/blender/scripts/addons
          COMPONENT blender FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
endif()

# The documentation: the README and the pages' text with the command line (the pages' own
# links between them still work), their pictures (21 MB) in a package of their own.
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT cli)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs COMPONENT cli FILES_MATCHING PATTERN "*.md"
        PATTERN images EXCLUDE)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs COMPONENT doc
        FILES_MATCHING PATTERN "*.png" PATTERN "*.svg")

# Debian packages: `cpack -G DEB` in the build folder writes one package per component:
#   sansui          the command line (pictures headless through Mesa's EGL)
#   sansui-viewer   the interactive viewer (GLFW)
#   sansui-mpi      the MPI plugin: `mpirun -np N sansui run` spreads tiled worlds over ranks
#   sansui-dev      static libraries, headers, CMake package, pkg-config file
#   python3-sansui  the Python module (when built: pybind11, numpy)
#   sansui-blender  the Blender add-on (needs the module)
#   sansui-doc      the pictures of the documentation
# MPI and GLFW are thus only installed with the packages that use them: the program links no
# MPI (its MPI part is the plugin), and only the viewer links GLFW. Each package carries
# /usr/share/doc/PACKAGE/copyright (DEP-5; cmake/debian/copyright) and changelog.Debian.gz
# (cmake/debian/changelog, whose first version must be the package's: deb_test.sh checks it),
# and passes lintian without errors (tests/install/deb_test.sh; the warnings kept are in
# cmake/debian/lintian-overrides, with reasons). Debian's dependencies come from
# dpkg-shlibdeps plus, below, what the programs load at run time, which it cannot see. gzip:
# xz takes minutes on the libraries. Installed into a clean Debian 12 by apt, with a picture
# rendered there: tests/install/clean_root_test.sh.
set(SANSUI_DEB_RELEASE 1)
set(sansui_deb_version ${PROJECT_VERSION}-${SANSUI_DEB_RELEASE})
set(sansui_components cli viewer dev doc)
set(sansui_package_cli sansui)
set(sansui_package_viewer sansui-viewer)
set(sansui_package_dev sansui-dev)
set(sansui_package_doc sansui-doc)
if(SANSUI_MPI)
  list(APPEND sansui_components mpi)
  set(sansui_package_mpi sansui-mpi)
endif()
if(SANSUI_PYTHON)
  list(APPEND sansui_components python blender)
  set(sansui_package_python python3-sansui)
  set(sansui_package_blender sansui-blender)
endif()

# The files of /usr/share/doc/PACKAGE, compressed without a time stamp (gzip -n) as Debian's are.
set(sansui_deb_dir ${PROJECT_BINARY_DIR}/debian)
file(MAKE_DIRECTORY ${sansui_deb_dir})
add_custom_command(OUTPUT ${sansui_deb_dir}/changelog.Debian.gz ${sansui_deb_dir}/changelog.gz
  COMMAND gzip -9nc ${PROJECT_SOURCE_DIR}/cmake/debian/changelog > ${sansui_deb_dir}/changelog.Debian.gz
  COMMAND gzip -9nc ${PROJECT_SOURCE_DIR}/CHANGELOG.md > ${sansui_deb_dir}/changelog.gz
  DEPENDS ${PROJECT_SOURCE_DIR}/cmake/debian/changelog ${PROJECT_SOURCE_DIR}/CHANGELOG.md
  COMMENT "Compressing the changelogs for /usr/share/doc")
add_custom_target(sansui_package_files ALL DEPENDS ${sansui_deb_dir}/changelog.Debian.gz ${sansui_deb_dir}/changelog.gz)
foreach(component IN LISTS sansui_components)
  set(package ${sansui_package_${component}})
  install(FILES ${PROJECT_SOURCE_DIR}/cmake/debian/copyright ${sansui_deb_dir}/changelog.Debian.gz
          DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/${package} COMPONENT ${component})
  install(FILES ${PROJECT_SOURCE_DIR}/cmake/debian/lintian-overrides DESTINATION ${CMAKE_INSTALL_DATADIR}/lintian/overrides
          RENAME ${package} COMPONENT ${component})
endforeach()
install(FILES ${sansui_deb_dir}/changelog.gz DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT cli)  # CHANGELOG.md

set(CPACK_GENERATOR DEB)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL ${sansui_components})
set(CPACK_PACKAGE_NAME sansui)
set(CPACK_PACKAGE_VENDOR Sansui)
# The maintainers, by the address their commits carry (git log).
set(CPACK_PACKAGE_CONTACT "Sansui maintainers <maintainers@users.noreply.h-seed-33883018.example>")
# Each package's description below starts with its own synopsis; CPack would put the project's
# summary in front of every one of them.
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE ${SANSUI_DEB_RELEASE})
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# ... but not where nothing is linked dynamically (static libraries, headers, pictures, Python
# sources): CPack runs `file` once per packaged file to look for programs, 12 s for sansui-dev's.
set(CPACK_DEBIAN_DEV_PACKAGE_SHLIBDEPS OFF)
set(CPACK_DEBIAN_DOC_PACKAGE_SHLIBDEPS OFF)
set(CPACK_DEBIAN_BLENDER_PACKAGE_SHLIBDEPS OFF)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)

# What the renderer loads at run time: libepoxy opens libEGL.so.1 (glvnd's libegl1), whose
# vendor library for a headless context is Mesa's (libegl-mesa0) with its software driver
# (libgl1-mesa-dri: llvmpipe, no GPU needed), and the desktop OpenGL functions from glvnd's
# libOpenGL.so.0 (libopengl0). GDAL is opened with dlopen when a DEM is first read through it
# (io/gdal_api.hpp): named by the package of the soname the build compiled in.
string(REGEX REPLACE "^libgdal\\.so\\.([0-9]+)$" "libgdal\\1" sansui_gdal_package "${sansui_gdal_soname}")
set(sansui_runtime_depends "${sansui_gdal_package}, libegl1, libegl-mesa0, libgl1-mesa-dri, libopengl0")
set(sansui_same_version "(= ${sansui_deb_version})")

# A Debian description: the synopsis, then paragraphs wrapped to 78 columns (lintian warns
# about longer lines, and CPack does not wrap them).
function(sansui_deb_description variable synopsis)
  set(text "${synopsis}")
  set(separator "")
  foreach(paragraph IN LISTS ARGN)
    string(APPEND text "${separator}")  # an empty line between paragraphs (" ." in the control file)
    set(separator "\n")
    string(REPLACE " " ";" words "${paragraph}")
    set(line "")
    foreach(word IN LISTS words)
      string(LENGTH "${line} ${word}" length)
      if(line AND length GREATER 78)
        string(APPEND text "\n${line}")
        set(line "${word}")
      elseif(line)
        string(APPEND line " ${word}")
      else()
        set(line "${word}")
      endif()
    endforeach()
    string(APPEND text "\n${line}")
  endforeach()
  set(${variable} "${text}" PARENT_SCOPE)
endfunction()

set(CPACK_DEBIAN_CLI_PACKAGE_NAME sansui)
set(CPACK_DEBIAN_CLI_PACKAGE_SECTION science)
set(CPACK_DEBIAN_CLI_PACKAGE_DEPENDS "${sansui_runtime_depends}")
set(CPACK_DEBIAN_CLI_PACKAGE_SUGGESTS "sansui-doc, sansui-viewer, sansui-mpi, python3-sansui, gdal-bin")
set(sansui_about "Sansui makes natural scenery from a few parameters: fractal terrain, mountains grown from \
one contour line, rivers and lakes, rock and marble textures, trees, and whole scenes with sky, sun, clouds \
and sea from a climate, a season, the weather and a time of day. It writes heightmaps, GeoTIFFs, meshes and \
pictures for GIS, Blender and game engines. The same seed gives the same bytes.")
sansui_deb_description(CPACK_DEBIAN_CLI_DESCRIPTION "natural scenery from a few parameters: terrain, water, scenes" "${sansui_about}"
  "This package holds the command-line tool sansui, with its manual page, bash completion, example scenes \
and documentation. It draws pictures headless, with Mesa's EGL: no display or GPU is needed.")

set(CPACK_DEBIAN_VIEWER_PACKAGE_NAME sansui-viewer)
set(CPACK_DEBIAN_VIEWER_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_VIEWER_PACKAGE_DEPENDS "${sansui_runtime_depends}, libglx-mesa0")
set(CPACK_DEBIAN_VIEWER_PACKAGE_RECOMMENDS "sansui ${sansui_same_version}")
sansui_deb_description(CPACK_DEBIAN_VIEWER_DESCRIPTION "interactive viewer of Sansui's natural scenery" "${sansui_about}"
  "This package holds sansui-viewer: front, side, top and perspective views of a scene in a window (GLFW, \
OpenGL 3.3), its parameters edited live, a walk through the terrain, and scripts that run unattended.")

set(CPACK_DEBIAN_MPI_PACKAGE_NAME sansui-mpi)
set(CPACK_DEBIAN_MPI_PACKAGE_SECTION science)
set(CPACK_DEBIAN_MPI_PACKAGE_DEPENDS "sansui ${sansui_same_version}, openmpi-bin")
sansui_deb_description(CPACK_DEBIAN_MPI_DESCRIPTION "Sansui's tiled worlds over MPI ranks" "${sansui_about}"
  "This package holds the MPI plugin of the sansui program: under mpirun (Open MPI), `mpirun -np 4 sansui \
run world.toml` spreads a tiled world's tiles over the ranks and gives the same bytes as one process. \
Without it, sansui links no MPI.")

set(CPACK_DEBIAN_DEV_PACKAGE_NAME sansui-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
# The packages whose headers and libraries the installed CMake package and sansui.pc name
# (cmake/SansuiConfig.cmake.in, cmake/sansui.pc.in).
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "libtbb-dev, libfmt-dev, nlohmann-json3-dev, libsimdjson-dev, libglm-dev, \
libtinygltf-dev, libtinyobjloader-dev, libeigen3-dev, libtomlplusplus-dev, libcgal-dev, libgdal-dev, libegl-dev, \
libgl-dev, libopengl-dev, libpng-dev, libtiff-dev, libgeotiff-dev, libepoxy-dev, libpolyclipping-dev, libproj-dev, \
libgmp-dev, libmpfr-dev, pkg-config, ${sansui_runtime_depends}")
set(CPACK_DEBIAN_DEV_PACKAGE_RECOMMENDS "cmake (>= 3.25), g++ (>= 4:12)")
sansui_deb_description(CPACK_DEBIAN_DEV_DESCRIPTION "Sansui's C++20 library: static libraries and headers" "${sansui_about}"
  "This package holds the library as static libraries with their headers (include/sansui), a CMake package \
(find_package(Sansui), target Sansui::sansui) and a pkg-config file (sansui.pc).")

if(SANSUI_PYTHON)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-sansui)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  # The extension is built for Debian 12's Python 3.11 (its file name says cpython-311).
  math(EXPR sansui_python_next "${Python_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "python3 (>= ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}~), \
python3 (<< ${Python_VERSION_MAJOR}.${sansui_python_next}), python3-numpy, ${sansui_runtime_depends}")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_RECOMMENDS "python3-xarray, python3-rioxarray")
  sansui_deb_description(CPACK_DEBIAN_PYTHON_DESCRIPTION "Python 3 module of Sansui's natural scenery" "${sansui_about}"
    "This package holds the Python module sansui: every node kind as a function, heightfields as numpy arrays \
shared without copies (DataArrays with coordinates and CRS when xarray is installed), and whole recipes.")

  set(CPACK_DEBIAN_BLENDER_PACKAGE_NAME sansui-blender)
  set(CPACK_DEBIAN_BLENDER_PACKAGE_SECTION graphics)
  set(CPACK_DEBIAN_BLENDER_PACKAGE_ARCHITECTURE all)
  # An arch-all package on an arch-any one: a range, not "=", so a rebuild (binNMU) still fits.
  set(CPACK_DEBIAN_BLENDER_PACKAGE_DEPENDS "python3-sansui (>= ${sansui_deb_version}), python3-sansui (<< ${sansui_deb_version}.1~)")
  set(CPACK_DEBIAN_BLENDER_PACKAGE_ENHANCES blender)
  sansui_deb_description(CPACK_DEBIAN_BLENDER_DESCRIPTION "Blender add-on for Sansui's natural scenery" "${sansui_about}"
    "This package holds the Blender add-on Sansui terrain, among Blender's system add-ons: Add > Mesh > \
Sansui terrain makes an eroded, textured and planted terrain, and a panel made from the library's \
parameter tables edits it.")
endif()

set(CPACK_DEBIAN_DOC_PACKAGE_NAME sansui-doc)
set(CPACK_DEBIAN_DOC_PACKAGE_SECTION doc)
set(CPACK_DEBIAN_DOC_PACKAGE_ARCHITECTURE all)
sansui_deb_description(CPACK_DEBIAN_DOC_DESCRIPTION "pictures of Sansui's documentation" "${sansui_about}"
  "This package holds the pictures of the documentation pages that the sansui package installs in \
/usr/share/doc/sansui.")

include(CPack)
