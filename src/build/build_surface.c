/* surface(file, center, invert, convexity): a height map as the closed mesh
 * OpenSCAD 2021.01 builds (its src/surface.cc), through build_mesh_prim.
 *
 * Input. A PNG file (recognised by its 8-byte signature, whatever its
 * name) is read through OpenImageIO; pixel (x, y), row 0 at the top, of
 * an image h rows high gives the value at row h - 1 - y, column x:
 * 100 / 255 * L, L = 0.2126 R + 0.7152 G + 0.0722 B in 0..255 (a grey
 * image has R = G = B), and with invert, 100 / 255 * (1 - L), as
 * OpenSCAD computes it (so an inverted map lies below zero). Anything
 * else is a .dat text file: lines of numbers separated by spaces or tabs;
 * empty lines and lines starting with '#' are skipped; line i gives row
 * i, its k-th number column k; rows shorter than the longest are padded
 * with 0 (after the floor below is found, as OpenSCAD does, so padding
 * may touch the floor). A token that is not a finite number ends the
 * reading there, as OpenSCAD's does: the values before it are kept, its
 * own line's among them (a row when it holds one), with a warning.
 *
 * Mesh, for a grid of `lines` rows and `columns` columns of values v(i, j)
 * at (x, y) = (j, i) (shifted by -(columns - 1) / 2 and -(lines - 1) / 2
 * with center), and floor = min(0, min v - 1) over the values read:
 *   - each grid cell is four triangles meeting at its centre, whose
 *     height is the mean of the cell's corners;
 *   - each boundary edge of the grid is a wall quad down to the floor;
 *   - the floor is one polygon through all boundary points at floor
 *     height.
 * Its points are merged by their grid position (corners, cell centres and
 * floor points), so the mesh is closed; its winding follows OpenSCAD's.
 * A grid with fewer than 2 rows or 2 columns has no volume: the empty
 * solid with a warning.
 *
 * What OpenSCAD 2021.01 renders with a warning (its surface.cc: "The file
 * '...' couldn't be opened.", "Can't read PNG image '...'", "Illegal value
 * in '...'") is a warning here too, at the file name, and the rest of the
 * model is rendered: a file that cannot be opened, or that has a PNG
 * signature and cannot be decoded, is the empty surface, counted as left
 * out (build_notes), so that no second warning says it is empty; a .dat
 * file with an illegal value is what was read before it. With --strict
 * each is the error its warning starts with.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "build/build_hull.h"
#include "build/build_mesh.h"
#include "formats/file.h"
#include "formats/image_read.h"

typedef struct grid {
    double *v; /* lines * columns values, row by row */
    uint32_t lines, columns;
    double floor_z; /* min(0, smallest value read - 1) */
} grid;

static int is_png(const unsigned char *b, size_t n)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    return n >= 8 && memcmp(b, sig, 8) == 0;
}

/* A growable list of (row, column, value). */
typedef struct cells {
    double *v;
    uint32_t *row, *col;
    size_t count, cap;
} cells;

static int add_cell(cells *s, uint32_t r, uint32_t k, double v)
{
    if (s->count == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 1024;
        double *nv = realloc(s->v, cap * sizeof *nv);
        if (nv)
            s->v = nv;
        uint32_t *nr = realloc(s->row, cap * sizeof *nr);
        if (nr)
            s->row = nr;
        uint32_t *nc = realloc(s->col, cap * sizeof *nc);
        if (nc)
            s->col = nc;
        if (!nv || !nr || !nc)
            return 0;
        s->cap = cap;
    }
    s->v[s->count] = v;
    s->row[s->count] = r;
    s->col[s->count] = k;
    s->count++;
    return 1;
}

static sc_status too_large(const build_ctx *c, const sc_location *loc, const char *path)
{
    return err_set(c->error, SC_ERR_LIMIT, loc,
                   "surface: '%s' has too many points (limit is %u)", path,
                   BUILD_SURFACE_MAX_POINTS);
}

/* Parses .dat text into g. A token that is not a number ends the reading
 * there: its error in c->error, 1 in *stopped, and g holds what came
 * before (the status stays SC_OK). On a last line without its newline it
 * is 2: OpenSCAD 2021.01 warns of an illegal value only where its stream
 * is not at the end, and keeps the same values silently there. */
