/* The builder's handlers for spancast's shading nodes (build_shading.c;
 * the lowering pass reads them, model/lower_shading.c):
 *
 *   light(position = [x, y, z] | direction = [x, y, z], color = [r, g, b],
 *         intensity = 1, radius = 0);
 *   material(color = [r, g, b], ambient, diffuse, specular, shininess,
 *            reflect, transmit, ior, checker = SIZE, color2 = [r, g, b])
 *            { children }
 *   camera(eye = [...], center = [...], up = [0, 0, 1], fov = 22.5,
 *          projection = "perspective" | "orthographic");
 *   background(color = [r, g, b]);
 *
 * A light's position and direction (and its radius, by the transform's
 * largest axis scale) go through the transforms above it; camera and
 * background are in world coordinates wherever they are written, and the
 * last of each in file order wins. Colours are vectors or OpenSCAD colour
 * names. Nodes that are not built ('%', outside a '!') are still checked but
 * add nothing. Each handler returns SC_OK or fills error with the node's or
 * the value's position.
 */
#ifndef SPANCAST_BUILD_BUILD_SHADING_H
#define SPANCAST_BUILD_BUILD_SHADING_H

#include "math/vec.h"
#include "model/model.h"
#include "model/shading.h"
#include "spancast/spancast.h"

/* light, camera and background, where the node is built (emit): a light
 * placed by to_world; the last camera and background win. */
sc_status build_light(shading *s, const model_node *n, const affine *to_world, int emit,
                      sc_error *error);
void build_camera(shading *s, const model_node *n, int emit);
void build_background(shading *s, const model_node *n, int emit);

/* material: adds a material (when emit) and makes it the one its children
 * inherit (*material); a given colour replaces color (RGBA, alpha 1),
 * unless color is NULL (a colour above it is set and wins). */
sc_status build_material(shading *s, const model_node *n, int emit, uint32_t *material,
                         float color[4], sc_error *error);

#endif
