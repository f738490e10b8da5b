/* Whitted-style shading: see shade.h for the model.
 *
 * Blinn-Phong at a hit with facing normal n, towards-viewer v, and for each
 * unshadowed light towards-light l with linear colour E:
 *   L = ambient base + sum E (diffuse base max(0, n.l)
 *                             + specular max(0, n.h)^shininess),  h = |l + v|
 * then L += kr L(mirror ray) + kt L(refracted ray), where with Schlick's
 * F = R0 + (1 - R0)(1 - cos)^5, R0 = ((n1 - n2) / (n1 + n2))^2 and cos the
 * cosine on the less dense side,
 *   kr = reflect + transmit F,   kt = transmit (1 - F),
 * and total internal reflection (no refracted direction) gives kr =
 * reflect + transmit, kt = 0.
 */
#include "render/shade.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "formats/color.h"
#include "build/build.h"
#include "csg/prim_mesh.h"
#include "render/render.h"

/* The default rig, as directions towards the lights in camera coordinates
 * (right, up, towards the viewer) and intensities. */
static const double key_light[3] = {-0.5, 0.6, 0.8};
static const double fill_light[3] = {0.6, -0.3, 0.7};
static const double key_intensity = 0.8;
static const double fill_intensity = 0.3;

/* OpenSCAD's two lights (GLView::initializeGL), set with an identity
 * modelview, so fixed to the camera: towards (-1, 1, 1) and (1, -1, -1) in
 * its eye coordinates, diffuse 1, with the light model's global ambient
 * 0.2 and no specular term (the material's specular colour is black). */
static const double openscad_light0[3] = {-1, 1, 1};
static const double openscad_light1[3] = {1, -1, -1};
#define OPENSCAD_AMBIENT 0.2

static const float default_background[3] = {RENDER_BACKGROUND_R, RENDER_BACKGROUND_G,
                                            RENDER_BACKGROUND_B};

static vec3 camera_to_world(const camera *cam, const double c[3])
{
    vec3 w = v3_scale(cam->r, c[0]);
    w = v3_madd(w, cam->u, c[1]);
    w = v3_madd(w, cam->f, -c[2]);
    return v3_normalize(w);
}

static void linear3(const float in[3], double scale, double out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = scale * color_srgb_to_linear(in[k]);
}

/* Whether a leaf's colour is OpenSCAD's default face colour, which a
 * colour scheme replaces (the tree keeps no other mark of a colour that
 * the file did not give; an explicit #f9d72c counts as none). */
static int is_default_color(const float c[4])
{
    static const float def[4] = BUILD_DEFAULT_COLOR;
    return c[0] == def[0] && c[1] == def[1] && c[2] == def[2];
}

/* Fills product (one per leaf; see shade_scene.leaf_product): OpenSCAD
 * normalises the tree into a list of products, one for each child of the
 * unions at its top (CSGTreeNormalizer), and draws each by itself. Nodes
 * come children first, so going down the array meets a node's parents
 * before it. Returns 0 when out of memory. */
static int find_products(const csg_tree *tree, uint32_t *product, unsigned char *whole)
{
    for (uint32_t i = 0; i < tree->leaf_count; i++)
        product[i] = CSG_EMPTY;
    if (tree->root == CSG_EMPTY)
        return 1;
    /* of each node: CSG_EMPTY unreached, top for a top-level union, else
     * its product */
    const uint32_t top = CSG_EMPTY - 1;
    uint32_t *of = malloc(((size_t)tree->node_count + 1) * sizeof *of);
    if (!of)
        return 0;
    for (uint32_t i = 0; i < tree->node_count; i++)
        of[i] = CSG_EMPTY;
    of[tree->root] = tree->nodes[tree->root].op == CSG_UNION ? top : tree->root;
    for (uint32_t i = tree->node_count; i-- > 0;) {
        const csg_node *n = &tree->nodes[i];
        if (of[i] == CSG_EMPTY)
            continue;
        if (n->op == CSG_LEAF) {
            product[n->leaf] = of[i];
            whole[n->leaf] = of[i] == i; /* a lone leaf */
            continue;
        }
        for (uint32_t k = 0; k < n->child_count; k++) {
            uint32_t c = tree->child_ids[n->first_child + k];
            if (of[i] != top)
                of[c] = of[i];
            else
                of[c] = tree->nodes[c].op == CSG_UNION ? top : c;
        }
    }
    free(of);
    return 1;
}

