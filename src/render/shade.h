/* Whitted-style shading: what a ray sees.
 *
 * shade_ray follows one ray into the scene: at its first hit it adds the
 * material's ambient term and, for every light that a shadow ray (an
 * ANY_HIT query) finds unblocked, Blinn-Phong diffuse and specular terms;
 * then it follows a mirror ray (weight reflect) and a refracted ray (weight
 * transmit), the two split by Schlick's Fresnel approximation, with total
 * internal reflection sending everything to the mirror ray. Recursion stops
 * at max_depth bounces or when a ray's weight in the pixel falls below
 * SHADE_CUTOFF. A ray that hits nothing sees the background.
 *
 * Refraction through CSG solids follows the span list: a refracted ray
 * starts just inside the solid and its first hit is where it leaves
 * (csg_first_hit reports exiting), which for a drilled block is the wall of
 * the hole, not the far face. Which side is inside comes from the outward
 * normal the booleans give each surface (subtracted surfaces flipped): a
 * ray along the outward normal is leaving. The medium inside a solid has the
 * index of refraction of the material of the surface the ray crossed.
 *
 * Secondary rays start off the surface, not on it: the hit point is moved
 * along the surface normal (towards the side the ray leaves on) by
 * SHADE_OFFSET times the larger of the query tolerance csg_eps at the point
 * and 1e-9 of the distance the ray travelled, so the offset follows the
 * scene's scale and the hit's rounding error (which grows with both), and
 * stays far below any wall thickness the tolerance can resolve. Moving along
 * the normal, not along the ray, keeps grazing rays from re-hitting the
 * surface they leave (no shadow acne) and never carries a point through a
 * wall thicker than the offset (no light leaks).
 *
 * Lights: point, sphere and directional (shading.h). A sphere light is
 * sampled at one point per pixel sample, uniformly on the disc of its
 * radius facing the shaded point, so soft shadows converge with --spp.
 * A scene without lights gets the default rig: two directional lights fixed
 * to the camera (a key light from the upper left and towards the viewer, a
 * weaker fill from the lower right), which cast shadows like any other.
 * --lighting=openscad replaces all of that by OpenSCAD's own lighting,
 * computed on display values without shadows (shade.c).
 *
 * Section cuts: every query of shading (camera, shadow, occlusion and
 * secondary rays) goes through shade_first_hit and shade_any_hit, which
 * clip the ray to the intersection of the cut half-spaces and take the
 * solid's span list inside it: where a span starts at a cut plane the ray
 * meets a cap, with the plane's normal and the cap colour (hatched with
 * lines at 45 degrees in the plane's own axes, fixed in the world, for
 * --section-style=hatch). Without cuts they are the plain first-hit and
 * any-hit queries.
 *
 * Ambient occlusion: at each hit, ao_samples rays from the offset point,
 * cosine-distributed about the facing normal and ao_radius long; the
 * colour there (not what reflections add) is scaled by the share that
 * meets nothing. The rays take the sample's own random numbers, so the
 * image depends on neither the thread count nor the tiling.
 */
#ifndef SPANCAST_RENDER_SHADE_H
#define SPANCAST_RENDER_SHADE_H

#include <stdint.h>

#include "base/arena.h"
#include "csg/csg.h"
#include "model/shading.h"
#include "render/camera.h"
#include "render/sample.h"

#define SHADE_CUTOFF 1e-3      /* rays carrying less of the pixel are not followed */
#define SHADE_OFFSET 4.0       /* secondary ray origins, in units of the tolerance */
#define SHADE_MAX_DEPTH 64     /* largest max_depth accepted */
#define SHADE_HATCH_LINES 80   /* hatch lines across the model's diagonal */
#define SHADE_HATCH_WIDTH 0.25 /* a hatch line's share of the spacing */

typedef struct shade_light {
    int directional;
    int rect;      /* a rectangular light (shading.h) */
    vec3 position; /* point, sphere and rectangular lights (the centre) */
    vec3 to_light; /* directional: unit direction towards the light */
    double radius; /* sphere light; 0 for a point */
    vec3 half_width, half_height, normal; /* rectangular light, world */
    double color[3];                      /* linear, times the intensity */
} shade_light;

typedef struct shade_material {
    double ambient, diffuse, specular, shininess, reflect, transmit, ior, checker;
    double color2[3]; /* linear */
    double lobe;      /* glossy lobe exponent 2 / roughness^2 - 2; 0 with roughness 0
                         (a mirror: no lobe is sampled) */
    int glossy;       /* roughness > 0 */
    int whole;        /* shininess when a whole number in 0..SHADE_WHOLE_MAX (the
                         highlight then takes whole_power), else -1 */
} shade_material;

#define SHADE_WHOLE_MAX 1024

/* A section cut: the half-space n.p <= d keeps the solid (n unit). */
typedef struct shade_section {
    vec3 n;
    double d;
} shade_section;

/* How a scene is lit (sc_lighting, split by preview). */
typedef enum shade_lighting {
    SHADE_LIGHTING_OWN,             /* light() nodes or the default rig, shadows */
    SHADE_LIGHTING_OPENSCAD_RENDER, /* OpenSCAD's render: two fixed lights */
    SHADE_LIGHTING_OPENSCAD_PREVIEW /* OpenSCAD's preview shader: one light */
} shade_lighting;

/* Which face colour a leaf's hits take: the back one where the hit's
 * normal is flipped (a subtracted surface), or, for a mesh drawn by the
 * parity rule, whose flips only follow its triangles' winding, the front
 * one, or the back one where the leaf is subtracted (OpenSCAD colours a
 * subtracted object's faces, whichever way they wind). */
enum { SHADE_SIDE_FLIP, SHADE_SIDE_FRONT, SHADE_SIDE_BACK };

