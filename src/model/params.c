/* OpenSCAD 2021.01's parameters of its builtin modules and the warnings
 * of a call's arguments (params.h). */
#include "model/params.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/grow.h"
#include "model/args.h"
#include "model/colors.h"

/* timestamp is not a parameter, but OpenSCAD's export writes it for the
 * modules that read a file; OpenSCAD warns of it when it reads its own
 * export back, which would make every exported model with an import warn
 * of a word the user never wrote. spancast takes it silently. */
static const model_params table[] = {
    {"cube", {"size", "center"}, {NULL}, 1, 0, 0, 3},
    {"sphere", {"r"}, {"d"}, 1, 1, 0, 0},
    {"cylinder", {"h", "r1", "r2", "center"}, {"r", "d", "d1", "d2"}, 1, 3, 0, 0},
    {"polyhedron", {"points", "faces", "convexity"}, {"triangles"}, 1, 0, 0, 0},
    {"square", {"size", "center"}, {NULL}, 1, 0, 0, 2},
    {"circle", {"r"}, {"d"}, 1, 1, 0, 0},
    {"polygon", {"points", "paths", "convexity"}, {NULL}, 1, 0, 0, 0},
    {"text",
     {"text", "size", "font"},
     {"direction", "language", "script", "halign", "valign", "spacing"},
     0,
     0,
     0,
     0},
    {"linear_extrude",
     {"file", "layer", "height", "origin", "scale", "center", "twist", "slices"},
     {"convexity", "timestamp"},
     0,
     0,
     0,
     0},
    {"rotate_extrude",
     {"file", "layer", "origin", "scale"},
     {"convexity", "angle", "timestamp"},
     0,
     0,
     0,
     0},
    {"projection", {"cut"}, {"convexity"}, 0, 0, 0, 0},
    {"offset", {"r"}, {"delta", "chamfer"}, 0, 0, 0, 0},
    {"resize", {"newsize", "auto", "convexity"}, {NULL}, 0, 0, 0, 0},
    {"hull", {NULL}, {NULL}, 0, 0, 0, 0},
    {"minkowski", {"convexity"}, {NULL}, 0, 0, 0, 0},
    {"render", {"convexity"}, {NULL}, 0, 0, 0, 0},
    {"multmatrix", {"m"}, {NULL}, 0, 0, 0, 0},
    {"import",
     {"file", "layer", "convexity", "origin", "scale"},
     {"width", "height", "filename", "center", "dpi", "timestamp"},
     0,
     0,
     0,
     0},
    {"surface", {"file", "center", "convexity"}, {"invert", "timestamp"}, 0, 0, 0, 0},
    {"color", {"c", "alpha"}, {NULL}, 0, 0, 1, 0},
};

const model_params *model_params_of(const char *name)
{
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
        if (table[i].name[0] == name[0] && strcmp(table[i].name, name) == 0)
            return &table[i];
    return NULL;
}

/* Which of $fn, $fa, $fs name is (0, 1, 2), -1 for any other name. */
static int special_index(const char *name)
{
    if (!name || name[0] != '$' || name[1] != 'f' || !name[2] || name[3])
        return -1;
    return name[2] == 'n' ? 0 : name[2] == 'a' ? 1 : name[2] == 's' ? 2 : -1;
}

/* Fills the entries of out still NULL from the $fn, $fa, $fs of n's
 * ancestors (model_special_args). The arguments are scanned before the
 * name is looked up: most ancestors (the multmatrix above every leaf of an
 * export) have none. */
static void inherit_special_args(const parse_node *n, const parse_arg *out[3])
{
    int missing = !out[0] + !out[1] + !out[2];
    for (const parse_node *at = n->parent; at && missing; at = at->parent) {
        const parse_arg *own[3] = {NULL, NULL, NULL}; /* the last of each wins */
        int any = 0;
        for (uint32_t i = 0; i < at->arg_count; i++) {
            int k = special_index(at->args[i].name);
            if (k >= 0) {
                own[k] = &at->args[i];
                any = 1;
            }
        }
        if (!any || !model_params_of(at->name))
            continue;
        for (int k = 0; k < 3; k++)
            if (!out[k] && own[k]) {
                out[k] = own[k];
                missing--;
            }
    }
}