static int parity_mesh(const prim *p)
{
    return p->kind == PRIM_MESH && p->u.mesh.mesh && p->u.mesh.mesh->parity;
}

/* Sets s->leaf_side where a leaf is a mesh drawn by the parity rule (see
 * SHADE_SIDE_*): the front colour, or the back one where the leaf lies
 * under an odd number of differences' later operands. Nodes come
 * children first, so going down the array meets a node's parents before
 * it. Returns 0 when out of memory. */
static int shade_sides(shade_scene *s, const csg_tree *tree)
{
    int any = 0;
    for (uint32_t i = 0; i < tree->leaf_count && !any; i++)
        any = parity_mesh(&tree->leaves[i].prim);
    if (!any || tree->root == CSG_EMPTY)
        return 1;
    unsigned char *negative = calloc((size_t)tree->node_count + 1, 1);
    s->leaf_side = calloc((size_t)tree->leaf_count + 1, 1);
    if (!negative || !s->leaf_side) {
        free(negative);
        return 0;
    }
    for (uint32_t i = tree->node_count; i-- > 0;) {
        const csg_node *n = &tree->nodes[i];
        if (n->op == CSG_LEAF) {
            const prim *p = &tree->leaves[n->leaf].prim;
            if (parity_mesh(p))
                s->leaf_side[n->leaf] = negative[i] ? SHADE_SIDE_BACK : SHADE_SIDE_FRONT;
            continue;
        }
        for (uint32_t k = 0; k < n->child_count; k++) {
            uint32_t c = tree->child_ids[n->first_child + k];
            negative[c] = negative[i] ^ (n->op == CSG_DIFFERENCE && k > 0);
        }
    }
    free(negative);
    return 1;
}

/* The leaves subtracted inside a render() (shading.preview_swapped), which
 * OpenSCAD's preview draws as one mesh: the walls of their holes in the
 * front colour, their faces cut from something else in the back colour. */
static void swap_render_faces(shade_scene *s, const csg_tree *tree, const shading *look)
{
    const uint32_t *ids = look->preview_swapped;
    size_t count = look->preview_swapped_count;
    for (uint32_t i = 0; i < tree->leaf_count && count; i++) {
        uint32_t id = tree->leaves[i].object_id;
        size_t lo = shading_find_id(ids, count, sizeof *ids, 0, id);
        if (lo == count || ids[lo] != id)
            continue;
        for (int k = 0; k < 3; k++) {
            double t = s->leaf_color[3 * i + k];
            s->leaf_color[3 * i + k] = s->leaf_back[3 * i + k];
            s->leaf_back[3 * i + k] = t;
        }
    }
}

/* The index of the item of renders that holds object id, or
 * renders->count. */
static size_t render_of(const shading_renders *renders, uint32_t id)
{
    size_t k = shading_find_id(renders->items, renders->count, sizeof *renders->items,
                               offsetof(shading_ids, first), id);
    if (k < renders->count && renders->items[k].first == id)
        return k;
    return k && id < renders->items[k - 1].end ? k - 1 : renders->count;
}

sc_status shade_mark_renders(shade_scene *s, const shading_renders *renders,
                             sc_error *error)
{
    const csg_tree *tree = s->tree;
    if (!s->leaf_product || !renders->count)
        return SC_OK;
    /* of each product node, the render() of its first leaf, and whether
     * all its leaves share it */
    size_t *in = malloc(((size_t)tree->node_count + 1) * sizeof *in);
    unsigned char *one = malloc((size_t)tree->node_count + 1);
    if (!in || !one) {
        free(in);
        free(one);
        return err_nomem(error, NULL);
    }
    const size_t unseen = SIZE_MAX;
    for (uint32_t i = 0; i < tree->node_count; i++)
        in[i] = unseen;
    for (uint32_t i = 0; i < tree->leaf_count; i++) {
        uint32_t p = s->leaf_product[i];
        if (p == CSG_EMPTY)
            continue;
        size_t r = render_of(renders, tree->leaves[i].object_id);
        if (in[p] == unseen) {
            in[p] = r;
            one[p] = r < renders->count;
        } else if (in[p] != r) {
            one[p] = 0;
        }
    }
    /* the products inside one render() become one, its first: OpenSCAD
     * draws the render()'s mesh, not the products of its leaves */
    uint32_t *first = malloc((renders->count + 1) * sizeof *first);
    if (!first) {
        free(in);
        free(one);
        return err_nomem(error, NULL);
    }
    for (size_t r = 0; r < renders->count; r++)
        first[r] = CSG_EMPTY;
    for (uint32_t i = 0; i < tree->leaf_count; i++) {
        uint32_t p = s->leaf_product[i];
        if (p == CSG_EMPTY || !one[p])
            continue;
        if (first[in[p]] == CSG_EMPTY)
            first[in[p]] = p;
        s->leaf_product[i] = first[in[p]];
        s->leaf_whole[i] = 1;
    }
    free(first);
    free(in);
    free(one);
    return SC_OK;
}

