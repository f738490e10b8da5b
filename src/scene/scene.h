/* The loaded scene: what sc_scene_load hands to the renderer.
 *
 * It owns the compiled CSG tree, the file name strings that source
 * locations point into, and the warnings collected while loading. Camera,
 * lights and materials from the file join it with their issues.
 */
#ifndef SPANCAST_SCENE_SCENE_H
#define SPANCAST_SCENE_SCENE_H

#include "csg/csg.h"
#include "spancast/spancast.h"

struct sc_scene {
    csg_tree *tree;     /* never NULL after a successful load */
    char *path;         /* the file name used in locations, owned */
    sc_error *warnings; /* malloc'd array */
    size_t warning_count;
};

static inline const csg_tree *scene_tree(const sc_scene *s)
{
    return s->tree;
}

#endif
