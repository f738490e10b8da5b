/* OpenSCAD's render colour schemes (--colorscheme).
 *
 * OpenSCAD 2021.01 has one scheme built in, Cornfield (ColorMap.cc), and
 * reads the others from the *.json files of its color-schemes/render
 * folder, which Debian's openscad package installs. A file is
 *
 *   { "name": "Metallic", "index": 1100, "show-in-gui": true,
 *     "colors": { "background": "#aaaaff", "axes-color": "#222233", ... } }
 *
 * with eleven colours, each exactly "#rrggbb". As in OpenSCAD, a file
 * without a name, an index, show-in-gui or one of the eleven colours, or
 * with a colour in another form, is not a scheme and is passed over, and
 * names are listed in the order of their index (Cornfield is 1000). The
 * files are read at run time with cJSON, so a scheme added to the folder
 * is found without a rebuild; Cornfield needs no file.
 */
#include <cJSON.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/sized.h"
#include "formats/file.h"
#include "spancast/spancast.h"

#define SCHEME_FILE_LIMIT (1u << 20) /* a scheme file is a few hundred bytes */
#define SCHEME_MAX_FILES 256         /* files of the folder looked at */

/* The colour keys of a scheme file, in OpenSCAD's order. */
static const char *const color_keys[] = {
    "background",      "axes-color",   "opencsg-face-front", "opencsg-face-back",
    "cgal-face-front", "cgal-face-2d", "cgal-face-back",     "cgal-edge-front",
    "cgal-edge-back",  "cgal-edge-2d", "crosshair"};
enum { KEY_COUNT = sizeof color_keys / sizeof color_keys[0] };

static void set_rgb(float out[3], unsigned rgb)
{
    out[0] = (float)((rgb >> 16) & 0xff) / 255.0f;
    out[1] = (float)((rgb >> 8) & 0xff) / 255.0f;
    out[2] = (float)(rgb & 0xff) / 255.0f;
}

void sc_color_scheme_default(sc_color_scheme *s)
{
    memset(s, 0, sizeof *s);
    strcpy(s->name, "Cornfield");
    set_rgb(s->background, 0xffffe5);
    set_rgb(s->axes, 0x000000);
    set_rgb(s->face_front, 0xf9d72c);
    set_rgb(s->face_back, 0x9dcb51);
    set_rgb(s->render_face, 0xf9d72c);
    set_rgb(s->render_face_back, 0x9dcb51);
    set_rgb(s->edge, 0xffec5e);
    set_rgb(s->crosshair, 0x800000);
}

/* "#rrggbb" as 0xrrggbb; -1 for anything else. */
static long parse_hex_color(const char *text)
{
    if (!text || strlen(text) != 7 || text[0] != '#')
        return -1;
    long v = 0;
    for (int k = 1; k < 7; k++) {
        char c = text[k];
        int d = c >= '0' && c <= '9'   ? c - '0'
                : c >= 'a' && c <= 'f' ? c - 'a' + 10
                : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                       : -1;
        if (d < 0)
            return -1;
        v = v * 16 + d;
    }
    return v;
}

/* A scheme read from one file, with the two 2D colours the fixed record
 * sc_color_scheme has no room for. */
typedef struct scheme_entry {
    int index;
    sc_color_scheme scheme;
    float face_2d[3], edge_2d[3];
} scheme_entry;

/* Cornfield, built in. */
static void default_entry(scheme_entry *e)
{
    e->index = 1000;
    sc_color_scheme_default(&e->scheme);
    set_rgb(e->face_2d, 0x00bf99);
    set_rgb(e->edge_2d, 0xff0000);
}

/* Reads the scheme file at path into *out; returns 1, or 0 when the file
 * is not a valid scheme. */
