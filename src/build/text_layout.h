/* The text plugin's interface: text() laid out by fontconfig, HarfBuzz and
 * FreeType, which only the plugin spancast-text.so (text/text_freetype.c)
 * links. Those three bring glib, PCRE2, graphite2, Brotli, expat, libpng
 * and zlib with them: about a dozen shared objects whose loading and
 * start-up every run paid for when the tool linked them. build_text.c loads
 * the plugin on the first text node (plugin.h), or for the first font file
 * a model registers (text_register_font); no other run loads them.
 *
 * The plugin writes only plain, malloc'd arrays into a text_shape, which
 * text_shape_free releases with free(), and messages as text; the
 * positions and sc_error values belong to build_text.c.
 */
#ifndef SPANCAST_BUILD_TEXT_LAYOUT_H
#define SPANCAST_BUILD_TEXT_LAYOUT_H

#include <stddef.h>

#include "build/build_text.h"
#include "model/model.h"

#define TEXT_PLUGIN_FILE "spancast-text.so"

/* spancast_text_layout: lays out a (a->length > 0) into out, which the
 * caller has zeroed and given size and curve_points. Returns SC_OK, or a
 * status with a message (no position) in err: SC_ERR_NOMEM (err empty:
 * out of memory), SC_ERR_SEMANTIC (no such font, a bad font name or
 * size), SC_ERR_IO (the font file does not open). On failure out may hold
 * arrays for text_shape_free. The first warning (an unknown font family,
 * halign or valign) goes to note, which is left alone when it is not
 * empty. */
typedef sc_status text_layout_fn(const model_text *a, text_shape *out, char *note,
                                 size_t note_size, char *err, size_t err_size);

/* spancast_text_register: adds the font file at path to fontconfig's
 * configuration of the process (its application fonts), so that later
 * layouts find it by its family name. Returns SC_OK, or SC_ERR_IO with a
 * message in err when fontconfig cannot read it. */
typedef sc_status text_register_fn(const char *path, char *err, size_t err_size);

#endif
