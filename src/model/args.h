/* Readers of a syntax node's arguments, shared by the lowering pass and
 * the builders that still read their own node: each finds an argument by
 * name or position (the last one given wins, as in OpenSCAD). An argument
 * of OpenSCAD's builtin modules of the wrong kind is read as OpenSCAD
 * 2021.01 reads it, as the parameter's default, without an error (the
 * warnings OpenSCAD gives of some are model_check_params'); spancast's
 * own nodes report an error at the value with the message the corpus in
 * tests/bad-input expects ("wrong type for argument 'r1' of 'torus'
 * (expected ...)", model_wrong_type).
 */
#ifndef SPANCAST_MODEL_ARGS_H
#define SPANCAST_MODEL_ARGS_H

#include <stdint.h>

#include "model/model.h"
#include "spancast/spancast.h"
#include "syntax/parse.h"

/* Where positions point and errors go. */
typedef struct model_reader {
    const char *file;
    sc_error *error;
} model_reader;

/* One lowering pass over a context below the top (lower_points.c,
 * lower_twod.c): the model's arena, the reader, and whether an allocation
 * failed. */
typedef struct model_lowerer {
    arena *mem;
    model_reader r; /* its error is the pending error being made */
    int nomem;
} model_lowerer;

/* size zeroed bytes (at least one) from l's arena, owned by the model; NULL,
 * with l->nomem set, when out of memory. */
void *model_lowerer_alloc(model_lowerer *l, size_t size);

/* The value of the named or position-th positional argument; NULL when it
 * is absent or undef. */
const parse_value *model_arg(const parse_node *n, const char *name, int position);
/* A value's position. */
sc_location model_loc(const model_reader *r, const parse_value *v);
/* The error for argument param of n having the wrong type. */
sc_status model_wrong_type(const model_reader *r, const parse_node *n, const char *param,
                           const parse_value *v, const char *expected);
/* A number argument into *out (left alone when absent or not a number, as
 * OpenSCAD takes it). Never fails. */
sc_status model_number(const model_reader *r, const parse_node *n, const char *name,
                       int position, double *out);
/* OpenSCAD's radius lookup: the diameter (named only) wins over the
 * radius, halved; one that is not a number is not given; *given says
 * either was given; *out is left alone when neither is. Never fails. */
sc_status model_radius(const model_reader *r, const parse_node *n, const char *diameter,
                       const char *radius, int radius_position, double *out, int *given);
/* A true/false argument into *out (left alone when absent or not true or
 * false: OpenSCAD's center is true only when it is true). Never fails. */
sc_status model_bool(const model_reader *r, const parse_node *n, const char *name,
                     int position, int *out);
/* sphere(r = 1 | d, $fn, $fa, $fs)'s arguments ($fn, $fa, $fs as
 * model_resolution_of reads them, clamped as for every primitive). */
sc_status model_read_sphere(const model_reader *r, const parse_node *n, double *radius,
                            model_resolution *res);
/* cylinder(h = 1, r1 = 1, r2 = 1, center = false, $fn, $fa, $fs), also with
 * r, d, d1, d2: r1/d1 and r2/d2 win over r/d, a diameter over a radius. */
sc_status model_read_cylinder(const model_reader *r, const parse_node *n, double *h,
                              double *r1, double *r2, int *center, model_resolution *res);
/* multmatrix(m), row-major, as OpenSCAD 2021.01 reads it (transform.cc),
 * without a word: the identity, each entry m has as a number replacing the
 * identity's (missing rows and columns, extra ones, and entries that are
 * not numbers leave it; m not a vector, or none, is the identity), then
 * all of it divided by the bottom right entry when that is not 1; the
 * rest of the bottom row is then dropped (the affine part is rows 0 to
 * 2). An entry that is nan or inf after the division (what OpenSCAD
 * writes for 0/0 and 1/0; a bottom right 0) sets *not_finite: OpenSCAD
 * removes such a multmatrix's subtree (model.h). Never fails. */
sc_status model_matrix(const model_reader *r, const parse_node *n, double m[4][4],
                       int *not_finite);
/* multmatrix(m) as model_matrix reads it, its 3x4 affine part allocated
 * from mem into *out: the zero map when an entry is not finite (1 in
 * *not_finite). */
sc_status model_read_xform(const model_reader *r, arena *mem, const parse_node *n,
                           const affine **out, int *not_finite);
/* The end of a nested node's lowering (model.h): status st of reading its
 * arguments, with the error in *pending, kept in out->pending (allocated
 * from mem); SC_OK, or SC_ERR_NOMEM in *error when memory ran out (nomem
 * set, or st says so). */