static sc_status read_dat(const build_ctx *c, const sc_location *loc, const char *path,
                          char *text, size_t size, grid *g, int *stopped)
{
    cells s;
    memset(&s, 0, sizeof s);
    uint32_t lines = 0, columns = 0, line_no = 0;
    sc_status st = SC_OK;
    *stopped = 0;
    char *p = text, *end = text + size;
    while (p < end && st == SC_OK && !*stopped) {
        char *eol = memchr(p, '\n', (size_t)(end - p));
        if (!eol)
            eol = end;
        *eol = 0;
        line_no++;
        char *q = p;
        while (*q == ' ' || *q == '\t' || *q == '\r' || *q == '\v' || *q == '\f')
            q++;
        if (*q && *q != '#') {
            uint32_t col = 0;
            while (*q && st == SC_OK && !*stopped) {
                while (*q == ' ' || *q == '\t' || *q == '\r')
                    q++;
                if (!*q)
                    break;
                char *tok = q;
                while (*q && *q != ' ' && *q != '\t' && *q != '\r')
                    q++;
                char saved = *q;
                *q = 0;
                char *stop;
                errno = 0;
                double v = strtod(tok, &stop);
                if (stop == tok || *stop || !isfinite(v)) {
                    err_set(c->error, SC_ERR_SEMANTIC, loc,
                            "surface: illegal value in '%s' line %u: '%.40s' is not a "
                            "number",
                            path, line_no, tok);
                    *stopped = eol == end ? 2 : 1;
                    break;
                }
                *q = saved;
                if (s.count >= BUILD_SURFACE_MAX_POINTS) {
                    st = too_large(c, loc, path);
                    break;
                }
                if (!add_cell(&s, lines, col++, v))
                    st = err_nomem(c->error, loc);
            }
            if (col > columns)
                columns = col;
            if (col || !*stopped) /* a line stopped at its first value is no row */
                lines++;
        }
        p = eol + 1;
    }
    if (st == SC_OK && (uint64_t)lines * columns > BUILD_SURFACE_MAX_POINTS)
        st = too_large(c, loc, path);
    if (st == SC_OK && lines && columns) {
        g->v = calloc((size_t)lines * columns, sizeof *g->v);
        if (!g->v)
            st = err_nomem(c->error, loc);
    }
    if (st == SC_OK) {
        g->lines = lines;
        g->columns = columns;
        for (size_t i = 0; i < s.count && g->v; i++) {
            g->v[(size_t)s.row[i] * columns + s.col[i]] = s.v[i];
            g->floor_z = fmin(g->floor_z, s.v[i] - 1);
        }
    }
    free(s.v);
    free(s.row);
    free(s.col);
    return st;
}

static sc_status read_png(const build_ctx *c, const sc_location *loc, const char *path,
                          int invert, grid *g)
{
    image_data img;
    char why[256];
    if (!image_read(path, &img, why, (int)sizeof why))
        return err_set(c->error, SC_ERR_IO, loc, "surface: can't read PNG image '%s': %s",
                       path, why);
    sc_status st = SC_OK;
    if ((uint64_t)img.width * (uint64_t)img.height > BUILD_SURFACE_MAX_POINTS) {
        st = too_large(c, loc, path);
    } else if (img.width > 0 && img.height > 0) {
        g->lines = (uint32_t)img.height;
        g->columns = (uint32_t)img.width;
        g->v = malloc((size_t)g->lines * g->columns * sizeof *g->v);
        if (!g->v)
            st = err_nomem(c->error, loc);
        for (uint32_t y = 0; g->v && y < g->lines; y++) {
            for (uint32_t x = 0; x < g->columns; x++) {
                const float *px =
                    img.pixels + ((size_t)y * g->columns + x) * img.channels;
                double rgb[3];
                for (int k = 0; k < 3; k++) {
                    float f = px[img.channels >= 3 ? k : 0];
                    rgb[k] = floor(f * 255.0 + 0.5); /* the 8-bit value */
                }
                double pixel = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
                double z = 100.0 / 255 * (invert ? 1 - pixel : pixel);
                g->v[(size_t)(g->lines - 1 - y) * g->columns + x] = z;
                g->floor_z = fmin(g->floor_z, z - 1);
            }
        }
    }
    image_data_free(&img);
    return st;
}

/* The mesh of g (see the top of this file) as a leaf in *out, or, when
 * faces is not NULL, as its faces in *faces (out unused): CGAL takes the
 * floor as the one polygon it is, where the leaf's fan of it has triangles
 * without area along its sides. */
