/* The library's side of the sized structs of the public API
 * (include/spancast/spancast.h, "Stable API"): every options or results
 * struct starts with `size_t size`, the size of the struct as the caller
 * was compiled with it. A caller built against an older header passes a
 * shorter struct, one built against a newer header a longer one. The
 * library reads options through sized_read into a full struct of its own
 * (fields the caller's struct ends before keep their defaults), and fills
 * results through sized_write (never past the caller's size), so a struct
 * can grow at its end without breaking a program built before. */
#ifndef SPANCAST_BASE_SIZED_H
#define SPANCAST_BASE_SIZED_H

#include <stddef.h>

#include "spancast/spancast.h"

/* The size a struct had when the ABI was first recorded (abi/), up to and
 * including its field last: a caller's struct is never shorter. */
#define SIZED_MIN(type, last) (offsetof(type, last) + sizeof(((type *)0)->last))

/* Reads the caller's options into dst: dst holds the library's defaults
 * (size dst_size, its own size field included); the first size bytes of
 * src replace them, and dst's size field becomes dst_size. A size below
 * min_size (an uninitialised struct) or above dst_size (options from a
 * newer spancast this library cannot honour) is SC_ERR_ARGUMENT naming
 * type. */
sc_status sized_read(void *dst, size_t dst_size, const void *src, size_t min_size,
                     const char *type, sc_error *error);

/* SC_ERR_ARGUMENT naming type when the size field of the caller's struct
 * p is below min_size (it was never set up), else SC_OK. */
sc_status sized_check(const void *p, size_t min_size, const char *type, sc_error *error);

/* Copies the library's full result src (size src_size) into the caller's
 * dst, no further than dst's size field says, keeping that field. A size
 * below min_size is SC_ERR_ARGUMENT naming type, and dst is left alone. */
sc_status sized_write(void *dst, const void *src, size_t src_size, size_t min_size,
                      const char *type, sc_error *error);

/* Zeroes size bytes of p and stores size in its size field: the init
 * functions of results structs, and the start of those of options. */
void sized_clear(void *p, size_t size);

#endif