sc_status shade_prepare(shade_scene *s, const csg_tree *tree, const shading *look,
                        const camera *cam, const sc_render_options *o, sc_error *error)
{
    memset(s, 0, sizeof *s);
    s->tree = tree;
    s->max_depth = o->max_depth;
    uint32_t materials = look ? look->material_count : 1;
    uint32_t lights = look && look->light_count ? look->light_count : 2;
    s->materials = calloc(materials, sizeof *s->materials);
    s->lights = calloc(lights, sizeof *s->lights);
    s->leaf_color = calloc((size_t)tree->leaf_count * 3 + 3, sizeof *s->leaf_color);
    s->leaf_back = calloc((size_t)tree->leaf_count * 3 + 3, sizeof *s->leaf_back);
    s->leaf_alpha = calloc((size_t)tree->leaf_count + 1, sizeof *s->leaf_alpha);
    if (o->preview) {
        s->leaf_product =
            malloc(((size_t)tree->leaf_count + 1) * sizeof *s->leaf_product);
        s->leaf_whole = calloc((size_t)tree->leaf_count + 1, 1);
        if (s->leaf_product && s->leaf_whole &&
            !find_products(tree, s->leaf_product, s->leaf_whole)) {
            free(s->leaf_product);
            s->leaf_product = NULL;
        }
    }
    if (!s->materials || !s->lights || !s->leaf_color || !s->leaf_back ||
        !s->leaf_alpha || (o->preview && (!s->leaf_product || !s->leaf_whole))) {
        shade_release(s);
        return err_nomem(error, NULL);
    }
    s->material_count = materials;
    for (uint32_t i = 0; i < materials; i++) {
        shading_material m = look ? look->materials[i] : shading_default_material();
        shade_material *out = &s->materials[i];
        out->ambient = m.ambient;
        out->diffuse = m.diffuse;
        out->specular = m.specular;
        out->shininess = m.shininess;
        out->reflect = m.reflect;
        out->transmit = m.transmit;
        out->ior = m.ior;
        out->checker = m.checker;
        linear3(m.color2, 1, out->color2);
        out->whole = m.shininess >= 0 && m.shininess <= SHADE_WHOLE_MAX &&
                             m.shininess == floor(m.shininess)
                         ? (int)m.shininess
                         : -1;
        out->glossy = m.roughness > 0;
        out->lobe = out->glossy ? 2 / (m.roughness * m.roughness) - 2 : 0;
    }
    /* Faces: with a scheme chosen, or in the preview, the scheme's face
     * colours where the file gives none: the front colour, and the back
     * colour on subtracted faces (the walls of a drilled hole), as
     * OpenSCAD draws them in its preview (opencsg-*) and its render
     * (cgal-*). */
    const sc_color_scheme *scheme = &o->scheme;
    const float *scheme_front = o->preview ? scheme->face_front : scheme->render_face;
    const float *scheme_back = o->preview ? scheme->face_back : scheme->render_face_back;
    s->scheme_faces = o->use_scheme || o->preview;
    /* A 2D model in the render: OpenSCAD's render draws a 2D result
     * without lighting, in CGAL_FACE_2D_COLOR where the file gives no
     * colour, on both sides. */
    s->flat = look && look->flat_2d && !o->preview;
    if (s->flat) {
        scheme_front = scheme_back = o->face_2d;
        memcpy(s->flat_plane, look->flat_plane, sizeof s->flat_plane);
    }
    for (uint32_t i = 0; i < tree->leaf_count; i++) {
        const float *c = tree->leaves[i].color;
        int plain = (s->scheme_faces || s->flat) && is_default_color(c);
        linear3(plain ? scheme_front : c, 1, &s->leaf_color[3 * i]);
        linear3(plain ? scheme_back : c, 1, &s->leaf_back[3 * i]);
        s->leaf_alpha[i] = c[3];
        /* Only the preview shows alpha, as OpenSCAD's render (F6) does not. */
        s->translucent |= o->preview && c[3] < 1;
    }
    if (look && tree == look->preview_solid && s->scheme_faces)
        swap_render_faces(s, tree, look);
    if (s->scheme_faces && !shade_sides(s, tree)) {
        shade_release(s);
        return err_nomem(error, NULL);
    }
    if (look && tree == look->preview_solid && o->preview) {
        sc_status st = shade_mark_renders(s, &look->preview_renders, error);
        if (st != SC_OK) {
            shade_release(s);
            return st;
        }
    }
    s->light_count = lights;
    if (look && look->light_count) {
        for (uint32_t i = 0; i < lights; i++) {
            const shading_light *in = &look->lights[i];
            shade_light *out = &s->lights[i];
            out->directional = in->kind == SHADING_LIGHT_DIRECTIONAL;
            out->position = in->position;
            out->to_light = v3_neg(in->direction);
            out->radius = in->radius;
            out->rect = in->kind == SHADING_LIGHT_RECT;
            out->half_width = in->half_width;
            out->half_height = in->half_height;
            out->normal = in->normal;
            linear3(in->color, in->intensity, out->color);
        }
    } else {
        s->lights[0].directional = s->lights[1].directional = 1;
        s->lights[0].to_light = camera_to_world(cam, key_light);
        s->lights[1].to_light = camera_to_world(cam, fill_light);
        for (int k = 0; k < 3; k++) {
            s->lights[0].color[k] = key_intensity;
            s->lights[1].color[k] = fill_intensity;
        }
    }
    if (o->lighting == SC_LIGHTING_OPENSCAD)
        s->lighting =
            o->preview ? SHADE_LIGHTING_OPENSCAD_PREVIEW : SHADE_LIGHTING_OPENSCAD_RENDER;
    s->openscad_light[0] = camera_to_world(cam, openscad_light0);
    s->openscad_light[1] = camera_to_world(cam, openscad_light1);
    if (o->use_scheme)
        linear3(scheme->background, 1, s->background);
    else
        linear3(look && look->has_background ? look->background : default_background, 1,
                s->background);

    double diagonal = bbox_is_empty(&tree->bounds) || tree->root == CSG_EMPTY
                          ? 1.0
                          : v3_length(bbox_extent(&tree->bounds));
    s->section_count = 0;
    for (int k = 0; k < o->section_count && k < SC_MAX_SECTIONS; k++) {
        const double *q = o->section[k];
        double len = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        if (!(len > 0) || !isfinite(len) || !isfinite(q[3])) {
            shade_release(s);
            return err_set(error, SC_ERR_ARGUMENT, NULL,
                           "section %d needs a finite, non-zero normal and a finite "
                           "offset",
                           k + 1);
        }
        s->sections[s->section_count].n = v3(q[0] / len, q[1] / len, q[2] / len);
        s->sections[s->section_count].d = q[3] / len;
        s->section_count++;
    }
    linear3(scheme_back, 1, s->cap_color);
    s->hatch = o->section_style == SC_SECTION_HATCH;
    s->hatch_spacing = diagonal / SHADE_HATCH_LINES;
    s->ao_samples = o->ao_samples;
    s->ao_radius = o->ao_radius * diagonal;
    return SC_OK;
}