static sc_status surface_mesh(const build_ctx *c, const sc_location *loc, const grid *g,
                              int center, prim *out, const char **empty,
                              build_mesh_faces *faces)
{
    uint32_t L = g->lines, C = g->columns;
    double floor_z = g->floor_z;
    double ox = center ? -((double)C - 1) / 2 : 0, oy = center ? -((double)L - 1) / 2 : 0;
    /* Points: L*C corners, (L-1)*(C-1) centres, then the boundary at the
     * floor (indexed by grid position through floor_index). */
    size_t corners = (size_t)L * C, centres = (size_t)(L - 1) * (C - 1);
    size_t boundary = 2 * ((size_t)L + C) - 4;
    size_t npoints = corners + centres + boundary;
    size_t nfaces = 4 * centres + boundary + 1;
    size_t nidx = 12 * centres + 4 * boundary + boundary;
    vec3 *pts = malloc(npoints * sizeof *pts);
    uint32_t *idx = malloc(nidx * sizeof *idx);
    uint32_t *start = malloc((nfaces + 1) * sizeof *start);
    uint32_t *floor_of = malloc(corners * sizeof *floor_of);
    if (!pts || !idx || !start || !floor_of) {
        free(pts);
        free(idx);
        free(start);
        free(floor_of);
        return err_nomem(c->error, loc);
    }
#define V(i, j) g->v[(size_t)(i)*C + (j)]
#define CORNER(i, j) ((uint32_t)((size_t)(i)*C + (j)))
#define CENTRE(i, j) ((uint32_t)(corners + (size_t)((i)-1) * (C - 1) + ((j)-1)))
#define FLOOR(i, j) floor_of[(size_t)(i)*C + (j)]
    for (uint32_t i = 0; i < L; i++)
        for (uint32_t j = 0; j < C; j++)
            pts[CORNER(i, j)] = v3(ox + j, oy + i, V(i, j));
    for (uint32_t i = 1; i < L; i++) {
        for (uint32_t j = 1; j < C; j++) {
            double vx = (V(i - 1, j - 1) + V(i - 1, j) + V(i, j - 1) + V(i, j)) / 4;
            pts[CENTRE(i, j)] = v3(ox + j - 0.5, oy + i - 0.5, vx);
        }
    }
    uint32_t np = (uint32_t)(corners + centres);
    for (uint32_t i = 0; i < L; i++) {
        for (uint32_t j = 0; j < C; j++) {
            if (i == 0 || j == 0 || i == L - 1 || j == C - 1) {
                FLOOR(i, j) = np;
                pts[np++] = v3(ox + j, oy + i, floor_z);
            }
        }
    }
    uint32_t nf = 0, k = 0;
#define FACE_BEGIN() (start[nf++] = k)
#define PUT(x) (idx[k++] = (x))
    for (uint32_t i = 1; i < L; i++) {
        for (uint32_t j = 1; j < C; j++) {
            uint32_t v1 = CORNER(i - 1, j - 1), v2 = CORNER(i - 1, j),
                     v3i = CORNER(i, j - 1), v4 = CORNER(i, j), vx = CENTRE(i, j);
            FACE_BEGIN();
            PUT(v1);
            PUT(v2);
            PUT(vx);
            FACE_BEGIN();
            PUT(v2);
            PUT(v4);
            PUT(vx);
            FACE_BEGIN();
            PUT(v4);
            PUT(v3i);
            PUT(vx);
            FACE_BEGIN();
            PUT(v3i);
            PUT(v1);
            PUT(vx);
        }
    }
    /* Walls; OpenSCAD's insert_vertex reverses a polygon's order. */
    for (uint32_t i = 1; i < L; i++) {
        FACE_BEGIN();
        PUT(FLOOR(i - 1, 0));
        PUT(CORNER(i - 1, 0));
        PUT(CORNER(i, 0));
        PUT(FLOOR(i, 0));
        FACE_BEGIN();
        PUT(FLOOR(i, C - 1));
        PUT(CORNER(i, C - 1));
        PUT(CORNER(i - 1, C - 1));
        PUT(FLOOR(i - 1, C - 1));
    }
    for (uint32_t j = 1; j < C; j++) {
        FACE_BEGIN();
        PUT(FLOOR(0, j));
        PUT(CORNER(0, j));
        PUT(CORNER(0, j - 1));
        PUT(FLOOR(0, j - 1));
        FACE_BEGIN();
        PUT(FLOOR(L - 1, j - 1));
        PUT(CORNER(L - 1, j - 1));
        PUT(CORNER(L - 1, j));
        PUT(FLOOR(L - 1, j));
    }
    /* The floor, reversed as OpenSCAD inserts it. */
    FACE_BEGIN();
    for (uint32_t i = 1; i < L; i++)
        PUT(FLOOR(i, 0));
    for (uint32_t j = 1; j < C; j++)
        PUT(FLOOR(L - 1, j));
    for (uint32_t i = L - 1; i-- > 0;)
        PUT(FLOOR(i, C - 1));
    for (uint32_t j = C - 1; j-- > 0;)
        PUT(FLOOR(0, j));
    start[nf] = k;
#undef V
#undef CORNER
#undef CENTRE
#undef FLOOR
#undef FACE_BEGIN
#undef PUT
    sc_status st = SC_OK;
    if (faces) {
        *faces = (build_mesh_faces){.points = pts,
                                    .point_count = np,
                                    .indices = idx,
                                    .face_start = start,
                                    .face_count = nf};
        pts = NULL;
        idx = start = NULL;
    } else {
        st = build_mesh_prim(c, loc, "surface", 0, pts, np, idx, start, nf, out, empty);
    }
    free(pts);
    free(idx);
    free(start);
    free(floor_of);
    return st;
}

