/* The CGAL solids of one build, by subtree (build_nef_cache.c): a
 * difference or intersection that hull(), minkowski() or projection()
 * evaluates with CGAL is evaluated once per build, however many times its
 * subtree occurs, as OpenSCAD 2021.01 caches a subtree's geometry by the
 * subtree's text. See docs/hull.md.
 */
#ifndef SPANCAST_BUILD_BUILD_NEF_CACHE_H
#define SPANCAST_BUILD_BUILD_NEF_CACHE_H

#include <stddef.h>
#include <stdint.h>

#include "build/nef.h"
#include "model/model.h"

/* The solids, keyed by the structure of their subtrees. Owned by the
 * build (build_nef_cache_free); it holds the CGAL plugin open from its
 * first solid to its end. */
typedef struct build_nef_cache build_nef_cache;

/* A new empty cache, or NULL when memory runs out. */
build_nef_cache *build_nef_cache_new(void);

/* Releases every solid and the cache (NULL: nothing). */
void build_nef_cache_free(build_nef_cache *cache);

/* The key of subtree n in *hash: returns 1, or 0 when the subtree holds a
 * node the cache does not compare (an import, a material, a node with an
 * argument error, ...), which is then evaluated each time. Two subtrees
 * with the same key are compared in full before one stands for the
 * other. */
int build_nef_cache_key(const model_node *n, uint64_t *hash);

/* The solid of a subtree equal to n (key hash), in n's own frame, in
 * *solid (NULL for the empty solid; still the cache's): returns 1, or 0
 * when there is none yet, or when the equal subtree is one whose parent
 * has not finished (build_nef_cache_publish), as OpenSCAD caches a
 * subtree only once its parent has all its children. */
int build_nef_cache_find(build_nef_cache *cache, const model_node *n, uint64_t hash,
                         const nef_solid **solid);

/* Counts one evaluation of n (key hash) and, with keep, records solid
 * (NULL: empty) as its solid, not found until published. The cache takes
 * solid, and releases it at once without keep or when an equal subtree
 * is recorded already. plugin is the caller's open plugin. Returns 0 when
 * memory runs out or the plugin does not load again (solid released
 * then). */
int build_nef_cache_put(build_nef_cache *cache, const model_node *n, uint64_t hash,
                        nef_solid *solid, int keep, const nef_plugin *plugin);

/* The number of solids recorded so far: the mark of a parent's start. */
size_t build_nef_cache_mark(const build_nef_cache *cache);

/* Makes the solids recorded since mark found: called when their parent
 * has all its children. */
void build_nef_cache_publish(build_nef_cache *cache, size_t mark);

/* Solids evaluated (recorded) and reused (found) so far. */
void build_nef_cache_counts(const build_nef_cache *cache, size_t *evaluated,
                            size_t *reused);

#endif
