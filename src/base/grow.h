/* Growable arrays: the one rule every module's dynamic arrays follow.
 *
 * The capacity doubles (from 16) until it holds need items; size arithmetic
 * is checked, and on overflow or allocation failure the array is left as it
 * was and 0 is returned. The 32-bit form keeps the capacity below
 * UINT32_MAX, which several modules use as a "none" index.
 */
#ifndef SPANCAST_BASE_GROW_H
#define SPANCAST_BASE_GROW_H

#include <stddef.h>
#include <stdint.h>

int grow_array(void **array, size_t *cap, size_t need, size_t elem);
int grow_array32(void **array, uint32_t *cap, uint32_t need, size_t elem);

#endif
