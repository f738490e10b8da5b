/* What every builder of src/build/ shares: the build context (the file
 * for positions, the CSG builder that owns what leaves allocate, where
 * errors and a warning go, faithful mode); and, for the builders of the
 * 2D and points contexts (model.h), a node's pending argument error and
 * the 2D part of a multmatrix.
 */
#ifndef SPANCAST_BUILD_BUILD_CTX_H
#define SPANCAST_BUILD_BUILD_CTX_H

#include <stdarg.h>

#include "base/error.h"
#include "csg/csg.h"
#include "model/model.h"
#include "spancast/spancast.h"

/* Warnings at their positions, in the order they were given (message and
 * location; status SC_OK). */
typedef struct build_notes {
    sc_error *items;
    size_t count, cap;
    /* imports left out with a warning (a file that cannot be opened or
     * read), so far: an empty result that follows one is not warned of
     * again, as OpenSCAD prints only the import's warning */
    size_t left_out;
} build_notes;

/* The files a build's imports read, by import (its node, or the copy a
 * resize's measure walks: build_mesh.c): each file read and parsed once,
 * and each of its objects merged once for both modes, however many
 * builders take the import (a hull's or minkowski's check that it is
 * closed, then its leaf, then CGAL's faces; resize's measure, then the
 * leaf), and its triangles charged to the budget once (triangles_left).
 * The leaf built where an import stands lets its file go, and so does a
 * hull, minkowski or CGAL solid for the imports below it, once built
 * (build_imports_done). Zeroed to start; freed with build_imports_free
 * (build_mesh.h). */
typedef struct build_imports {
    struct build_import_file *items; /* open addressing on the import's address */
    size_t count, cap;               /* cap is 0 or a power of two */
    size_t merges; /* meshes merged so far (each object of a file is one) */
} build_imports;

typedef struct build_ctx {
    const char *file; /* for positions */
    csg_builder *csg; /* owner of the bytecode */
    sc_error *error;
    int faithful; /* --faithful: OpenSCAD's polygons and polyhedra */
    /* where a builder may leave one warning (a font fallback), or NULL */
    sc_error *note;
    /* where the warnings of a subtree's walk go (a 3D child a 2D operation
     * ignores), or NULL where the subtree is only checked, not built */
    build_notes *notes;
    /* --strict: a mesh a builder makes that is not closed is an error, not a
     * warning (build_mesh_prim) */
    int strict;
    /* the model is a mesh file's one-line import (BUILD_MESH_MODEL): a
     * file that an import in a model leaves out with a warning, as
     * OpenSCAD imports nothing from it, is the error */
    int mesh_model;
    /* the leaf's mesh reaches no CGAL operation in OpenSCAD's render (it
     * draws the mesh as it is), or reaches it convex (CGAL hulls it): one
     * that is not closed is drawn by the parity rule in faithful mode too,
     * not left out, and one closed as built is not checked again on
     * OpenSCAD's grid (build_mesh_prim) */
    int drawn_as_is;
    /* the triangles the load's meshes may still have, of max_triangles
     * (sc_load_options.max_triangles), shared by every context of a load;
     * NULL: no budget. An import's are charged once per import statement,
     * by the first builder that takes them (imports records it), a
     * polyhedron's at most once, by its leaf (a hull takes its points) */
    size_t *triangles_left;
    size_t max_triangles;
    /* the load's files read so far, shared by every context of a load;
     * NULL: an import reads its file wherever it is built */
    build_imports *imports;
    /* the load's CGAL solids by subtree (build_nef_cache.h), shared by
     * every context of a load; NULL: each is evaluated where it occurs */
    struct build_nef_cache *nefs;
    /* where an import's points have moved to before OpenSCAD takes its
     * mesh (build_mesh_merge_moved): the import's builders read them so;
     * NULL: as written */
    const affine *moved;
} build_ctx;

/* Charges count mesh triangles that what (a node's name) is about to build
 * to c's budget: SC_OK while they fit, else the SC_ERR_LIMIT error at loc
 * "what: too many mesh triangles (N more, past the limit of M in one
 * model)". Called before the mesh is checked or indexed, so that the work
 * of one load stays within the budget and one node's faces. */
sc_status build_charge_triangles(const build_ctx *c, const sc_location *loc,
                                 const char *what, size_t count);

/* The same check for at least count triangles, before they are made,
 * without charging them: "what: too many mesh triangles (at least N more,
 * ...)". For a builder that knows a lower bound of its mesh before it
 * makes the faces (linear_extrude's side faces). */