void model_special_args(const parse_node *n, const parse_arg *out[3])
{
    out[0] = out[1] = out[2] = NULL;
    for (uint32_t i = 0; i < n->arg_count; i++) {
        int k = special_index(n->args[i].name);
        if (k >= 0)
            out[k] = &n->args[i];
    }
    inherit_special_args(n, out);
}

void model_resolution_of(const parse_node *n, int clamp, double *fn, double *fa,
                         double *fs)
{
    const parse_arg *a[3];
    model_special_args(n, a);
    double *outs[3] = {fn, fa, fs};
    const double defaults[3] = {0, 12, 2};
    for (int k = 0; k < 3; k++) {
        /* OpenSCAD takes a value that is not a number (undef included) as
         * 0, which a primitive then clamps */
        *outs[k] = !a[k]                              ? defaults[k]
                   : a[k]->value.kind == PARSE_NUMBER ? a[k]->value.u.number
                                                      : 0;
        if (clamp && k > 0 && *outs[k] < MODEL_F_MINIMUM)
            *outs[k] = MODEL_F_MINIMUM;
    }
}

static size_t positional_count(const model_params *p)
{
    size_t k = 0;
    while (k < sizeof p->positional / sizeof p->positional[0] && p->positional[k])
        k++;
    return k;
}

static int listed(const char *const *list, size_t count, const char *name)
{
    for (size_t k = 0; k < count && list[k]; k++)
        if (list[k][0] == name[0] && strcmp(list[k], name) == 0)
            return 1;
    return 0;
}

/* Where a warning of node n about what stands at loc goes: there when it
 * is on the node's line, else at the node. OpenSCAD names the line of the
 * statement, so a call written over several lines gets its line, and one
 * line the column of what is wrong. */
static sc_location at_node_line(const parse_node *n, sc_location loc)
{
    return loc.line == n->loc.line ? loc : n->loc;
}

static sc_status note_at(model_notes *notes, sc_error *error, const char *file,
                         sc_location loc, const char *format, ...) SC_PRINTF(5, 6);

static sc_status note_at(model_notes *notes, sc_error *error, const char *file,
                         sc_location loc, const char *format, ...)
{
    if (!grow_array((void **)&notes->items, &notes->cap, notes->count + 1,
                    sizeof *notes->items))
        return err_nomem(error, NULL);
    char message[SC_ERROR_MESSAGE_MAX];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    sc_location at = {file, loc.line, loc.column};
    err_set(&notes->items[notes->count++], SC_OK, &at, "%s", message);
    return SC_OK;
}

/* The names given so far by name. A parse tree stores each name once
 * (parse.h), so a name's address stands for its text; a call of many
 * arguments is hashed on the address, so that no input makes the check
 * quadratic. */
enum { FEW_ARGS = 16 };

typedef struct seen_names {
    const parse_node *n;
    const char **slots; /* open addressing, cap a power of two; NULL: scan */
    size_t cap;
} seen_names;

static size_t slot_of(const seen_names *s, const char *name)
{
    size_t i = ((uintptr_t)name >> 3) * 0x9e3779b97f4a7c15u & (s->cap - 1);
    while (s->slots[i] && s->slots[i] != name)
        i = (i + 1) & (s->cap - 1);
    return i;
}

/* Whether argument i's name was given by name before it (and remembers
 * it when hashing). */
static int named_before(seen_names *s, uint32_t i)
{
    const char *name = s->n->args[i].name;
    if (!s->slots) {
        for (uint32_t j = 0; j < i; j++)
            if (s->n->args[j].name == name)
                return 1;
        return 0;
    }
    size_t k = slot_of(s, name);
    if (s->slots[k])
        return 1;
    s->slots[k] = name;
    return 0;
}

/* Whether parameter name (the position-th positional one, or < 0: named
 * only) is a number; *arg is the argument that gives it. */
static int number_arg(const parse_node *n, const char *name, int position,
                      const parse_arg **arg)
{
    *arg = parse_node_arg(n, name, position);
    return *arg && (*arg)->value.kind == PARSE_NUMBER;
}

/* OpenSCAD's lookup_radius: the diameter wins, with a warning at the
 * radius when both are numbers. Sets *given when either is a number. */
static sc_status radius(const char *file, const parse_node *n, const char *diameter,
                        const char *name, int position, model_notes *notes,
                        sc_error *error, int *given)
{
    const parse_arg *d, *r;
    int has_d = number_arg(n, diameter, -1, &d),
        has_r = number_arg(n, name, position, &r);
    *given = has_d || has_r;
    if (!has_d || !has_r)
        return SC_OK;
    return note_at(notes, error, file, at_node_line(n, r->loc),
                   "Ignoring radius variable '%s' as diameter '%s' is defined too.", name,
                   diameter);
}

