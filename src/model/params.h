/* OpenSCAD 2021.01's parameters of its builtin modules, and the warnings it
 * gives of a call's arguments when it instantiates the call, before it
 * evaluates any geometry:
 *
 *   variable centre not specified as parameter    a named argument that is
 *                                                 none of the module's
 *                                                 parameters ($ names are
 *                                                 never warned of)
 *   argument size supplied more than once         a named argument whose
 *                                                 name an earlier argument
 *                                                 gave, by name or by
 *                                                 position
 *   Too many unnamed arguments supplied           the first positional
 *                                                 argument past the
 *                                                 module's positional
 *                                                 parameters (once a call)
 *
 * in the order of the arguments (EvalContext::resolveArguments). group,
 * union, difference and intersection read no arguments and warn of none;
 * spancast's own nodes check theirs where they are lowered. The lists were
 * read off OpenSCAD 2021.01 itself (openscad -o x.csg on calls with each
 * name and with more and more positional arguments); tests/cli_lenient.sh
 * compares the warnings with OpenSCAD's.
 */
#ifndef SPANCAST_MODEL_PARAMS_H
#define SPANCAST_MODEL_PARAMS_H

#include <stddef.h>
#include <stdint.h>

#include "spancast/spancast.h"
#include "syntax/parse.h"

/* A module's parameters: those a positional argument takes, in order,
 * then those given only by name; each list ends at the first NULL. */
typedef struct model_params {
    const char *name;
    const char *positional[9];
    const char *named[7];
    /* one of OpenSCAD's primitives (PrimitiveModule): $fs and $fa below
     * 0.01 are clamped to 0.01, with a warning */
    unsigned char primitive;
    /* the radii it looks up by diameter or radius: 1 for r (d), 3 for a
     * cylinder's r, r1 and r2 (d, d1, d2) */
    unsigned char radii;
    /* color(): "color() expects numbers between 0.0 and 1.0. Value of 1.2
     * is out of range" for each component of c (alpha aside) outside 0..1,
     * at the component, and "Unable to parse color "x"" at a name it does
     * not know */
    unsigned char color;
    /* cube (3) and square (2): "Unable to convert cube(size=[1, 2], ...)
     * parameter to a number or a vec3 of numbers" (vec2 for square) for a
     * size that is neither (model_size_value; undef is no size), at it */
    unsigned char size;
} model_params;

/* The parameters of OpenSCAD's builtin module name; NULL for a node that
 * warns of no argument. */
const model_params *model_params_of(const char *name);

/* The smallest $fs and $fa OpenSCAD's primitives take (its F_MINIMUM). */
#define MODEL_F_MINIMUM 0.01

/* The arguments that give node n its $fn, $fa and $fs (out[0], [1], [2]),
 * as OpenSCAD 2021.01 looks them up: n's own (the last of each), else the
 * nearest ancestor's that passes its $ arguments on to its children (every
 * builtin module with parameters does; group, union, difference and
 * intersection do not, nor do spancast's own nodes, so they are skipped),
 * NULL where none gives it (the default: 0, 12, 2). OpenSCAD's export
 * writes all three on every node that uses them, so this matters only for
 * a hand-written file (`multmatrix(m, $fn = 6) sphere(1);`). The ancestors
 * are read through parent links, which a streamed parse keeps while a
 * node is open (parse.h). */
void model_special_args(const parse_node *n, const parse_arg *out[3]);

/* n's $fn, $fa and $fs (model_special_args; an argument that is not a
 * number, undef included, is 0 as OpenSCAD takes it, none the default),
 * $fa and $fs clamped to MODEL_F_MINIMUM when clamp is set (OpenSCAD's
 * primitives). */
void model_resolution_of(const parse_node *n, int clamp, double *fn, double *fa,
                         double *fs);

/* Warnings, in file order; items grow as they come (free them). */
typedef struct model_notes {
    sc_error *items;
    size_t count, cap;
} model_notes;

/* The last call of a module whose argument names raised no warning: a
 * call of the same module with the same names in the same order (a parse
 * tree stores each name once, so their addresses are compared) raises
 * none either, and only its values are checked again (a million spheres
 * of an export are one check of their names). Zero it to start; one per
 * module, or reset when the module changes. */
typedef struct model_params_memo {
    const model_params *p; /* NULL: empty */
    uint32_t count;
    const char *names[8];
    signed char special[3]; /* the index of the last $fn, $fa, $fs, or -1 */
    unsigned char diameter, radius;
} model_params_memo;

/* Adds to notes OpenSCAD's warnings of node n's arguments against p (see
 * above), each at its argument in file, then, as OpenSCAD goes on to
 * instantiate a primitive, "$fs too small - clamping to 0.010000" (and
 * $fa; at the node), "Ignoring radius variable 'r' as diameter 'd' is
 * defined too." (at r, for each pair a sphere, circle or cylinder looks
 * up, when both are numbers) and, for a cylinder given r and r1 or r2
 * (by radius or diameter), "Cylinder parameters ambiguous" (at the node);
 * the size warning of cube and square (model_params.size); for import,
 * linear_extrude and rotate_extrude, an origin that is not [x, y] of
 * finite numbers: "linear_extrude(..., origin=\"a\") could not be converted"
 * (OpenSCAD's text, linear_extrude for import too), at it, and for
 * linear_extrude with an origin, a scale that is neither a number nor
 * [x, y] of numbers, absent included ("linear_extrude(..., scale=undef)
 * could not be converted"). A $fs or $fa
 * that is not a number (undef too) is 0 to OpenSCAD, so it is clamped
 * with the warning as well.
 * Fails only when memory runs out (SC_ERR_NOMEM in error). */
sc_status model_check_params(const char *file, const parse_node *n, const model_params *p,
                             model_params_memo *memo, model_notes *notes,
                             sc_error *error);

/* OpenSCAD's warning that n names no module it knows ("Ignoring unknown
 * module 'foo'", at the node), which it leaves out with its children,
 * never instantiated. Fails only when memory runs out. */
sc_status model_note_unknown(const char *file, const parse_node *n, model_notes *notes,
                             sc_error *error);

/* OpenSCAD's warning that primitive n (p->primitive) has children, which
 * it ignores without instantiating them ("module cube() does not support
 * child modules", at the node), inserted in notes at index at: OpenSCAD
 * gives it before the node's other warnings, and a streamed lowering
 * learns of the children only after it has checked the arguments. The
 * caller tells that n has children other than '*' ones (those are never
 * read). Fails only when memory runs out. */
sc_status model_note_children(const char *file, const parse_node *n, model_notes *notes,
                              size_t at, sc_error *error);

#endif
