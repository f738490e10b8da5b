/* Names of the primitive kinds, for `spancast info` and messages. */
#include "csg/prim.h"
#include "spancast/spancast.h"

const char *prim_kind_name(prim_kind kind)
{
    switch (kind) {
    case PRIM_SPHERE:
        return "sphere";
    case PRIM_BOX:
        return "box";
    case PRIM_CYLINDER:
        return "cylinder";
    case PRIM_CONVEX:
        return "convex polyhedron";
    case PRIM_TORUS:
        return "torus";
    case PRIM_QUADRIC:
        return "quadric";
    case PRIM_IMPLICIT:
        return "implicit";
    case PRIM_MESH:
        return "mesh";
    case PRIM_REVOLVE:
        return "revolve";
    case PRIM_EXTRUSION:
        return "extrusion";
    case PRIM_OUTLINE:
        return "outline";
    case PRIM_KIND_COUNT:
        break;
    }
    return NULL;
}

const char *sc_leaf_kind_name(int k)
{
    if (k < 0 || k >= PRIM_KIND_COUNT || k >= SC_LEAF_KINDS)
        return NULL;
    return prim_kind_name((prim_kind)k);
}
