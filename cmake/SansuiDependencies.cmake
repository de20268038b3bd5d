# Every dependency is a Debian 12 package installed by scripts/setup; nothing is downloaded.
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)
find_package(TBB REQUIRED)
find_package(fmt REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(nlohmann_json REQUIRED)
# simdjson (libsimdjson-dev): contour maps read in one streaming pass (io/contour_lines_geojson.cpp).
find_package(simdjson REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(tinyobjloader REQUIRED)
find_package(Eigen3 REQUIRED)
find_package(glm CONFIG REQUIRED)
find_package(OpenGL REQUIRED COMPONENTS EGL OpenGL)
pkg_check_modules(PNG REQUIRED IMPORTED_TARGET libpng)
pkg_check_modules(TIFF REQUIRED IMPORTED_TARGET libtiff-4)
pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)
# PROJ (libproj-dev): coordinate reference systems, checked and described from its EPSG database
# (io/crs.hpp).
pkg_check_modules(PROJ REQUIRED IMPORTED_TARGET proj)
# GDAL (libgdal-dev): DEMs in every raster format GIS tools write (io/gdal_raster.cpp).
find_package(GDAL CONFIG REQUIRED)
# Its soname: io/ opens the library with dlopen when it is first needed (io/gdal_api.hpp).
get_target_property(sansui_gdal_soname GDAL::GDAL IMPORTED_SONAME_NONE)
if(NOT sansui_gdal_soname)
  get_target_property(sansui_gdal_soname GDAL::GDAL IMPORTED_SONAME_RELEASE)
endif()
if(NOT sansui_gdal_soname)
  set(sansui_gdal_soname libgdal.so.32)  # Debian 12's GDAL 3.6
endif()

# libgeotiff ships no pkg-config or CMake file on Debian 12.
find_path(GEOTIFF_INCLUDE_DIR geotiff.h PATH_SUFFIXES geotiff REQUIRED)
find_library(GEOTIFF_LIBRARY geotiff REQUIRED)
add_library(sansui_geotiff INTERFACE)
target_include_directories(sansui_geotiff SYSTEM INTERFACE ${GEOTIFF_INCLUDE_DIR})
target_link_libraries(sansui_geotiff INTERFACE ${GEOTIFF_LIBRARY} PkgConfig::TIFF)

if(SANSUI_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(SANSUI_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

# The Python module (python/, docs/python.md): pybind11-dev, python3-dev and python3-numpy, which
# scripts/setup installs for the test command only; without them the module is left out.
option(SANSUI_PYTHON "Build the Python module when pybind11, Python 3 and NumPy are found" ON)
if(SANSUI_PYTHON)
  # Debian's python3, whose dist-packages hold numpy and whose version Blender embeds; not a
  # pyenv or conda interpreter that happens to be first on the PATH.
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(Python 3.11 COMPONENTS Interpreter Development.Module NumPy)
  if(Python_FOUND AND Python_NumPy_FOUND)
    find_package(pybind11 CONFIG)
  endif()
  if(NOT (Python_FOUND AND Python_NumPy_FOUND AND pybind11_FOUND))
    message(STATUS "Python module left out: needs pybind11-dev, python3-dev and python3-numpy (scripts/setup --test)")
    set(SANSUI_PYTHON OFF)
  endif()
endif()

# Worlds over MPI ranks (src/mpi/, `mpirun -np N sansui run`): on when MPI is found.
option(SANSUI_MPI "Build the MPI exchange when MPI is found" ON)
if(SANSUI_MPI)
  find_package(MPI COMPONENTS CXX)
  if(NOT MPI_CXX_FOUND)
    message(STATUS "MPI left out: needs libopenmpi-dev and openmpi-bin (scripts/setup --test)")
    set(SANSUI_MPI OFF)
  endif()
endif()
