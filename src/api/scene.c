/* Loading a scene: the public sc_scene_* calls.
 *
 * sc_scene_load reads a mesh file (.stl, .off) as the model that imports
 * it (sc_scene_load_mesh), and any other file whole into memory and, like
 * sc_scene_load_string, runs the scene stages (parse, lower, build) and
 * keeps only their result: the compiled CSG tree and the warnings. Each
 * stage's input is freed as soon as the stages after it no longer need it
 * (load, below). The scene owns a copy of the file name, which every source
 * location in the tree points to.
 */
#define _POSIX_C_SOURCE 200809L /* fileno */
#include "build/scene.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "api/mesh_model.h"
#include "api/options.h"
#include "base/error.h"
#include "base/mem.h"
#include "base/sized.h"
#include "build/build.h"
#include "build/build_text.h"
#include "model/model.h"
#include "syntax/parse.h"

void sc_load_options_init_size(sc_load_options *options, size_t size)
{
    if (options && size >= sizeof options->size)
        sized_clear(options, size);
}

static char *copy_string(const char *s)
{
    size_t n = strlen(s);
    char *c = malloc(n + 1);
    if (c)
        memcpy(c, s, n + 1);
    return c;
}

/* The three stages, each stage's input freed as soon as the next one no
 * longer needs it: parsing and lowering run as one stream (parse_stream
 * with model_stream's sink), so a node's syntax is freed as soon as it is
 * lowered and the whole syntax tree never exists (a million positioned
 * spheres: 141 MB of text, 350 MB of model, 400 MB of tree, where the
 * syntax alone took 1.1 GB); then the text when owned_text is set (the
 * caller's buffer, which this frees); the model once the build has walked
 * it, before the tree is compiled; the names and strings it points to
 * after the build. */
static sc_status load(const char *name, const char *text, size_t length, char *owned_text,
                      const sc_load_options *options, int more_flags, sc_scene **scene,
                      sc_error *error)
{
    err_clear(error);
    if (!scene) {
        free(owned_text);
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no scene pointer");
    }
    *scene = NULL;
    if (!text && length) {
        free(owned_text);
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no text to load");
    }
    sc_load_options own;
    sc_status st = options_load(options, &own, error);
    if (st != SC_OK) {
        free(owned_text);
        return st;
    }
    sc_scene *s = calloc(1, sizeof *s);
    if (!s || !(s->path = copy_string(name ? name : "<string>"))) {
        free(s);
        free(owned_text);
        return err_nomem(error, NULL);
    }
    parse_tree *syntax = NULL;
    model *typed = NULL;
    model_stream *lowering;
    st = model_stream_new(s->path, &lowering, error);
    if (st == SC_OK) {
        parse_sink sink = model_stream_sink(lowering);
        /* a large text is read in two threads where there are two */
        if (options_thread_count(own.threads) >= 2)
            sink.split_min = PARSE_SPLIT_MIN;
        st = parse_stream(s->path, text ? text : "", length, &sink, &syntax, error);
        if (st == SC_OK)
            st = model_stream_finish(lowering, &typed);
        else
            model_stream_free(lowering);
    }
    /* The model goes during the build, once walked and before the tree is
     * compiled (build_scene_take); the text, read and no longer needed,
     * goes at its start, its pages kept for the leaves where they serve. */
    if (st == SC_OK && own.openscad_export)
        typed->notes.count = 0;
    if (st == SC_OK) {
        int threads = options_threads_begin(own.threads);
        st = build_scene_take(typed, owned_text, owned_text ? length : 0,
                              options_build_flags(&own) | more_flags, own.max_triangles,
                              &s->tree, &s->look, &s->warnings, &s->warning_count, error);
        options_threads_end(threads);
    } else {
        free(owned_text);
        model_free(typed);
    }
    parse_tree_free(syntax);
    if (st != SC_OK) {
        char what[64];
        snprintf(what, sizeof what, "loading '%.48s'", s->path);
        mem_blame(error, what);
        sc_scene_release(s);
        return st;
    }
    *scene = s;
    return SC_OK;
}

sc_status sc_font_register(const char *path, sc_error *error)
{
    if (!path)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "sc_font_register needs a path");
    return text_register_font(path, error);
}

sc_status sc_scene_load_string(const char *name, const char *text, size_t length,
                               const sc_load_options *options, sc_scene **scene,
                               sc_error *error)
{
    return load(name, text, length, NULL, options, 0, scene, error);
}

sc_status mesh_model_load(const char *name, const char *text, size_t length,
                          const sc_load_options *options, sc_scene **scene,
                          sc_error *error)
{
    return load(name, text, length, NULL, options, BUILD_MESH_MODEL, scene, error);
}

