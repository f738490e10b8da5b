/* Sized structs of the public API: see sized.h. */
#include "base/sized.h"

#include <string.h>

#include "base/error.h"

static size_t size_of(const void *p)
{
    size_t size;
    memcpy(&size, p, sizeof size);
    return size;
}

sc_status sized_check(const void *p, size_t min_size, const char *type, sc_error *error)
{
    size_t size = size_of(p);
    if (size < min_size)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "%s has size %zu, less than the %zu of any release: it was not "
                       "set up by %s_init",
                       type, size, min_size, type);
    return SC_OK;
}

sc_status sized_read(void *dst, size_t dst_size, const void *src, size_t min_size,
                     const char *type, sc_error *error)
{
    sc_status st = sized_check(src, min_size, type, error);
    if (st != SC_OK)
        return st;
    size_t size = size_of(src);
    if (size > dst_size)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "%s has size %zu: it comes from a newer spancast than this "
                       "library %s, which knows %zu bytes of it",
                       type, size, SPANCAST_VERSION_STRING, dst_size);
    memcpy(dst, src, size);
    memcpy(dst, &dst_size, sizeof dst_size);
    return SC_OK;
}

sc_status sized_write(void *dst, const void *src, size_t src_size, size_t min_size,
                      const char *type, sc_error *error)
{
    sc_status st = sized_check(dst, min_size, type, error);
    if (st != SC_OK)
        return st;
    size_t size = size_of(dst);
    size_t n = size < src_size ? size : src_size;
    memcpy((char *)dst + sizeof size, (const char *)src + sizeof size, n - sizeof size);
    return SC_OK;
}

void sized_clear(void *p, size_t size)
{
    memset(p, 0, size);
    memcpy(p, &size, sizeof size);
}
