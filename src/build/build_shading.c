/* Placing spancast's shading nodes, read and checked by the lowering pass
 * (model/lower_shading.c), into the scene's shading record: see
 * build_shading.h. */
#include "build/build_shading.h"

#include <math.h>
#include <string.h>

#include "base/error.h"

sc_status build_light(shading *s, const model_node *n, const affine *to_world, int emit,
                      sc_error *error)
{
    if (!emit)
        return SC_OK;
    shading_light light = *n->u.light;
    if (light.kind == SHADING_LIGHT_POINT) {
        light.position = affine_point(to_world, light.position);
        /* The radius scales with the transform's largest axis. */
        double scale = 0;
        for (int k = 0; k < 3; k++) {
            vec3 axis = affine_vector(to_world, v3(k == 0, k == 1, k == 2));
            scale = fmax(scale, v3_length(axis));
        }
        light.radius *= scale;
    } else if (light.kind == SHADING_LIGHT_RECT) {
        /* The rectangle's edges map as vectors (scaled, sheared, rotated
         * with it); its lit side is the side the local normal points to,
         * which a mirroring transform mirrors too, so the normal is the
         * edges' cross product turned by the sign of the determinant. */
        light.position = affine_point(to_world, light.position);
        light.half_width = affine_vector(to_world, light.half_width);
        light.half_height = affine_vector(to_world, light.half_height);
        vec3 n = v3_normalize(v3_cross(light.half_width, light.half_height));
        light.normal = affine_det(to_world) < 0 ? v3_neg(n) : n;
    } else {
        light.direction = v3_normalize(affine_vector(to_world, light.direction));
    }
    return shading_add_light(s, &light) ? SC_OK : err_nomem(error, NULL);
}

void build_camera(shading *s, const model_node *n, int emit)
{
    if (emit) {
        s->camera = *n->u.camera;
        s->has_camera = 1;
    }
}

void build_background(shading *s, const model_node *n, int emit)
{
    if (emit) {
        memcpy(s->background, n->u.background, sizeof s->background);
        s->has_background = 1;
    }
}

sc_status build_material(shading *s, const model_node *n, int emit, uint32_t *material,
                         float color[4], sc_error *error)
{
    if (!emit)
        return SC_OK;
    uint32_t index = shading_add_material(s, &n->u.material->material);
    if (index == UINT32_MAX)
        return err_nomem(error, NULL);
    *material = index;
    if (color && n->u.material->has_color) {
        memcpy(color, n->u.material->color, sizeof n->u.material->color);
        color[3] = 1;
    }
    return SC_OK;
}
