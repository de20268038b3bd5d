# The browser build (docs/web.md): the library's layers compiled to WebAssembly by Debian's
# Emscripten (`scripts/build --web`, emcmake into build-web/), in place of
# cmake/SansuiDependencies.cmake. Nothing is downloaded here:
#
# - header-only libraries come from the same Debian packages as the native build, through a folder
#   of links to exactly their headers (build-web/web-include), never /usr/include itself, whose C
#   library headers are not Emscripten's;
# - the libraries the native build links as Debian shared objects (Clipper, simdjson, libpng,
#   zlib) are compiled here from their Debian source packages, which web/fetch-debian-sources
#   (scripts/setup --web) puts in build-deps/debian/;
# - what a browser does not need is left out: GDAL, PROJ, libtiff/GeoTIFF, MPI, EGL/GL (render/,
#   the viewer), CGAL (map sketches). The few files that call them are swapped for web/stubs/,
#   which say in one line that the browser build cannot do that (sansui_web_sources below);
# - the parallel seam (core/parallel.hpp) runs serially (SANSUI_PARALLEL=serial), or, with
#   SANSUI_WEB_THREADS (scripts/build --web configures build-web-threads/ so), on WebAssembly
#   threads (SANSUI_PARALLEL=threads, a std::thread pool): the module sansui-threads.js that the
#   page loads when it is cross-origin isolated. Shared memory needs every object compiled with
#   -pthread, hence a build folder of its own.
set(SANSUI_WEB ON)
option(SANSUI_WEB_THREADS "The browser module on WebAssembly threads (sansui-threads.js) rather than serial (sansui.js)" OFF)
if(SANSUI_WEB_THREADS)
  set(SANSUI_PARALLEL threads CACHE STRING "" FORCE)
  add_compile_options(-pthread)
  add_link_options(-pthread)
else()
  set(SANSUI_PARALLEL serial CACHE STRING "" FORCE)
endif()
set(SANSUI_BUILD_TESTS OFF CACHE BOOL "" FORCE)
set(SANSUI_BUILD_BENCH OFF CACHE BOOL "" FORCE)
set(SANSUI_PYTHON OFF CACHE BOOL "" FORCE)
set(SANSUI_MPI OFF CACHE BOOL "" FORCE)
set(SANSUI_NATIVE OFF CACHE BOOL "" FORCE)

set(SANSUI_WEB_DIR ${PROJECT_SOURCE_DIR}/web)
set(debian_sources ${PROJECT_SOURCE_DIR}/build-deps/debian CACHE PATH "Debian source packages for the browser build (web/fetch-debian-sources)")

# C++ exceptions as WebAssembly exceptions (the library reports bad input by throwing; Chromium
# has run them natively since 95), and 128-bit SIMD (no fused multiply-add: the same bytes).
add_compile_options(-fwasm-exceptions -msimd128)
# The few C++20 library parts that Emscripten 3.1.6's libc++ (LLVM 13's) lacks (web/compat/).
add_compile_options("$<$<COMPILE_LANGUAGE:CXX>:SHELL:-include ${PROJECT_SOURCE_DIR}/web/compat/libcxx13.hpp>")
add_link_options(-fwasm-exceptions)

find_package(Threads REQUIRED)

function(sansui_web_require_source folder)
  file(GLOB found LIST_DIRECTORIES true "${debian_sources}/${folder}")
  if(NOT found)
    message(FATAL_ERROR "The browser build needs Debian's source of ${folder} in ${debian_sources}: run web/fetch-debian-sources "
                        "(scripts/setup --web does)")
  endif()
  list(GET found 0 first)
  string(MAKE_C_IDENTIFIER "${folder}" name)
  set(source_${name} ${first} PARENT_SCOPE)
endfunction()
sansui_web_require_source(libpolyclipping-*)
sansui_web_require_source(simdjson-*)
sansui_web_require_source(libpng1.6-*)
sansui_web_require_source(zlib-*)

# Headers of Debian's header-only packages, one link each.
set(web_include ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${web_include}/polyclipping)
foreach(link IN ITEMS fmt nlohmann glm toml++ tiny_gltf.h tiny_obj_loader.h eigen3/Eigen eigen3/unsupported stb/stb_image.h stb/stb_image_write.h)
  get_filename_component(name ${link} NAME)
  if(NOT EXISTS /usr/include/${link})
    message(FATAL_ERROR "/usr/include/${link} is missing: scripts/setup installs the Debian packages the browser build reads")
  endif()
  file(CREATE_LINK /usr/include/${link} ${web_include}/${name} SYMBOLIC)
endforeach()
file(CREATE_LINK ${source_libpolyclipping__}/cpp/clipper.hpp ${web_include}/polyclipping/clipper.hpp SYMBOLIC)
file(CREATE_LINK ${source_simdjson__}/singleheader/simdjson.h ${web_include}/simdjson.h SYMBOLIC)
foreach(header IN ITEMS png.h pngconf.h)
  file(CREATE_LINK ${source_libpng1_6__}/${header} ${web_include}/${header} SYMBOLIC)