/* Everything shading needs, prepared once per render (shade_prepare) and
 * read-only while rendering. */
typedef struct shade_scene {
    const csg_tree *tree;
    shade_material *materials;
    uint32_t material_count;
    double *leaf_color; /* 3 linear values per leaf */
    double *leaf_back;  /* 3 linear values per leaf: its subtracted faces */
    double *leaf_alpha; /* one per leaf: its colour's opacity */
    int translucent;    /* a preview with some leaf's alpha below 1 (render.c
                           composites its surfaces) */
    /* The preview only (else NULL), one per leaf: the node of the tree
     * that is the leaf's product in OpenSCAD's normal form, which OpenGL
     * draws as a unit: the child of the top-level unions the leaf lies
     * under, the leaf's own node where it is such a child (a lone leaf,
     * whose rear faces OpenSCAD draws too); CSG_EMPTY for none. */
    uint32_t *leaf_product;
    /* The preview only, one per leaf: its product is drawn whole, rear
     * faces first, then front faces, so that each of its surfaces shows: a
     * lone leaf, or a render() by itself (shade_mark_renders), which
     * OpenSCAD draws as one mesh. */
    unsigned char *leaf_whole;
    /* With scheme_faces, one per leaf (NULL where no leaf needs it): which
     * face colour a hit takes, SHADE_SIDE_* (shade_sides). */
    unsigned char *leaf_side;
    shade_light *lights;
    uint32_t light_count;
    double background[3]; /* linear */
    int max_depth;
    shade_lighting lighting;
    int scheme_faces;       /* subtracted faces take leaf_back */
    int flat;               /* a 2D model in the render: unlit (shading.h) */
    double flat_plane[4];   /* with flat, where rays see it: n, d (shading.h) */
    vec3 openscad_light[2]; /* unit directions towards OpenSCAD's lights */
    shade_section sections[SC_MAX_SECTIONS];
    int section_count;
    double cap_color[3];  /* linear: section caps */
    int hatch;            /* caps hatched */
    double hatch_spacing; /* world units between hatch lines */
    int ao_samples;       /* ambient occlusion rays per hit; 0: none */
    double ao_radius;     /* their length, world units */
} shade_scene;

/* A camera ray's visible point: a surface hit, or a section cap where the
 * ray meets a cut plane inside the solid. */
typedef struct shade_hit {
    csg_hit hit;     /* for a cap: t on the plane, the leaf of the span cut */
    double time;     /* the ray's time, which places moving leaves */
    int cap;         /* 1: a section cap */
    vec3 cap_normal; /* a cap's outward normal: the plane's n */
} shade_hit;

/* Per-thread counters. */
typedef struct shade_counters {
    uint64_t shadow_rays, reflection_rays, refraction_rays;
    uint64_t edge_rays; /* camera rays beside a sample's, for edge lines */
} shade_counters;

/* One thread's state for one pixel sample. */
typedef struct shade_thread {
    arena *scratch;  /* query memory; the caller resets it after the sample */
    sample_rng rng;  /* the sample's random numbers */
    sample_pixel px; /* the sample's place among the pixel's, for stratified
                        dimensions (sample_2d) */
    double lens[2];  /* the camera ray's point on the unit disc of the lens */
    double time;     /* the sample's time in the shutter, which every ray of the
                        sample carries (csg_motion); 0 without motion blur */
    shade_counters count;
    csg_counters *csg; /* the thread's query counters */
} shade_thread;

/* Prepares s for tree under look (NULL: no lights, default materials) seen
 * by cam, as options ask (colour scheme, lighting, sections, occlusion,
 * max_depth). Returns SC_OK, or SC_ERR_NOMEM with error filled. */
sc_status shade_prepare(shade_scene *s, const csg_tree *tree, const shading *look,
                        const camera *cam, const sc_render_options *options,
                        sc_error *error);
void shade_release(shade_scene *s);

/* Paints the leaves of a preview's modifier part (render.c) rgba (display
 * values, alpha last), front and back faces and caps alike, except, with
 * keep_own, leaves whose file gave them a colour: those keep it and its
 * alpha, as OpenSCAD draws a coloured '%' part. */
void shade_paint_part(shade_scene *s, const float rgba[4], int keep_own);

/* Marks as drawn whole (leaf_whole) the leaves of each product of the
 * preview s whose leaves all lie in one of renders (a render() that is a
 * product by itself, or several products where the render() is a union),
 * and makes the products of each render() one (leaf_product), as
 * OpenSCAD draws the render()'s mesh. Returns SC_OK, or SC_ERR_NOMEM with
 * error filled. */
sc_status shade_mark_renders(shade_scene *s, const shading_renders *renders,
                             sc_error *error);

/* FIRST_HIT with the section cuts applied: 1 and *hit when the ray sees
 * the solid within [tmin, tmax]. Without sections it is csg_first_hit;
 * with them the ray's span list is clipped to the half-spaces, and a span
 * that the clip starts is a cap. */
int shade_first_hit(const shade_scene *s, shade_thread *th, const csg_ray *ray,
                    shade_hit *hit);

/* ANY_HIT with the section cuts applied. */
int shade_any_hit(const shade_scene *s, shade_thread *th, const csg_ray *ray);

/* The unit outward normal at a hit (a cap's plane normal). */
vec3 shade_hit_normal(const shade_scene *s, const csg_ray *ray, const shade_hit *hit);

/* The linear colour seen along ray (depth bounces so far, weight its share
 * of the pixel). hit is the ray's first hit when the caller has already
 * found it (shade_first_hit), NULL to query. Writes out[3]. */
void shade_ray(const shade_scene *s, shade_thread *th, const csg_ray *ray,
               const shade_hit *hit, int depth, double weight, double out[3]);

#endif