void shade_release(shade_scene *s)
{
    free(s->materials);
    free(s->lights);
    free(s->leaf_color);
    free(s->leaf_back);
    free(s->leaf_alpha);
    free(s->leaf_product);
    free(s->leaf_whole);
    free(s->leaf_side);
    memset(s, 0, sizeof *s);
}

void shade_paint_part(shade_scene *s, const float rgba[4], int keep_own)
{
    for (uint32_t i = 0; i < s->tree->leaf_count; i++) {
        const float *c = s->tree->leaves[i].color;
        if (keep_own && !is_default_color(c))
            continue; /* shade_prepare gave it its own colour and alpha */
        linear3(rgba, 1, &s->leaf_color[3 * i]);
        linear3(rgba, 1, &s->leaf_back[3 * i]);
        s->leaf_alpha[i] = rgba[3];
    }
    linear3(rgba, 1, s->cap_color);
    s->hatch = 0;
    s->translucent = 0;
}

/* The distance secondary rays start from a hit at p reached after dist. */
static double offset_at(const shade_scene *s, vec3 p, double dist)
{
    double eps = csg_eps(s->tree, p, v3(1, 0, 0));
    return SHADE_OFFSET * fmax(eps, 1e-9 * dist);
}

/* The base colour at p on leaf (checkerboard applied); inward is a point a
 * little inside the surface, so a face lying on a cell boundary gets one
 * colour. */
