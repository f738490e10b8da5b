/* What a scene says about its look: lights, materials, camera, background.
 *
 * The builder fills a shading record from spancast's own nodes
 * (build_shading.c); the renderer reads it. Colours here are display
 * values, exactly as the file writes them (sRGB-encoded, like OpenSCAD's
 * colours); the renderer turns them into linear light once per render.
 *
 * Materials form a table; every leaf of the CSG tree names one by index
 * (csg_leaf.material). Index 0 is the default material, the one leaves
 * outside any material() node get. A material's base colour is not here: it
 * is the leaf's colour, so that material(color = ...) and OpenSCAD's
 * color() set the same thing and the outermost of them wins.
 *
 * The record also carries the parts OpenSCAD's preview draws besides the
 * solid: the '#' (highlight) and '%' (background) subtrees, as trees of
 * their own, which only a --preview render shows (render.c).
 */
#ifndef SPANCAST_MODEL_SHADING_H
#define SPANCAST_MODEL_SHADING_H

#include <stddef.h>
#include <stdint.h>

#include "csg/csg.h"
#include "math/vec.h"
#include "spancast/spancast.h"

typedef enum shading_light_kind {
    SHADING_LIGHT_POINT,       /* at position; a sphere light when radius > 0 */
    SHADING_LIGHT_DIRECTIONAL, /* from infinitely far along -direction */
    SHADING_LIGHT_RECT         /* a rectangle centred at position, lit on one side */
} shading_light_kind;

typedef struct shading_light {
    shading_light_kind kind;
    vec3 position;  /* point and sphere lights, world */
    vec3 direction; /* directional lights: unit direction the light travels */
    double radius;  /* sphere lights, world units; 0 for a point light */
    /* Rectangular lights: the half-edges from the centre along the width
     * and along the height (up projected onto the light's plane), and the
     * unit normal of the side that emits. In the node's own coordinates
     * after lowering, in world coordinates after building. */
    vec3 half_width, half_height, normal;
    float color[3];   /* display values 0..1 */
    double intensity; /* multiplies the colour (after linearising) */
} shading_light;

/* Defaults of a material() node's parameters, and of material 0. */
#define SHADING_DEFAULT_AMBIENT 0.1
#define SHADING_DEFAULT_DIFFUSE 0.9
#define SHADING_DEFAULT_SPECULAR 0.2
#define SHADING_DEFAULT_SHININESS 40.0
#define SHADING_DEFAULT_IOR 1.5

typedef struct shading_material {
    double ambient, diffuse, specular, shininess; /* Blinn-Phong weights */
    double reflect;                               /* mirror reflection weight, 0..1 */
    double transmit;  /* refraction weight, 0..1; Fresnel splits it */
    double ior;       /* index of refraction of the solid's inside */
    double checker;   /* > 0: a 3D checkerboard of cells this size in world units */
    double roughness; /* 0: mirror and clear refraction; up to 1: glossy lobes */
    float color2[3];  /* the checkerboard's second colour, display values */
} shading_material;

typedef struct shading_camera {
    double eye[3], center[3], up[3];
    double fov_deg;
    sc_projection projection;
    double aperture; /* thin lens diameter, world units; 0: a pinhole */
    double focus;    /* distance of the sharp plane from the eye; 0: eye to centre */
} shading_camera;

/* The kinds of modifier parts shading.overlay holds. */
enum { SHADING_OVERLAY_HIGHLIGHT, SHADING_OVERLAY_BACKGROUND, SHADING_OVERLAYS };

/* A slab of the preview's trees (a 2D object drawn 1 thick), and the box
 * OpenSCAD's preview frames it by: its polygons', at z = 0 in its own
 * frame, without the slab's thickness. */
typedef struct shading_slab {
    uint32_t object; /* the leaf's object_id */
    bbox flat;
} shading_slab;

/* Object ids first <= id < end: the leaves of one render(). */
typedef struct shading_ids {
    uint32_t first, end;
} shading_ids;