/* What the scan of a call's arguments found for a primitive's checks. */
typedef struct scanned {
    const parse_arg *special[3]; /* its own $fn, $fa, $fs (the last of each) */
    int diameter;                /* some d, d1 or d2 is given by name */
    int radius;                  /* r is given by name */
} scanned;

/* The warning of a size that is neither a number nor a vector of
 * p->size numbers (model_params.size). */
static sc_status check_size(const char *file, const parse_node *n, const model_params *p,
                            model_notes *notes, sc_error *error)
{
    const parse_value *v = model_arg(n, "size", 0);
    double unused[3];
    if (!v || model_size_value(v, p->size, unused))
        return SC_OK;
    char text[MODEL_ECHO_MAX + 1];
    model_echo_into(text, v);
    sc_location at = {file, v->line, v->column};
    return note_at(notes, error, file, at_node_line(n, at),
                   "Unable to convert %s(size=%s, ...) parameter to a number or a vec%d "
                   "of numbers",
                   n->name, text, (int)p->size);
}

/* The warnings of a primitive's instantiation after its arguments'. The
 * radii are looked up only where a diameter or r is given, which
 * OpenSCAD's export never writes with another radius. */
static sc_status check_primitive(const char *file, const parse_node *n,
                                 const model_params *p, scanned *a, model_notes *notes,
                                 sc_error *error)
{
    inherit_special_args(n, a->special);
    sc_status st = SC_OK;
    for (int k = 2; k >= 1 && st == SC_OK; k--) {
        const parse_arg *s = a->special[k];
        if (s && (s->value.kind != PARSE_NUMBER || s->value.u.number < MODEL_F_MINIMUM))
            st = note_at(notes, error, file, n->loc, "%s too small - clamping to %f",
                         k == 2 ? "$fs" : "$fa", MODEL_F_MINIMUM);
    }
    if (st == SC_OK && p->size)
        st = check_size(file, n, p, notes, error);
    if (!p->radii || (!a->diameter && !(a->radius && p->radii == 3)))
        return st;
    int r = 0, r1 = 0, r2 = 0;
    if (st == SC_OK)
        st = radius(file, n, "d", "r", p->radii == 1 ? 0 : -1, notes, error, &r);
    if (st == SC_OK && p->radii == 3)
        st = radius(file, n, "d1", "r1", 1, notes, error, &r1);
    if (st == SC_OK && p->radii == 3)
        st = radius(file, n, "d2", "r2", 2, notes, error, &r2);
    if (st == SC_OK && r && (r1 || r2))
        st = note_at(notes, error, file, n->loc, "Cylinder parameters ambiguous");
    return st;
}

enum { MEMO_NAMES = sizeof((model_params_memo *)0)->names / sizeof(const char *) };

/* Whether n's call has the names memo remembers for p; fills *found. */
static int memo_matches(const model_params_memo *memo, const model_params *p,
                        const parse_node *n, scanned *found)
{
    if (memo->p != p || memo->count != n->arg_count)
        return 0;
    for (uint32_t i = 0; i < n->arg_count; i++)
        if (memo->names[i] != n->args[i].name)
            return 0;
    for (int k = 0; k < 3; k++)
        found->special[k] = memo->special[k] >= 0 ? &n->args[memo->special[k]] : NULL;
    found->diameter = memo->diameter;
    found->radius = memo->radius;
    return 1;
}

static void memo_keep(model_params_memo *memo, const model_params *p, const parse_node *n,
                      const scanned *found)
{
    if (n->arg_count > MEMO_NAMES)
        return;
    memo->p = p;
    memo->count = n->arg_count;
    for (uint32_t i = 0; i < n->arg_count; i++)
        memo->names[i] = n->args[i].name;
    for (int k = 0; k < 3; k++)
        memo->special[k] =
            (signed char)(found->special[k] ? found->special[k] - n->args : -1);
    memo->diameter = (unsigned char)found->diameter;
    memo->radius = (unsigned char)found->radius;
}

