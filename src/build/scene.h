/* The loaded scene: what sc_scene_load hands to the renderer.
 *
 * It owns the compiled CSG tree, the file name strings that source
 * locations point into, the warnings collected while loading, and the
 * shading record (lights, materials, camera, background: shading.h).
 */
#ifndef SPANCAST_BUILD_SCENE_H
#define SPANCAST_BUILD_SCENE_H

#include "csg/csg.h"
#include "model/shading.h"
#include "spancast/spancast.h"

struct sc_scene {
    csg_tree *tree;     /* never NULL after a successful load */
    shading *look;      /* lights, materials, camera, background; never NULL */
    char *path;         /* the file name used in locations, owned */
    sc_error *warnings; /* malloc'd array */
    size_t warning_count;
};

static inline const csg_tree *scene_tree(const sc_scene *s)
{
    return s->tree;
}

static inline const shading *scene_shading(const sc_scene *s)
{
    return s->look;
}

#endif
