/* The browser build's proj.h (cmake/SansuiWeb.cmake): the browser build has no PROJ, and a world
 * there has no coordinate reference system (web/stubs/crs.cpp refuses one), so the one file that
 * still names PROJ, io/envi_header.cpp, only ever asks it for the WKT of a CRS it never has.
 * These are the calls that file makes, each answering "nothing": the .hdr gets no CRS line. */
#pragma once

typedef struct pj_ctx PJ_CONTEXT;
typedef struct PJconsts PJ;
typedef enum { PJ_LOG_NONE = 0 } PJ_LOG_LEVEL;
typedef enum { PJ_WKT1_GDAL = 3 } PJ_WKT_TYPE;

static inline PJ_CONTEXT* proj_context_create(void) { return 0; }
static inline void proj_context_destroy(PJ_CONTEXT* context) { (void)context; }
static inline PJ_LOG_LEVEL proj_log_level(PJ_CONTEXT* context, PJ_LOG_LEVEL level) { (void)context; return level; }
static inline PJ* proj_create(PJ_CONTEXT* context, const char* text) { (void)context; (void)text; return 0; }
static inline const char* proj_as_wkt(PJ_CONTEXT* context, const PJ* object, PJ_WKT_TYPE type, const char* const* options) {
  (void)context; (void)object; (void)type; (void)options; return 0;
}
static inline void proj_destroy(PJ* object) { (void)object; }