static int read_scheme(const char *path, scheme_entry *out)
{
    const char *why;
    size_t size;
    char *text = file_read(path, SCHEME_FILE_LIMIT, &size, &why);
    if (!text)
        return 0;
    cJSON *root = cJSON_ParseWithLength(text, size);
    free(text);
    if (!root)
        return 0;
    int ok = 0;
    const cJSON *name = cJSON_GetObjectItemCaseSensitive(root, "name");
    const cJSON *index = cJSON_GetObjectItemCaseSensitive(root, "index");
    const cJSON *gui = cJSON_GetObjectItemCaseSensitive(root, "show-in-gui");
    const cJSON *colors = cJSON_GetObjectItemCaseSensitive(root, "colors");
    if (cJSON_IsString(name) && name->valuestring[0] &&
        strlen(name->valuestring) < SC_COLOR_SCHEME_NAME_MAX && cJSON_IsNumber(index) &&
        cJSON_IsBool(gui) && cJSON_IsObject(colors)) {
        long rgb[KEY_COUNT];
        ok = 1;
        for (int k = 0; ok && k < KEY_COUNT; k++) {
            const cJSON *c = cJSON_GetObjectItemCaseSensitive(colors, color_keys[k]);
            rgb[k] = cJSON_IsString(c) ? parse_hex_color(c->valuestring) : -1;
            ok = rgb[k] >= 0;
        }
        if (ok) {
            sc_color_scheme *s = &out->scheme;
            memset(s, 0, sizeof *s);
            strcpy(s->name, name->valuestring);
            out->index = index->valueint;
            set_rgb(s->background, (unsigned)rgb[0]);
            set_rgb(s->axes, (unsigned)rgb[1]);
            set_rgb(s->face_front, (unsigned)rgb[2]);
            set_rgb(s->face_back, (unsigned)rgb[3]);
            set_rgb(s->render_face, (unsigned)rgb[4]);
            set_rgb(s->render_face_back, (unsigned)rgb[6]);
            set_rgb(s->edge, (unsigned)rgb[7]);
            set_rgb(s->crosshair, (unsigned)rgb[10]);
            set_rgb(out->face_2d, (unsigned)rgb[5]);
            set_rgb(out->edge_2d, (unsigned)rgb[9]);
        }
    }
    cJSON_Delete(root);
    return ok;
}

static int by_index(const void *a, const void *b)
{
    const scheme_entry *x = a, *y = b;
    if (x->index != y->index)
        return x->index < y->index ? -1 : 1;
    return strcmp(x->scheme.name, y->scheme.name);
}

static int has_json_suffix(const char *name)
{
    size_t n = strlen(name);
    return n > 5 && !strcmp(name + n - 5, ".json");
}

/* Finds the scheme called name in folder (sc_color_scheme_find) and copies
 * it to *out. */
static sc_status find_entry(const char *name, const char *folder, scheme_entry *out,
                            sc_error *error)
{
    if (!folder)
        folder = SC_COLOR_SCHEME_FOLDER;
    scheme_entry *entries = calloc(SCHEME_MAX_FILES + 1, sizeof *entries);
    if (!entries)
        return err_nomem(error, NULL);
    size_t count = 1;
    default_entry(&entries[0]);
    DIR *dir = opendir(folder);
    if (dir) {
        struct dirent *e;
        while ((e = readdir(dir)) != NULL && count <= SCHEME_MAX_FILES) {
            if (!has_json_suffix(e->d_name))
                continue;
            char path[4096];
            int n = snprintf(path, sizeof path, "%s/%s", folder, e->d_name);
            if (n < 0 || (size_t)n >= sizeof path)
                continue;
            scheme_entry got;
            if (!read_scheme(path, &got))
                continue;
            int seen = 0; /* the first scheme of a name wins, as in OpenSCAD */
            for (size_t k = 0; k < count && !seen; k++)
                seen = !strcmp(entries[k].scheme.name, got.scheme.name);
            if (!seen)
                entries[count++] = got;
        }
        closedir(dir);
    }
    qsort(entries, count, sizeof *entries, by_index);
    for (size_t k = 0; k < count; k++) {
        if (!strcmp(entries[k].scheme.name, name)) {
            *out = entries[k];
            free(entries);
            return SC_OK;
        }
    }
    char names[SC_ERROR_MESSAGE_MAX / 2];
    size_t used = 0;
    names[0] = '\0';
    for (size_t k = 0; k < count && used < sizeof names; k++) {
        int n = snprintf(names + used, sizeof names - used, "%s'%s'", k ? ", " : "",
                         entries[k].scheme.name);
        if (n < 0)
            break;
        used += (size_t)n;
    }
    free(entries);
    return err_set(error, SC_ERR_ARGUMENT, NULL,
                   "unknown colour scheme '%.64s' (known: %s)", name, names);
}

sc_status sc_color_scheme_find(const char *name, const char *folder,
                               sc_color_scheme *scheme, sc_error *error)
{
    if (!name || !scheme)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "sc_color_scheme_find needs a name and a scheme");
    scheme_entry found;
    sc_status st = find_entry(name, folder, &found, error);
    if (st == SC_OK)
        *scheme = found.scheme;
    return st;
}

sc_status sc_render_options_set_scheme(sc_render_options *options, const char *name,
                                       const char *folder, sc_error *error)
{
    if (!name || !options)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "sc_render_options_set_scheme needs options and a name");
    if (options->size < SIZED_MIN(sc_render_options, edge_2d))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "sc_render_options_set_scheme needs options from a header with "
                       "edge_2d (sc_render_options_init)");
    scheme_entry found;
    sc_status st = find_entry(name, folder, &found, error);
    if (st != SC_OK)
        return st;
    options->scheme = found.scheme;
    options->use_scheme = 1;
    memcpy(options->face_2d, found.face_2d, sizeof options->face_2d);
    memcpy(options->edge_2d, found.edge_2d, sizeof options->edge_2d);
    return SC_OK;
}