sc_status model_keep_pending(arena *mem, sc_status st, int nomem, const sc_error *pending,
                             model_node *out, sc_error *error);
/* polyhedron(points, faces | triangles)'s arguments into out->u.polyhedron
 * (allocated from mem), as OpenSCAD 2021.01 reads them (primitives.cc):
 * points that are not a vector are none, faces that are not a vector none,
 * and a face that is not a vector an empty one; each index a number,
 * truncated toward zero (model_index_value), one out of range left out of
 * its face and listed in bad (the builders warn of it); a point is read
 * where a face reads it, [x, y] as [x, y, 0], and the first that is not
 * [x, y, z] of finite numbers ends the faces there (bad_point: the face
 * it is in keeps the indices before it); then a face of fewer than
 * min_points points is left out (OpenSCAD's triangulation drops it).
 * Fails only when memory runs out (SC_ERR_NOMEM in r->error). */
sc_status model_read_polyhedron(const model_reader *r, arena *mem, const parse_node *n,
                                uint32_t min_points, model_node *out);
/* The longest text of model_echo_value, "..." included. */
#define MODEL_ECHO_MAX 200
/* Value v as OpenSCAD 2021.01 echoes it in a message (Value::toEchoString:
 * numbers with 6 significant digits, "1e+6", strings quoted as they are,
 * vectors "[a, b]"), cut to MODEL_ECHO_MAX bytes ending in "...";
 * allocated from mem, NULL when memory runs out. */
const char *model_echo_value(arena *mem, const parse_value *v);
/* The same text in buf; returns its length. */
size_t model_echo_into(char buf[MODEL_ECHO_MAX + 1], const parse_value *v);
/* A point index v of a polygon's path or a polyhedron's face, as OpenSCAD
 * 2021.01 converts it (Value::toDouble, then an unsigned integer): a number
 * truncated toward zero, anything else 0. */
double model_index_value(const parse_value *v);
/* Whether v is a size of dims numbers as OpenSCAD 2021.01 takes it: a
 * number (each of them) or a vector of exactly dims numbers, then in out;
 * else out is left alone. */
int model_size_value(const parse_value *v, uint32_t dims, double *out);
/* cube(size = s | [x, y, z], center = false)'s arguments, as OpenSCAD
 * 2021.01 reads them: a size of another kind is 1 (model_check_params
 * warns of it), a center that is not true or false false. */
sc_status model_cube(const model_reader *r, const parse_node *n, double size[3],
                     int *center);
/* square(size = s | [x, y], center = false)'s arguments, read as cube's. */
sc_status model_read_square(const model_reader *r, const parse_node *n, double *sx,
                            double *sy, int *center);
/* Whether import(file) names a drawing: a string ending in .dxf or .svg
 * (any case), which OpenSCAD imports as 2D wherever it stands. */
int model_import_is_drawing(const parse_node *n);
/* The mesh format a file name's extension (any case) makes. */
model_mesh_format model_mesh_format_of(const char *name);
/* A file name or layer v as OpenSCAD 2021.01 takes it (Value::toString):
 * a string's characters, any other value as model_echo_value writes it
 * ("5", "[1, \"a\"]"), allocated from mem (NULL when memory runs out). */
const char *model_string_value(arena *mem, const parse_value *v);
/* import(file = "x.stl" | "x.off" | "x.amf" | "x.3mf") of a mesh into *out
 * (a file that is not a string as model_string_value names it, allocated
 * from mem); any other extension is MODEL_MESH_UNSUPPORTED, for the
 * builder to warn of as OpenSCAD does. */
sc_status model_read_import(const model_reader *r, arena *mem, const parse_node *n,
                            model_import *out);
/* surface(file, center = false, invert = false) into *out, as OpenSCAD
 * 2021.01 reads them: the file as model_string_value names it (from mem),
 * center and invert true only when they are true. */
sc_status model_read_surface(const model_reader *r, arena *mem, const parse_node *n,
                             model_surface *out);
/* $fn, $fa, $fs of a 2D shape or an extrusion, each the node's where it
 * gives it, else an ancestor's as OpenSCAD passes it down
 * (model_special_args), 0 where that is not a number; else OpenSCAD's
 * defaults 0, 12, 2 (model_resolution_of, unclamped). Never fails. */
sc_status model_read_resolution(const model_reader *r, const parse_node *n, double *fn,
                                double *fa, double *fs);
/* circle(r = 1 | d, $fn, $fa, $fs)'s arguments, in that order (model.h). */
sc_status model_read_circle(const model_reader *r, const parse_node *n,
                            model_circle *out);
/* Does s end in suffix (lower case), ignoring the case of s? */
int model_has_suffix(const char *s, const char *suffix);

#endif