static void base_color(const shade_scene *s, const shade_material *m, uint32_t leaf,
                       vec3 inward, double out[3])
{
    const double *c = &s->leaf_color[3 * leaf];
    if (m->checker > 0) {
        double cell = floor(inward.x / m->checker) + floor(inward.y / m->checker) +
                      floor(inward.z / m->checker);
        if (fmod(fabs(cell), 2.0) == 1.0)
            c = m->color2;
    }
    memcpy(out, c, 3 * sizeof *out);
}

/* The ray's parameter interval inside every section half-space, within
 * [tmin, tmax]; *plane is the section whose plane starts it (-1 when it
 * starts at tmin). Returns 0 when it is empty. */
static int section_interval(const shade_scene *s, const csg_ray *ray, double *ta,
                            double *tb, int *plane)
{
    *ta = ray->tmin;
    *tb = ray->tmax;
    *plane = -1;
    for (int k = 0; k < s->section_count; k++) {
        const shade_section *c = &s->sections[k];
        double nd = v3_dot(c->n, ray->d), no = v3_dot(c->n, ray->o);
        if (nd == 0) {
            if (no > c->d)
                return 0;
            continue;
        }
        double t = (c->d - no) / nd;
        if (nd > 0) {
            if (t < *tb)
                *tb = t;
        } else if (t > *ta) {
            *ta = t;
            *plane = k;
        }
    }
    return *ta < *tb;
}

/* The spans of s's tree along ray, for th's time, within the sections'
 * interval [*ta, *tb] (section_interval, which also gives *plane).
 * Returns 0 when the interval is empty or the query fails. */
static int section_spans(const shade_scene *s, shade_thread *th, const csg_ray *ray,
                         double *ta, double *tb, int *plane, span_list *spans)
{
    if (!section_interval(s, ray, ta, tb, plane))
        return 0;
    csg_ray clipped = *ray;
    clipped.tmin = *ta;
    clipped.tmax = *tb;
    return csg_spans_at(s->tree, &clipped, th->time, th->scratch, th->csg, spans);
}

/* shade_first_hit for a 2D model in the render (flat): the point where
 * the ray crosses the plane of its polygons, when the slab holds it (the
 * polygons' inside) and the sections keep it; a cap with the plane's
 * normal turned to the ray. */
static int flat_first_hit(const shade_scene *s, shade_thread *th, const csg_ray *ray,
                          shade_hit *hit)
{
    vec3 n = v3(s->flat_plane[0], s->flat_plane[1], s->flat_plane[2]);
    double nd = v3_dot(n, ray->d);
    double t = (s->flat_plane[3] - v3_dot(n, ray->o)) / nd;
    double ta, tb;
    int plane;
    span_list spans;
    if (!(nd != 0 && section_spans(s, th, ray, &ta, &tb, &plane, &spans) && t >= ta &&
          t <= tb))
        return 0;
    for (uint32_t k = 0; k < spans.n; k++) {
        const span *sp = &spans.v[k];
        if (!(sp->in.t <= t && t <= sp->out.t))
            continue;
        hit->cap = 1;
        hit->cap_normal = nd < 0 ? n : v3_neg(n);
        hit->hit.t = t;
        hit->hit.leaf = sp->in.leaf != SPAN_NO_LEAF    ? sp->in.leaf
                        : sp->out.leaf != SPAN_NO_LEAF ? sp->out.leaf
                                                       : 0;
        return 1;
    }
    return 0;
}

int shade_first_hit(const shade_scene *s, shade_thread *th, const csg_ray *ray,
                    shade_hit *hit)
{
    memset(hit, 0, sizeof *hit);
    hit->time = th->time;
    if (s->flat)
        return flat_first_hit(s, th, ray, hit);
    if (s->section_count == 0)
        return csg_first_hit_at(s->tree, ray, th->time, th->scratch, th->csg, &hit->hit);
    double ta, tb;
    int plane;
    span_list spans;
    if (!section_spans(s, th, ray, &ta, &tb, &plane, &spans))
        return 0;
    for (uint32_t k = 0; k < spans.n; k++) {
        const span *sp = &spans.v[k];
        if (!(sp->out.t > sp->in.t))
            continue;
        if (sp->in.leaf != SPAN_NO_LEAF) { /* an ordinary surface */
            hit->hit.t = sp->in.t;
            hit->hit.leaf = sp->in.leaf;
            hit->hit.part = sp->in.part;
            hit->hit.flip = sp->in.flip;
            return 1;
        }
        if (plane >= 0) { /* inside the solid where a cut plane starts the ray */
            hit->cap = 1;
            hit->cap_normal = s->sections[plane].n;
            hit->hit.t = ta;
            hit->hit.leaf = sp->out.leaf != SPAN_NO_LEAF ? sp->out.leaf : 0;
            return 1;
        }
        /* The ray starts inside: its first hit is where it leaves. */
        if (sp->out.leaf == SPAN_NO_LEAF)
            return 0;
        hit->hit.t = sp->out.t;
        hit->hit.leaf = sp->out.leaf;
        hit->hit.part = sp->out.part;
        hit->hit.flip = sp->out.flip;
        hit->hit.exiting = 1;
        return 1;
    }
    return 0;
}