static const char left_out[] =
    "; the surface is empty, as OpenSCAD leaves it out (--strict makes it an error)";
static const char rest_ignored[] = "; the rest of the file is ignored, as OpenSCAD stops "
                                   "reading there (--strict makes it an error)";

/* build_surface, or with faces build_surface_faces. */
static sc_status surface(const build_ctx *c, const model_surface *s, prim *out,
                         const char **empty, build_mesh_faces *faces)
{
    int center = s->center, invert = s->invert;
    sc_location loc = s->file_loc;
    const char *name = s->file;
    char *path = build_file_path(c, name);
    if (!path)
        return err_nomem(c->error, (&loc));
    size_t size = 0;
    const char *why = NULL;
    unsigned char *bytes =
        (unsigned char *)file_read(path, BUILD_SURFACE_MAX_FILE, &size, &why);
    grid g = {NULL, 0, 0, 0};
    sc_status st = SC_OK;
    int stopped = 0;
    if (!bytes && why == file_no_memory)
        st = err_nomem(c->error, &loc);
    else if (!bytes && why == file_too_large) /* our limit, not the file's */
        st = err_set(c->error, SC_ERR_LIMIT, &loc, "surface: cannot read '%s': %s", path,
                     why);
    else if (!bytes)
        st = err_set(c->error, SC_ERR_IO, &loc,
                     "surface: the file '%s' couldn't be opened: %s", path, why);
    else if (is_png(bytes, size))
        st = read_png(c, &loc, path, invert, &g);
    else
        st = read_dat(c, &loc, path, (char *)bytes, size, &g, &stopped);
    free(bytes);
    if (st == SC_OK && stopped == 2) { /* silent, as OpenSCAD is */
        err_clear(c->error);
        stopped = 0;
    }
    if (st == SC_ERR_IO && !c->strict) { /* not opened, or not decoded */
        sc_error reason = *c->error;
        err_clear(c->error);
        st = build_note_left_out(c, &loc, "%s%s", reason.message, left_out);
        *empty = "";
    } else if (st == SC_OK && stopped && c->strict) {
        st = c->error->status;
    } else if (st == SC_OK && stopped) {
        sc_error reason = *c->error;
        err_clear(c->error);
        if (g.lines < 2 || g.columns < 2) {
            /* no area read: left out, with nothing more said of it */
            st = build_note_left_out(c, &loc, "%s%s", reason.message, rest_ignored);
            *empty = "";
        } else {
            st = build_note(c, &loc, "%s%s", reason.message, rest_ignored);
            if (st == SC_OK)
                st = surface_mesh(c, &loc, &g, center, out, empty, faces);
        }
    } else if (st == SC_OK) {
        if (g.lines < 2 || g.columns < 2)
            *empty = "surface without area is empty";
        else
            st = surface_mesh(c, &loc, &g, center, out, empty, faces);
    }
    free(g.v);
    free(path);
    return st;
}

sc_status build_surface(const build_ctx *c, const model_surface *s, prim *out,
                        const char **empty)
{
    return surface(c, s, out, empty, NULL);
}

sc_status build_surface_faces(const build_ctx *c, const model_surface *s,
                              build_mesh_faces *faces, const char **empty)
{
    memset(faces, 0, sizeof *faces);
    return surface(c, s, NULL, empty, faces);
}
