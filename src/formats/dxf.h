/* Reading DXF drawings into 2D contours, as OpenSCAD 2021.01's
 * import("file.dxf") reads them (dxf.c has the rules). */
#ifndef SPANCAST_FORMATS_DXF_H
#define SPANCAST_FORMATS_DXF_H

#include <stddef.h>

#include "spancast/spancast.h"
#include "twod/twod.h"

/* Largest DXF file read, in bytes. */
#define DXF_MAX_FILE (64u * 1024u * 1024u)
/* Most line segments in one drawing (lines, polyline edges, circle and arc
 * fragments, block lines and their inserted copies together). */
#define DXF_MAX_SEGMENTS 50000u
/* Most blocks in one drawing. */
#define DXF_MAX_BLOCKS 10000u
/* Most warnings passed on from one drawing; one more counts the rest. */
#define DXF_MAX_WARNINGS 100u

typedef struct dxf_options {
    double fn, fa, fs;         /* fragments of circles, arcs and ellipses */
    const char *layer;         /* only this layer's entities; NULL or "" for all */
    double origin_x, origin_y; /* subtracted from every coordinate ... */
    double scale;              /* ... before it is multiplied by this */
    /* Each warning OpenSCAD gives where it reads on (dxf.c), at the DXF
     * file's line: changes is 1 when what is drawn is not what the file
     * says (a value skipped, an entity left out, the rest of the file not
     * read). SC_OK reads on; any other status (its error set) stops the
     * reader with it. NULL: the warnings are dropped. */
    sc_status (*warn)(void *ctx, const sc_location *at, int changes, const char *message);
    void *warn_ctx;
} dxf_options;

/* Reads the DXF text (size bytes, not necessarily terminated) named path
 * (for messages: errors are set at path:line:1) into out, which must be
 * initialised and is replaced: one contour per path OpenSCAD joins from the
 * drawing's segments, open paths closed, not sanitized (the caller applies
 * OpenSCAD's even-odd sanitize). When unsupported is not NULL it receives
 * the name of the first entity OpenSCAD ignores (SPLINE, POLYLINE, ...),
 * or "" when there is none; it must hold 32 bytes. */
sc_status dxf_read(const char *text, size_t size, const char *path, const dxf_options *o,
                   twod_region *out, char *unsupported, sc_error *error);

/* Reads the file at path (at most DXF_MAX_FILE bytes) through dxf_read;
 * an unreadable file is an error at *at. */
sc_status dxf_read_file(const char *path, const sc_location *at, const dxf_options *o,
                        twod_region *out, char *unsupported, sc_error *error);

#endif