int shade_any_hit(const shade_scene *s, shade_thread *th, const csg_ray *ray)
{
    if (s->section_count == 0)
        return csg_any_hit_at(s->tree, ray, th->time, th->scratch, th->csg);
    shade_hit hit;
    return shade_first_hit(s, th, ray, &hit);
}

vec3 shade_hit_normal(const shade_scene *s, const csg_ray *ray, const shade_hit *hit)
{
    return hit->cap ? hit->cap_normal
                    : csg_hit_normal_at(s->tree, ray, hit->time, &hit->hit);
}

/* x^n by squaring: at most 2 log2(n) products, against libm's pow, which
 * takes a logarithm and an exponential for every highlight. Each product
 * rounds once, so the result may differ from pow's (correctly rounded in
 * practice) by a few ulps, far below a colour channel's 1/255. */
static double whole_power(double x, unsigned n)
{
    double r = 1;
    while (n) {
        if (n & 1)
            r *= x;
        n >>= 1;
        if (n)
            x *= x;
    }
    return r;
}

/* Adds the direct light at p (facing normal n, towards-viewer v). */
static void direct_light(const shade_scene *s, shade_thread *th, const shade_material *m,
                         const double base[3], vec3 p, vec3 n, vec3 v, vec3 origin,
                         double out[3])
{
    for (uint32_t i = 0; i < s->light_count; i++) {
        const shade_light *light = &s->lights[i];
        csg_ray shadow;
        shadow.o = origin;
        shadow.tmin = 0;
        vec3 l;
        double emitted = 1; /* a rectangular light's Lambert factor */
        if (light->directional) {
            l = light->to_light;
            shadow.d = l;
            shadow.tmax = INFINITY;
        } else {
            vec3 target = light->position;
            if (light->rect) {
                /* A uniform point on the rectangle, stratified over the
                 * pixel's samples. */
                double a, b;
                sample_2d(&th->px, &th->rng, &a, &b);
                target = v3_madd(v3_madd(target, light->half_width, 2 * a - 1),
                                 light->half_height, 2 * b - 1);
            } else if (light->radius > 0) {
                /* A uniform point on the disc of the light facing p. */
                vec3 w = v3_normalize(v3_sub(light->position, p));
                vec3 a = fabs(w.x) < 0.6 ? v3(1, 0, 0) : v3(0, 1, 0);
                vec3 e1 = v3_normalize(v3_cross(w, a)), e2 = v3_cross(w, e1);
                double r = light->radius * sqrt(sample_next(&th->rng));
                double phi = 6.283185307179586 * sample_next(&th->rng);
                target = v3_madd(v3_madd(target, e1, r * cos(phi)), e2, r * sin(phi));
            }
            shadow.d = v3_sub(target, origin);
            shadow.tmax = 1;
            l = v3_normalize(shadow.d);
            if (light->rect) {
                emitted = -v3_dot(light->normal, l);
                if (!(emitted > 0))
                    continue; /* behind the light: it emits on one side */
            }
        }
        double nl = v3_dot(n, l);
        if (!(nl > 0))
            continue;
        th->count.shadow_rays++;
        if (shade_any_hit(s, th, &shadow))
            continue;
        double highlight = 0;
        if (m->specular > 0) {
            vec3 h = v3_normalize(v3_add(l, v));
            double nh = fmax(0.0, v3_dot(n, h));
            highlight = m->specular * (m->whole >= 0 ? whole_power(nh, (unsigned)m->whole)
                                                     : pow(nh, m->shininess));
        }
        for (int k = 0; k < 3; k++)
            out[k] += emitted * light->color[k] * (m->diffuse * base[k] * nl + highlight);
    }
}

