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
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "formats/color.h"
#include "render/render.h"

/* The default rig, as directions towards the lights in camera coordinates
 * (right, up, towards the viewer) and intensities. */
static const double key_light[3] = {-0.5, 0.6, 0.8};
static const double fill_light[3] = {0.6, -0.3, 0.7};
static const double key_intensity = 0.8;
static const double fill_intensity = 0.3;

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

sc_status shade_prepare(shade_scene *s, const csg_tree *tree, const shading *look,
                        const camera *cam, int max_depth, sc_error *error)
{
    memset(s, 0, sizeof *s);
    s->tree = tree;
    s->max_depth = max_depth;
    uint32_t materials = look ? look->material_count : 1;
    uint32_t lights = look && look->light_count ? look->light_count : 2;
    s->materials = calloc(materials, sizeof *s->materials);
    s->lights = calloc(lights, sizeof *s->lights);
    s->leaf_color = calloc((size_t)tree->leaf_count * 3 + 3, sizeof *s->leaf_color);
    if (!s->materials || !s->lights || !s->leaf_color) {
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
    }
    for (uint32_t i = 0; i < tree->leaf_count; i++)
        linear3(tree->leaves[i].color, 1, &s->leaf_color[3 * i]);
    s->light_count = lights;
    if (look && look->light_count) {
        for (uint32_t i = 0; i < lights; i++) {
            const shading_light *in = &look->lights[i];
            shade_light *out = &s->lights[i];
            out->directional = in->kind == SHADING_LIGHT_DIRECTIONAL;
            out->position = in->position;
            out->to_light = v3_neg(in->direction);
            out->radius = in->radius;
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
    linear3(look && look->has_background ? look->background : default_background, 1,
            s->background);
    return SC_OK;
}

void shade_release(shade_scene *s)
{
    free(s->materials);
    free(s->lights);
    free(s->leaf_color);
    memset(s, 0, sizeof *s);
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
        if (light->directional) {
            l = light->to_light;
            shadow.d = l;
            shadow.tmax = INFINITY;
        } else {
            vec3 target = light->position;
            if (light->radius > 0) {
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
        }
        double nl = v3_dot(n, l);
        if (!(nl > 0))
            continue;
        th->count.shadow_rays++;
        if (csg_any_hit_counted(s->tree, &shadow, th->scratch, th->csg))
            continue;
        double highlight = 0;
        if (m->specular > 0) {
            vec3 h = v3_normalize(v3_add(l, v));
            highlight = m->specular * pow(fmax(0.0, v3_dot(n, h)), m->shininess);
        }
        for (int k = 0; k < 3; k++)
            out[k] += light->color[k] * (m->diffuse * base[k] * nl + highlight);
    }
}

void shade_ray(const shade_scene *s, shade_thread *th, const csg_ray *ray,
               const csg_hit *known, int depth, double weight, double out[3])
{
    csg_hit found;
    const csg_hit *hit = known;
    if (!hit) {
        if (!csg_first_hit_counted(s->tree, ray, th->scratch, th->csg, &found)) {
            memcpy(out, s->background, 3 * sizeof *out);
            return;
        }
        hit = &found;
    }
    const csg_leaf *leaf = &s->tree->leaves[hit->leaf];
    const shade_material *m =
        &s->materials[leaf->material < s->material_count ? leaf->material : 0];
    double dlen = v3_length(ray->d);
    vec3 dir = v3_scale(ray->d, 1.0 / dlen); /* unit ray direction */
    vec3 p = v3_madd(ray->o, ray->d, hit->t);
    vec3 outward = csg_hit_normal(s->tree, ray, hit);
    int leaving = v3_dot(outward, dir) > 0; /* the ray goes from inside to outside */
    vec3 n = leaving ? v3_neg(outward) : outward; /* faces the incoming ray */
    vec3 v = v3_neg(dir);
    double offset = offset_at(s, p, hit->t * dlen);
    vec3 above = v3_madd(p, n, offset); /* on the incoming ray's side */
    vec3 below = v3_madd(p, n, -offset);

    double base[3];
    base_color(s, m, hit->leaf, v3_madd(p, outward, -1e-6 * m->checker), base);
    for (int k = 0; k < 3; k++)
        out[k] = m->ambient * base[k];
    direct_light(s, th, m, base, p, n, v, above, out);

    if (depth >= s->max_depth)
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
        csg_ray r = {above, v3_madd(dir, n, 2 * v3_dot(n, v)), 0, INFINITY};
        double c[3];
        th->count.reflection_rays++;
        shade_ray(s, th, &r, NULL, depth + 1, weight * kr, c);
        for (int k = 0; k < 3; k++)
            out[k] += kr * c[k];
    }
    if (kt * weight > SHADE_CUTOFF) {
        csg_ray r = {below, refracted, 0, INFINITY};
        double c[3];
        th->count.refraction_rays++;
        shade_ray(s, th, &r, NULL, depth + 1, weight * kt, c);
        for (int k = 0; k < 3; k++)
            out[k] += kt * c[k];
    }
}