/* Whether c is [-1, -1, -1, ...], what OpenSCAD's export writes for a
 * colour it could not parse (its "no colour"). OpenSCAD warns of the three
 * components when it reads its export back, after its warning of the name
 * when it made it: spancast takes the export's marker silently, as it
 * takes timestamp, so that a .scad converted through OpenSCAD warns once. */
static int exported_no_color(const parse_value *c)
{
    if (c->u.vector.count < 3)
        return 0;
    for (int i = 0; i < 3; i++) {
        const parse_value *item = &c->u.vector.items[i];
        if (item->kind != PARSE_NUMBER || item->u.number != -1)
            return 0;
    }
    return 1;
}

/* color()'s warnings (model_params.color). */
static sc_status check_color(const char *file, const parse_node *n, model_notes *notes,
                             sc_error *error)
{
    const parse_arg *a = parse_node_arg(n, "c", 0);
    if (!a)
        return SC_OK;
    const parse_value *v = &a->value;
    if (v->kind == PARSE_STRING) {
        float rgba[4];
        if (colors_lookup(v->u.string.chars, v->u.string.length, rgba))
            return SC_OK;
        /* OpenSCAD names it in lower case, as it looked it up */
        char name[128];
        size_t k = 0;
        for (; k + 1 < sizeof name && v->u.string.chars[k]; k++)
            name[k] = (char)tolower((unsigned char)v->u.string.chars[k]);
        name[k] = '\0';
        sc_location at = {file, v->line, v->column};
        return note_at(notes, error, file, at_node_line(n, at),
                       "Unable to parse color \"%s%s\"", name,
                       v->u.string.chars[k] ? "..." : "");
    }
    if (v->kind != PARSE_VECTOR || exported_no_color(v))
        return SC_OK;
    for (uint32_t i = 0; i < v->u.vector.count && i < 4; i++) {
        const parse_value *item = &v->u.vector.items[i];
        /* as OpenSCAD holds it: a float */
        float c = item->kind == PARSE_NUMBER ? (float)item->u.number : 0;
        if (!(c > 1 || c < 0))
            continue;
        sc_location at = {file, item->line, item->column};
        sc_status st = note_at(notes, error, file, at_node_line(n, at),
                               "color() expects numbers between 0.0 and 1.0. Value of "
                               "%.1f is out of range",
                               (double)c);
        if (st != SC_OK)
            return st;
    }
    return SC_OK;
}

/* "NAME(..., ARG=VALUE) could not be converted", at the argument a (the
 * node when it is absent: VALUE is then undef). */
static sc_status not_converted(const char *file, const parse_node *n, const char *name,
                               const char *arg, const parse_arg *a, model_notes *notes,
                               sc_error *error)
{
    static const parse_value undef = {.kind = PARSE_UNDEF};
    char text[MODEL_ECHO_MAX + 1];
    model_echo_into(text, a ? &a->value : &undef);
    sc_location at = a ? (sc_location){file, a->value.line, a->value.column} : n->loc;
    return note_at(notes, error, file, at_node_line(n, at),
                   "%s(..., %s=%s) could not be converted", name, arg, text);
}

/* The origin of import and the extrusions, given (not undef): one that is
 * not [x, y] of numbers is [0, 0], with OpenSCAD 2021.01's warning, which
 * names linear_extrude for import too; then linear_extrude's warning of a
 * scale that is neither a number nor [x, y] of numbers, which OpenSCAD
 * gives whenever an origin is given (undef too: no scale). */
static sc_status check_origin(const char *file, const parse_node *n, model_notes *notes,
                              sc_error *error)
{
    int import = strcmp(n->name, "import") == 0;
    int linear = !import && strcmp(n->name, "linear_extrude") == 0;
    if (!import && !linear && strcmp(n->name, "rotate_extrude") != 0)
        return SC_OK;
    const parse_value *origin = model_arg(n, "origin", -1);
    if (!origin)
        return SC_OK;
    double xy[2];
    sc_status st = SC_OK;
    if (!(origin->kind == PARSE_VECTOR && model_size_value(origin, 2, xy) &&
          isfinite(xy[0]) && isfinite(xy[1])))
        st = not_converted(file, n, import ? "linear_extrude" : n->name, "origin",
                           parse_node_arg(n, "origin", -1), notes, error);
    const parse_value *scale = model_arg(n, "scale", -1);
    if (st == SC_OK && linear && !(scale && model_size_value(scale, 2, xy)))
        st = not_converted(file, n, n->name, "scale", parse_node_arg(n, "scale", -1),
                           notes, error);
    return st;
}