/* A direction of the glossy lobe about the unit axis: density
 * (lobe + 1) / (2 pi) cos^lobe of the angle to the axis over the sphere of
 * directions, sampled exactly (cos = u^(1 / (lobe + 1))), stratified over
 * the pixel's samples. */
static vec3 glossy_direction(shade_thread *th, vec3 axis, double lobe)
{
    double u, w;
    sample_2d(&th->px, &th->rng, &u, &w);
    double c =
        pow(1 - u, 1 / (lobe + 1)); /* 1 - u in (0, 1]: never the pole's far side */
    double sn = sqrt(fmax(0.0, 1 - c * c));
    double phi = 6.283185307179586 * w;
    vec3 a = fabs(axis.x) < 0.6 ? v3(1, 0, 0) : v3(0, 1, 0);
    vec3 e1 = v3_normalize(v3_cross(axis, a)), e2 = v3_cross(axis, e1);
    return v3_madd(v3_madd(v3_scale(axis, c), e1, sn * cos(phi)), e2, sn * sin(phi));
}

/* OpenSCAD's lighting of base (linear) at facing normal n, computed on
 * display values as its fixed-function pipeline and its preview shader do:
 *   render:  c (0.2 + max(0, n.l0) + max(0, n.l1))
 *   preview: c (0.2 + |n.l0|)
 * clamped to 0..1, then decoded to linear light. */
static void openscad_light(const shade_scene *s, const double base[3], vec3 n,
                           double out[3])
{
    double factor;
    if (s->lighting == SHADE_LIGHTING_OPENSCAD_PREVIEW)
        factor = OPENSCAD_AMBIENT + fabs(v3_dot(n, s->openscad_light[0]));
    else
        factor = OPENSCAD_AMBIENT + fmax(0.0, v3_dot(n, s->openscad_light[0])) +
                 fmax(0.0, v3_dot(n, s->openscad_light[1]));
    for (int k = 0; k < 3; k++)
        out[k] = color_srgb_to_linear(fmin(1.0, color_linear_to_srgb(base[k]) * factor));
}

/* The fraction of ao_samples rays, cosine-distributed about n from origin,
 * that leave without meeting the solid within ao_radius. */
static double ambient_visibility(const shade_scene *s, shade_thread *th, vec3 n,
                                 vec3 origin)
{
    vec3 a = fabs(n.x) < 0.6 ? v3(1, 0, 0) : v3(0, 1, 0);
    vec3 e1 = v3_normalize(v3_cross(n, a)), e2 = v3_cross(n, e1);
    int open = 0;
    for (int k = 0; k < s->ao_samples; k++) {
        double r = sqrt(sample_next(&th->rng));
        double phi = 6.283185307179586 * sample_next(&th->rng);
        double z = sqrt(fmax(0.0, 1 - r * r));
        vec3 d = v3_madd(v3_madd(v3_scale(n, z), e1, r * cos(phi)), e2, r * sin(phi));
        csg_ray ray = {origin, d, 0, s->ao_radius};
        th->count.shadow_rays++;
        open += !shade_any_hit(s, th, &ray);
    }
    return (double)open / s->ao_samples;
}

/* Whether p on a cap lies on a hatch line: lines at 45 degrees in the cut
 * plane's own axes, SHADE_HATCH_LINES across the model. */
static int on_hatch(const shade_scene *s, vec3 n, vec3 p)
{
    vec3 a = fabs(n.x) < 0.6 ? v3(1, 0, 0) : v3(0, 1, 0);
    vec3 e1 = v3_normalize(v3_cross(n, a)), e2 = v3_cross(n, e1);
    double u = (v3_dot(p, e1) + v3_dot(p, e2)) * 0.7071067811865476 / s->hatch_spacing;
    return u - floor(u) < SHADE_HATCH_WIDTH;
}

/* Adds k times the light that arrives along a secondary ray (reflected or
 * refracted) from origin in the direction ideal to out; with a glossy m the
 * direction is drawn about ideal from m's lobe, and one on the wrong side
 * of the surface (side +1: the side n points to, -1: the other) is
 * absorbed. *rays counts the ray. */
static void secondary_ray(const shade_scene *s, shade_thread *th, const shade_material *m,
                          vec3 origin, vec3 ideal, vec3 n, double side, int depth,
                          double weight, double k, uint64_t *rays, double out[3])
{
    vec3 d = ideal;
    if (m->glossy)
        d = glossy_direction(th, v3_normalize(ideal), m->lobe);
    if (m->glossy && !(side * v3_dot(d, n) > 0))
        return;
    csg_ray r = {origin, d, 0, INFINITY};
    double c[3];
    (*rays)++;
    shade_ray(s, th, &r, NULL, depth + 1, weight * k, c);
    for (int j = 0; j < 3; j++)
        out[j] += k * c[j];
}

