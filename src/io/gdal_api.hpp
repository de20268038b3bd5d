// GDAL's C functions that Sansui calls, loaded when a command first reads a DEM through GDAL or
// writes a VRT. libgdal and the hundred libraries it needs (HDF5, netCDF, poppler, curl...) take
// 0.1-0.15 s to load, more than the rest of a `sansui` start together; most commands never need
// them. The headers give the functions' types; the library is opened by its soname with dlopen.
// Internal to io/.
#pragma once

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_minixml.h>
#include <gdal.h>
#include <gdal_utils.h>
#include <ogr_srs_api.h>

namespace sansui::io::detail {

// clang-format off: the formatter does not settle on a layout for this list.
#define SANSUI_GDAL_FUNCTIONS(X)   \
  X(GDALAllRegister)               \
  X(GDALOpenEx)                    \
  X(GDALClose)                     \
  X(GDALGetRasterXSize)            \
  X(GDALGetRasterYSize)            \
  X(GDALGetRasterCount)            \
  X(GDALGetGeoTransform)           \
  X(GDALGetSpatialRef)             \
  X(GDALGetRasterBand)             \
  X(GDALRasterIO)                  \
  X(GDALGetRasterNoDataValue)      \
  X(GDALGetRasterScale)            \
  X(GDALGetRasterOffset)           \
  X(GDALGetDriverCount)            \
  X(GDALGetDriver)                 \
  X(GDALGetDriverShortName)        \
  X(GDALDeregisterDriver)          \
  X(GDALDestroyDriver)             \
  X(GDALBuildVRT)                  \
  X(OSRExportToWktEx)              \
  X(OSRIsGeographic)               \
  X(OSRSetPROJEnableNetwork)       \
  X(VSIFree)                       \
  X(CPLPushErrorHandler)           \
  X(CPLQuietErrorHandler)          \
  X(CPLErrorReset)                 \
  X(CPLPopErrorHandler)            \
  X(CPLGetLastErrorMsg)            \
  X(CPLSetConfigOption)            \
  X(CPLSetThreadLocalConfigOption) \
  X(CPLGetThreadLocalConfigOption) \
  X(GDALIdentifyDriverEx)          \
  X(CPLParseXMLString)             \
  X(CPLGetXMLValue)                \
  X(CPLDestroyXMLNode)
// clang-format on

/// The functions, each a pointer of its declared type.
struct GdalApi {
#define SANSUI_GDAL_FIELD(name) decltype(&::name) name = nullptr;  // NOLINT(bugprone-macro-parentheses): a declaration
  SANSUI_GDAL_FUNCTIONS(SANSUI_GDAL_FIELD)
#undef SANSUI_GDAL_FIELD
  /// C++ sees two (a const overload); the library exports the C one.
  CPLXMLNode* (*CPLGetXMLNode)(CPLXMLNode*, const char*) = nullptr;
};

/// The functions, libgdal loaded on the first call (thread-safe). Throws InputError when GDAL
/// cannot be loaded (not installed), naming the library.
const GdalApi& gdal_api();

}  // namespace sansui::io::detail
