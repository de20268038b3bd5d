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
