/* Reading SVG drawings into 2D regions, as OpenSCAD 2021.01's
 * import("file.svg") reads them (svg.c has the rules). */
#ifndef SPANCAST_FORMATS_SVG_H
#define SPANCAST_FORMATS_SVG_H

#include <stddef.h>
#include <stdint.h>

#include "spancast/spancast.h"
#include "twod/twod.h"

/* Largest SVG file read, in bytes. */
#define SVG_MAX_FILE (64u * 1024u * 1024u)

typedef struct svg_options {
    double dpi; /* user units to the inch where the page gives no unit */
    int center; /* centre the drawing's bounds on the origin */
} svg_options;

/* The shapes OpenSCAD's clipper refuses an outline of (twod_clipper_admit):
 * how many, and the first (numbered from 1; 0: none). */
typedef struct svg_refused {
    uint32_t shapes, first;
} svg_refused;

/* Reads the SVG text (size bytes) into out, which must be initialised and
 * is replaced by the union of the drawing's shapes (OpenSCAD's region,
 * through the clipper). As OpenSCAD 2021.01 sanitizes each shape before
 * the union, a shape's outline past the clipper's range and those after it
 * in that shape are left out, counted in *refused (for the caller's
 * warning). name is the file as the model names it, for messages; errors
 * are set at *at as "import: NAME:LINE: why" (LINE where the XML parser
 * gives one). */
sc_status svg_read(const char *text, size_t size, const char *name, const sc_location *at,
                   const svg_options *o, twod_region *out, svg_refused *refused,
                   sc_error *error);

/* Reads the file at path (at most SVG_MAX_FILE bytes) through svg_read. */
sc_status svg_read_file(const char *path, const char *name, const sc_location *at,
                        const svg_options *o, twod_region *out, svg_refused *refused,
                        sc_error *error);

#endif