/* The leaves of each outermost render() of one tree, ascending and
 * disjoint: OpenSCAD's preview draws a render() as one mesh, so where it
 * is a product by itself (shade.h's leaf_product) every face of it is
 * drawn, as a lone leaf's are. */
typedef struct shading_renders {
    shading_ids *items;
    size_t count;
} shading_renders;

/* The slabs of one tree, ascending by object id. */
typedef struct shading_slabs {
    shading_slab *items;
    size_t count;
} shading_slabs;

typedef struct shading {
    shading_light *lights;
    uint32_t light_count, light_cap;
    shading_material *materials; /* [0] is the default material */
    uint32_t material_count, material_cap;
    int has_camera;
    shading_camera camera;
    int has_background;
    float background[3]; /* display values */
    /* The preview's modifier parts (build.h): the '#' subtrees united, and
     * the '%' subtrees united, each a tree of its own with its ancestors'
     * transforms and colours; NULL when the file has none. */
    csg_tree *overlay[SHADING_OVERLAYS];
    /* The solid as OpenSCAD's preview shows it, where it differs: without
     * the '#' operands of unions that have others, with the 2D objects of
     * a 3D model as slabs (build.c's build_preview_solid); NULL when it is
     * the solid. */
    csg_tree *preview_solid;
    /* The object ids of preview_solid's leaves subtracted inside a render(),
     * ascending: OpenSCAD's preview draws a render() as one mesh, so the
     * walls of its holes take the front colour and its other faces the back
     * colour (the two swap). */
    uint32_t *preview_swapped;
    size_t preview_swapped_count;
    /* The slabs (2D objects) of preview_solid and of each overlay tree,
     * each with the box OpenSCAD's preview frames it by. */
    shading_slabs preview_slabs;
    shading_slabs overlay_slabs[SHADING_OVERLAYS];
    /* The render()s of preview_solid and of each overlay tree. */
    shading_renders preview_renders;
    shading_renders overlay_renders[SHADING_OVERLAYS];
    /* A 2D model, drawn as the slab OpenSCAD draws a 2D result: its render
     * (not the preview) shows it unlit in the colour scheme's 2D face
     * colour, as OpenSCAD's render does. */
    int flat_2d;
    /* With flat_2d, the model as OpenSCAD's render draws it: the plane its
     * polygons lie in (world points p with n.p = d: n, d), the slab's
     * middle, where the render sees them; their box in it, which frames
     * them; and their outlines, which the render draws over them (world
     * points, 3 doubles each; outline k is points flat_start[k] to
     * flat_start[k + 1] - 1). */
    double flat_plane[4];
    bbox flat_box;
    double *flat_points;
    uint32_t *flat_start; /* flat_outlines + 1 entries when flat_outlines > 0 */
    uint32_t flat_outlines;
    /* The solid's own box (csg/bounds.h), which frames the render as
     * OpenSCAD frames its mesh; has_solid_box is 0 where it was not found
     * (the tree's box frames it then). */
    int has_solid_box;
    bbox solid_box;
} shading;

/* The index of the first of count items (stride bytes apart, each with a
 * uint32_t key offset bytes in, the keys ascending) whose key is at least
 * id; count when there is none. The object id lists above are searched
 * with it. */
size_t shading_find_id(const void *items, size_t count, size_t stride, size_t offset,
                       uint32_t id);

/* A record with the default material only; NULL when out of memory. */
shading *shading_new(void);
void shading_free(shading *s);

/* The default material, for material 0 and for material() parameters that
 * are not given. */
shading_material shading_default_material(void);

/* Appends a copy; returns 1, or 0 when out of memory. */
int shading_add_light(shading *s, const shading_light *light);

/* Appends a copy; returns its index, or UINT32_MAX when out of memory. */
uint32_t shading_add_material(shading *s, const shading_material *material);

#endif