void shade_ray(const shade_scene *s, shade_thread *th, const csg_ray *ray,
               const shade_hit *known, int depth, double weight, double out[3])
{
    shade_hit found;
    const shade_hit *hit = known;
    if (!hit) {
        if (!shade_first_hit(s, th, ray, &found)) {
            memcpy(out, s->background, 3 * sizeof *out);
            return;
        }
        hit = &found;
    }
    const csg_leaf *leaf = &s->tree->leaves[hit->hit.leaf];
    const shade_material *m =
        &s->materials[leaf->material < s->material_count ? leaf->material : 0];
    double dlen = v3_length(ray->d);
    vec3 dir = v3_scale(ray->d, 1.0 / dlen); /* unit ray direction */
    vec3 p = v3_madd(ray->o, ray->d, hit->hit.t);
    vec3 outward = shade_hit_normal(s, ray, hit);
    int leaving = v3_dot(outward, dir) > 0; /* the ray goes from inside to outside */
    vec3 n = leaving ? v3_neg(outward) : outward; /* faces the incoming ray */
    vec3 v = v3_neg(dir);
    double offset = offset_at(s, p, hit->hit.t * dlen);
    vec3 above = v3_madd(p, n, offset); /* on the incoming ray's side */
    vec3 below = v3_madd(p, n, -offset);

    double base[3];
    if (hit->cap && !s->flat) {
        double dim = s->hatch && on_hatch(s, hit->cap_normal, p) ? 0.25 : 1.0;
        for (int k = 0; k < 3; k++)
            base[k] = dim * s->cap_color[k];
    } else if (s->scheme_faces &&
               (s->leaf_side && s->leaf_side[hit->hit.leaf] != SHADE_SIDE_FLIP
                    ? s->leaf_side[hit->hit.leaf] == SHADE_SIDE_BACK
                    : hit->hit.flip)) {
        memcpy(base, &s->leaf_back[3 * hit->hit.leaf], sizeof base);
    } else {
        base_color(s, m, hit->hit.leaf, v3_madd(p, outward, -1e-6 * m->checker), base);
    }
    if (s->flat) {
        memcpy(out, base, sizeof base);
        return;
    } else if (s->lighting != SHADE_LIGHTING_OWN) {
        openscad_light(s, base, n, out);
    } else {
        for (int k = 0; k < 3; k++)
            out[k] = m->ambient * base[k];
        direct_light(s, th, m, base, p, n, v, above, out);
    }
    if (s->ao_samples > 0) {
        double visible = ambient_visibility(s, th, n, above);
        for (int k = 0; k < 3; k++)
            out[k] *= visible;
    }

    if (depth >= s->max_depth || hit->cap)
        return;
    double kr = m->reflect, kt = m->transmit;
    vec3 refracted = v3(0, 0, 0);
    if (kt > 0) {
        double n1 = leaving ? m->ior : 1.0, n2 = leaving ? 1.0 : m->ior;
        double eta = n1 / n2;
        double cos_i = fmin(1.0, v3_dot(n, v));
        double k = 1 - eta * eta * (1 - cos_i * cos_i);
        if (k < 0) { /* total internal reflection */
            kr += kt;
            kt = 0;
        } else {
            double cos_t = sqrt(k);
            refracted = v3_madd(v3_scale(dir, eta), n, eta * cos_i - cos_t);
            double r0 = (n1 - n2) / (n1 + n2);
            r0 *= r0;
            double c = 1 - (n1 > n2 ? cos_t : cos_i);
            /* Equal indices make no interface: the exact Fresnel terms
             * vanish at every angle, where Schlick's would not. */
            double fresnel = n1 == n2 ? 0 : r0 + (1 - r0) * c * c * c * c * c;
            kr += kt * fresnel;
            kt *= 1 - fresnel;
        }
    }
    if (kr * weight > SHADE_CUTOFF) {
        vec3 mirror = v3_madd(dir, n, 2 * v3_dot(n, v));
        secondary_ray(s, th, m, above, mirror, n, 1, depth, weight, kr,
                      &th->count.reflection_rays, out);
    }
    if (kt * weight > SHADE_CUTOFF)
        secondary_ray(s, th, m, below, refracted, n, -1, depth, weight, kt,
                      &th->count.refraction_rays, out);
}
