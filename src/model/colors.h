/* OpenSCAD's colour names and hexadecimal colours, for color("name") and
 * material(color = ...) (colors.c). */
#ifndef SPANCAST_MODEL_COLORS_H
#define SPANCAST_MODEL_COLORS_H

#include <stddef.h>

/* Looks up an OpenSCAD colour: a CSS/SVG name (any case) or "#rgb",
 * "#rgba", "#rrggbb", "#rrggbbaa". Returns 1 and fills rgba (0..1) when
 * known, else 0. */
int colors_lookup(const char *name, size_t length, float rgba[4]);

/* The colour table, for tests: its size and the index-th name. */
size_t colors_count(void);
const char *colors_name(size_t index);

#endif