/* The warnings after those of the arguments' names. */
/* polyhedron(triangles = ...) without faces: OpenSCAD 2021.01 reads the
 * faces from it, with its deprecation note (at no position; here at the
 * node). */
static sc_status check_triangles(const char *file, const parse_node *n,
                                 model_notes *notes, sc_error *error)
{
    int faces = 0, triangles = 0, unnamed = 0;
    for (uint32_t i = 0; i < n->arg_count; i++) {
        const char *name = n->args[i].name;
        unnamed += !name;
        faces |= name && !strcmp(name, "faces");
        triangles |= name && !strcmp(name, "triangles");
    }
    if (!triangles || faces || unnamed >= 2)
        return SC_OK;
    return note_at(notes, error, file, n->loc,
                   "polyhedron(triangles=[]) will be removed in future releases. Use "
                   "polyhedron(faces=[]) instead.");
}

static sc_status check_values(const char *file, const parse_node *n,
                              const model_params *p, scanned *found, model_notes *notes,
                              sc_error *error)
{
    if (!strcmp(p->name, "polyhedron")) {
        sc_status st = check_triangles(file, n, notes, error);
        if (st != SC_OK)
            return st;
    }
    if (p->primitive)
        return check_primitive(file, n, p, found, notes, error);
    if (p->color)
        return check_color(file, n, notes, error);
    return check_origin(file, n, notes, error);
}

sc_status model_check_params(const char *file, const parse_node *n, const model_params *p,
                             model_params_memo *memo, model_notes *notes, sc_error *error)
{
    scanned found = {{NULL, NULL, NULL}, 0, 0};
    if (memo_matches(memo, p, n, &found))
        return check_values(file, n, p, &found, notes, error);
    seen_names seen = {n, NULL, 0};
    if (n->arg_count > FEW_ARGS) {
        seen.cap = 2 * FEW_ARGS;
        while (seen.cap < 2 * (size_t)n->arg_count)
            seen.cap *= 2;
        seen.slots = calloc(seen.cap, sizeof *seen.slots);
        if (!seen.slots)
            return err_nomem(error, NULL);
    }
    size_t positional = positional_count(p), taken = 0;
    int too_many = 0;
    size_t before = notes->count;
    sc_status st = SC_OK;
    for (uint32_t i = 0; i < n->arg_count && st == SC_OK; i++) {
        const parse_arg *a = &n->args[i];
        const char *name = a->name;
        if (!name) {
            if (taken < positional)
                taken++;
            else if (!too_many) {
                too_many = 1;
                st = note_at(notes, error, file, at_node_line(n, a->loc),
                             "Too many unnamed arguments supplied");
            }
            continue;
        }
        int k = special_index(name);
        if (k >= 0) {
            found.special[k] = a;
        } else if (name[0] != '$') {
            if (!listed(p->positional, positional, name) &&
                !listed(p->named, sizeof p->named / sizeof p->named[0], name))
                st = note_at(notes, error, file, at_node_line(n, a->loc),
                             "variable %s not specified as parameter", name);
            found.diameter |= name[0] == 'd';
            found.radius |= name[0] == 'r' && !name[1];
        }
        int twice = named_before(&seen, i) || listed(p->positional, taken, name);
        if (st == SC_OK && twice)
            st = note_at(notes, error, file, at_node_line(n, a->loc),
                         "argument %s supplied more than once", name);
    }
    free(seen.slots);
    if (st == SC_OK && notes->count == before)
        memo_keep(memo, p, n, &found);
    if (st == SC_OK)
        st = check_values(file, n, p, &found, notes, error);
    return st;
}

sc_status model_note_unknown(const char *file, const parse_node *n, model_notes *notes,
                             sc_error *error)
{
    return note_at(notes, error, file, n->loc, "Ignoring unknown module '%s'", n->name);
}

sc_status model_note_children(const char *file, const parse_node *n, model_notes *notes,
                              size_t at, sc_error *error)
{
    sc_status st = note_at(notes, error, file, n->loc,
                           "module %s() does not support child modules", n->name);
    if (st != SC_OK)
        return st;
    sc_error note = notes->items[notes->count - 1];
    memmove(&notes->items[at + 1], &notes->items[at],
            (notes->count - 1 - at) * sizeof *notes->items);
    notes->items[at] = note;
    return SC_OK;
}
