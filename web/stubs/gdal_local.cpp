// The browser build's io/gdal_local.cpp: no GDAL (cmake/SansuiWeb.cmake); its only callers, the
// GDAL reader and the VRT writer, are stubs too.