/* Reads a whole file into a malloc'd buffer. */
static sc_status read_file(const char *path, char **text, size_t *length, sc_error *error)
{
    *text = NULL;
    *length = 0;
    FILE *f = fopen(path, "rb");
    if (!f)
        return err_set(error, SC_ERR_IO, NULL, "cannot open '%s': %s", path,
                       strerror(errno));
    /* A regular file is read into one buffer of its size (one byte more, to
     * see the end); anything else, or a file that grows meanwhile, doubles
     * the buffer as it goes. */
    size_t cap = 0, n = 0;
    char *buf = NULL;
    struct stat info;
    if (fstat(fileno(f), &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0 &&
        (uintmax_t)info.st_size < SIZE_MAX) {
        cap = (size_t)info.st_size + 1;
        if (!(buf = malloc(cap))) {
            fclose(f);
            return err_nomem(error, NULL);
        }
        mem_advise_huge(buf, cap); /* read straight into: fewer first-touch faults */
    }
    for (;;) {
        if (n == cap) {
            size_t next = cap ? cap * 2 : 64 * 1024;
            char *p = next > cap ? realloc(buf, next) : NULL;
            if (!p) {
                free(buf);
                fclose(f);
                return err_nomem(error, NULL);
            }
            buf = p;
            cap = next;
        }
        size_t got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (got == 0) {
            if (ferror(f)) {
                int code = errno;
                free(buf);
                fclose(f);
                return err_set(error, SC_ERR_IO, NULL, "cannot read '%s': %s", path,
                               strerror(code));
            }
            break;
        }
    }
    fclose(f);
    *text = buf;
    *length = n;
    return SC_OK;
}

sc_status sc_scene_load(const char *path, const sc_load_options *options,
                        sc_scene **scene, sc_error *error)
{
    err_clear(error);
    if (!scene)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no scene pointer");
    *scene = NULL;
    if (!path)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no file name");
    if (mesh_model_is_mesh(path))
        return sc_scene_load_mesh(path, options, scene, error);
    char *text;
    size_t length;
    sc_status st = read_file(path, &text, &length, error);
    if (st != SC_OK)
        return st;
    return load(path, text, length, text, options, 0, scene, error);
}

void sc_scene_release(sc_scene *scene)
{
    if (!scene)
        return;
    csg_tree_free(scene->tree);
    shading_free(scene->look);
    free(scene->path);
    free(scene->warnings);
    free(scene);
}

int sc_scene_bounds(const sc_scene *scene, double lo[3], double hi[3])
{
    const csg_tree *t = scene->tree;
    if (!t || t->root == CSG_EMPTY || bbox_is_empty(&t->bounds)) {
        for (int i = 0; i < 3; i++)
            lo[i] = hi[i] = 0;
        return 0;
    }
    lo[0] = t->bounds.lo.x;
    lo[1] = t->bounds.lo.y;
    lo[2] = t->bounds.lo.z;
    hi[0] = t->bounds.hi.x;
    hi[1] = t->bounds.hi.y;
    hi[2] = t->bounds.hi.z;
    return 1;
}

size_t sc_scene_warning_count(const sc_scene *scene)
{
    return scene->warning_count;
}

const sc_error *sc_scene_warning(const sc_scene *scene, size_t index)
{
    return index < scene->warning_count ? &scene->warnings[index] : NULL;
}

/* The compiled tree holds only what its root reaches, so its arrays are
 * the counts; the source figures were measured when it was compiled. */
static void scene_info(const sc_scene *scene, sc_scene_info *info);

void sc_scene_info_init_size(sc_scene_info *info, size_t size)
{
    if (info && size >= sizeof info->size)
        sized_clear(info, size);
}

sc_status sc_scene_get_info(const sc_scene *scene, sc_scene_info *out, sc_error *error)
{
    if (!scene || !out)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "sc_scene_get_info needs a scene and a result");
    sc_scene_info info;
    scene_info(scene, &info);
    return sized_write(out, &info, sizeof info, SIZED_MIN(sc_scene_info, checker_leaves),
                       "sc_scene_info", error);
}

/* Counts n leaves of material m as mirror, glass and checkered. */
static void count_material(sc_scene_info *info, const shading_material *m, uint32_t n)
{
    info->mirror_leaves += m->reflect > 0 ? n : 0;
    info->glass_leaves += m->transmit > 0 ? n : 0;
    info->checker_leaves += m->checker > 0 ? n : 0;
}

/* The statistics of sc_scene_get_info, into the library's full struct. */
static void scene_info(const sc_scene *scene, sc_scene_info *info)
{
    sc_scene_info_init(info);
    const csg_tree *t = scene->tree;
    if (!t || t->root == CSG_EMPTY)
        return;
    info->node_count = t->node_count;
    info->leaf_count = t->leaf_count;
    info->depth = t->depth;
    info->source_node_count = t->source_node_count;
    info->source_leaf_count = t->source_leaf_count;
    info->source_depth = t->source_depth;
    info->bvh_node_count = t->bvh_node_count;
    const shading *look = scene->look;
    info->lights = look ? look->light_count : 0;
    info->flat_2d = look && look->flat_2d;
    if (t->leaf_counts) { /* counted as the leaves were made */
        for (int k = 0; k < PRIM_KIND_COUNT && k < SC_LEAF_KINDS; k++)
            info->leaf_kinds[k] = t->kind_leaves[k];
        uint32_t materials = look ? look->material_count : 0;
        for (uint32_t m = 0; m < t->material_slots && m < materials; m++)
            count_material(info, &look->materials[m], t->material_leaves[m]);
        return;
    }
    for (uint32_t i = 0; i < t->leaf_count; i++) {
        const csg_leaf *l = &t->leaves[i];
        if ((int)l->prim.kind < SC_LEAF_KINDS)
            info->leaf_kinds[l->prim.kind]++;
        if (look && l->material < look->material_count)
            count_material(info, &look->materials[l->material], 1);
    }
}