sc_status build_check_triangles(const build_ctx *c, const sc_location *loc,
                                const char *what, size_t count);

/* Adds the warning format/args at loc to notes (nothing when it comes out
 * empty); fails only when memory runs out (an error in *error). */
sc_status build_notes_add(build_notes *notes, sc_error *error, const sc_location *loc,
                          const char *format, va_list args) SC_PRINTF(4, 0);

/* A place in c->notes, to go back to (build_notes_rewind) when a builder
 * drops what it read to read it again another way. */
typedef struct build_notes_place {
    size_t count, left_out;
} build_notes_place;

build_notes_place build_notes_here(const build_ctx *c);
void build_notes_rewind(const build_ctx *c, build_notes_place at);

/* Adds a warning at loc to c->notes (nothing when that is NULL); fails
 * only when memory runs out (an error in c->error). */
sc_status build_note(const build_ctx *c, const sc_location *loc, const char *format, ...)
    SC_PRINTF(3, 4);

/* build_note for an import left out (a file that cannot be opened or
 * read), counted in c->notes->left_out. */
sc_status build_note_left_out(const build_ctx *c, const sc_location *loc,
                              const char *format, ...) SC_PRINTF(3, 4);

/* A file at path that does not open (errno's reason in why), read as
 * "what" ("import", "DXF", "SVG"): OpenSCAD 2021.01 (import.cc) logs
 * "Can't open ... file" and imports nothing, and so does this, with the
 * warning, counted as left out; with --strict (c->strict) the error
 * SC_ERR_IO. */
sc_status build_file_not_opened(const build_ctx *c, const sc_location *loc,
                                const char *what, const char *path, const char *why);

/* The point indices out of range of a polyhedron's faces or a polygon's
 * paths n (model.h, bad), met where it is built: OpenSCAD 2021.01's
 * warning for each, "Point index 7 is out of bounds (from faces[3][3])"
 * (or paths[...]), as it leaves the index out; then the point it could
 * not convert (bad_point), with its error "Unable to convert points[3] =
 * [0, 0, "a"] to a vec3 of numbers" as a warning, as it renders the rest;
 * with --strict the first of them is the error. Each counts as left out
 * (c->notes->left_out). SC_OK for any other node. */
sc_status build_bad_indices(const build_ctx *c, const model_node *n);

/* A multmatrix n with a nan or inf entry (model.h, not_finite), met where
 * it is built (c->notes set): with --strict the error, else OpenSCAD
 * 2021.01's warning, as it removes the subtree; its matrix is the zero
 * map, which every walk takes as no geometry. SC_OK for any other node,
 * and where the subtree is only checked. */
sc_status build_xform_not_finite(const build_ctx *c, const model_node *n);
/* OpenSCAD 2021.01's warning for a transform (or resize) of 2D geometry
 * whose xy part is singular, which removes it (Polygon2d::transform):
 * "Scaling a 2D object with 0 - removing object", at n (c->notes set). */
sc_status build_xform_flat_2d(const build_ctx *c, const model_node *n);

/* OpenSCAD 2021.01's warnings for a child at loc of the other dimension,
 * which its operation leaves out (GeometryEvaluator.cc: isValidDim,
 * collectChildren2D and collectChildren3D): "Mixing 2D and 3D objects is
 * not supported" (build_mixing) and "Ignoring 3D child object for 2D
 * operation" (build_ignoring; in_2d: the operation is 2D, else "2D ... for
 * 3D"), where it is built (c->notes set); with --strict each is the error
 * "3D child object in a 2D operation" (or 2D in 3D), so that the first
 * warning the walk would give is the error. */
sc_status build_mixing(const build_ctx *c, const sc_location *loc, int in_2d);
sc_status build_ignoring(const build_ctx *c, const sc_location *loc, int in_2d);

/* A nested node's argument error, kept by the lowering (model.h, pending):
 * copied into c->error, its status returned. */
sc_status build_pending(const build_ctx *c, const model_node *n);

/* The 2D part of a multmatrix a (the model's): inner = outer after its xy
 * part (x' = m00 x + m01 y + m03, y' = m10 x + m11 y + m13; z is dropped,
 * as OpenSCAD flattens 2D children). Maps are rows [a b tx; c d ty];
 * inner may be outer. (build_args.c) */
void build_matrix_xy(const affine *a, const double outer[2][3], double inner[2][3]);

#endif