endforeach()
file(CREATE_LINK ${SANSUI_WEB_DIR}/stubs/proj.h ${web_include}/proj.h SYMBOLIC)  # no PROJ: what io/envi_header.cpp asks of it
configure_file(${source_libpng1_6__}/scripts/pnglibconf.h.prebuilt ${web_include}/pnglibconf.h COPYONLY)
foreach(header IN ITEMS zlib.h zconf.h)
  file(CREATE_LINK ${source_zlib__}/${header} ${web_include}/${header} SYMBOLIC)
endforeach()

function(sansui_web_interface name)
  add_library(${name} INTERFACE IMPORTED GLOBAL)
  target_include_directories(${name} SYSTEM INTERFACE ${web_include})
  target_compile_definitions(${name} INTERFACE ${ARGN})
endfunction()
sansui_web_interface(fmt::fmt FMT_HEADER_ONLY)
sansui_web_interface(nlohmann_json::nlohmann_json)
sansui_web_interface(glm::glm)
sansui_web_interface(Eigen3::Eigen)
sansui_web_interface(tomlplusplus::tomlplusplus TOML_HEADER_ONLY=1)
sansui_web_interface(TBB::tbb)  # the serial seam includes no TBB header
# Left out: their callers are web/stubs/.
foreach(name IN ITEMS GDAL::GDAL PkgConfig::PROJ PkgConfig::TIFF sansui_geotiff CGAL::CGAL)
  add_library(${name} INTERFACE IMPORTED GLOBAL)
endforeach()

# Debian's sources, compiled as they are (their own warnings are not ours).
set(zlib_files adler32.c compress.c crc32.c deflate.c infback.c inffast.c inflate.c inftrees.c trees.c uncompr.c zutil.c)
list(TRANSFORM zlib_files PREPEND ${source_zlib__}/)
add_library(sansui_web_zlib STATIC ${zlib_files})
target_include_directories(sansui_web_zlib SYSTEM PUBLIC ${web_include})

set(png_files png.c pngerror.c pngget.c pngmem.c pngread.c pngrio.c pngrtran.c pngrutil.c pngset.c pngtrans.c pngwio.c pngwrite.c
    pngwtran.c pngwutil.c)
list(TRANSFORM png_files PREPEND ${source_libpng1_6__}/)
add_library(sansui_web_png STATIC ${png_files})
target_compile_definitions(sansui_web_png PRIVATE PNG_ARM_NEON_OPT=0 PNG_INTEL_SSE_OPT=0)
target_link_libraries(sansui_web_png PUBLIC sansui_web_zlib)
add_library(PkgConfig::PNG ALIAS sansui_web_png)

add_library(sansui_web_clipper STATIC ${source_libpolyclipping__}/cpp/clipper.cpp)
target_include_directories(sansui_web_clipper SYSTEM PUBLIC ${web_include})
add_library(PkgConfig::CLIPPER ALIAS sansui_web_clipper)

add_library(sansui_web_simdjson STATIC ${source_simdjson__}/singleheader/simdjson.cpp)
target_include_directories(sansui_web_simdjson SYSTEM PUBLIC ${web_include})
add_library(simdjson::simdjson ALIAS sansui_web_simdjson)

# tinygltf and tinyobjloader: Debian ships them as headers plus a shared object built from them;
# here their implementations are compiled from the same headers (web/deps/header_libraries.cpp).
add_library(sansui_web_header_libraries STATIC ${SANSUI_WEB_DIR}/deps/header_libraries.cpp)
target_include_directories(sansui_web_header_libraries SYSTEM PUBLIC ${web_include})
add_library(TinyGLTF::TinyGLTF ALIAS sansui_web_header_libraries)
add_library(tinyobjloader::tinyobjloader ALIAS sansui_web_header_libraries)

# The files of src/ that the browser build compiles from web/stubs/ instead (src/CMakeLists.txt's
# sansui_library calls this): each calls a library the browser build leaves out.
set(sansui_web_stubbed io/gdal_raster.cpp io/gdal_local.cpp io/gdal_api.cpp io/geotiff.cpp io/crs.cpp io/vrt_mosaic.cpp)
function(sansui_web_sources out_var)
  file(RELATIVE_PATH folder ${PROJECT_SOURCE_DIR}/src ${CMAKE_CURRENT_SOURCE_DIR})
  set(sources)
  foreach(source IN LISTS ARGN)
    if("${folder}/${source}" IN_LIST sansui_web_stubbed)
      get_filename_component(name ${source} NAME)
      list(APPEND sources ${SANSUI_WEB_DIR}/stubs/${name})
    else()
      list(APPEND sources ${source})
    endif()
  endforeach()
  set(${out_var} ${sources} PARENT_SCOPE)
endfunction()
