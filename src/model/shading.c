/* The shading record of a scene: see shading.h. Plain growable arrays;
 * nothing here is used while rendering except by reading. */
#include "base/grow.h"
#include "model/shading.h"

#include <stdlib.h>
#include <string.h>

shading_material shading_default_material(void)
{
    shading_material m;
    memset(&m, 0, sizeof m);
    m.ambient = SHADING_DEFAULT_AMBIENT;
    m.diffuse = SHADING_DEFAULT_DIFFUSE;
    m.specular = SHADING_DEFAULT_SPECULAR;
    m.shininess = SHADING_DEFAULT_SHININESS;
    m.ior = SHADING_DEFAULT_IOR;
    return m;
}

shading *shading_new(void)
{
    shading *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    shading_material m = shading_default_material();
    if (shading_add_material(s, &m) == UINT32_MAX) {
        shading_free(s);
        return NULL;
    }
    return s;
}

size_t shading_find_id(const void *items, size_t count, size_t stride, size_t offset,
                       uint32_t id)
{
    const unsigned char *base = items;
    size_t lo = 0, hi = count;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        uint32_t key;
        memcpy(&key, base + mid * stride + offset, sizeof key);
        if (key < id)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

void shading_free(shading *s)
{
    if (!s)
        return;
    free(s->lights);
    free(s->materials);
    for (int k = 0; k < SHADING_OVERLAYS; k++)
        csg_tree_free(s->overlay[k]);
    csg_tree_free(s->preview_solid);
    free(s->preview_swapped);
    free(s->preview_slabs.items);
    free(s->preview_renders.items);
    free(s->flat_points);
    free(s->flat_start);
    for (int k = 0; k < SHADING_OVERLAYS; k++) {
        free(s->overlay_slabs[k].items);
        free(s->overlay_renders[k].items);
    }
    free(s);
}

int shading_add_light(shading *s, const shading_light *light)
{
    if (!grow_array32((void **)&s->lights, &s->light_cap, s->light_count + 1,
                      sizeof *light))
        return 0;
    s->lights[s->light_count++] = *light;
    return 1;
}

uint32_t shading_add_material(shading *s, const shading_material *material)
{
    if (!grow_array32((void **)&s->materials, &s->material_cap, s->material_count + 1,
                      sizeof *material))
        return UINT32_MAX;
    s->materials[s->material_count] = *material;
    return s->material_count++;
}
