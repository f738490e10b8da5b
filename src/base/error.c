/* sc_error helpers: see error.h. */
#include "base/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "base/mem.h"

static void copy_string(char *dst, size_t size, const char *src)
{
    size_t n = strlen(src);
    if (n >= size)
        n = size - 1;
    memcpy(dst, src, n);
    dst[n] = '\0';
}

sc_status err_set(sc_error *error, sc_status status, const sc_location *loc,
                  const char *format, ...)
{
    if (!error)
        return status;
    error->status = status;
    error->file[0] = '\0';
    error->line = 0;
    error->column = 0;
    if (loc) {
        if (loc->file)
            copy_string(error->file, sizeof error->file, loc->file);
        error->line = loc->line;
        error->column = loc->column;
    }
    va_list args;
    va_start(args, format);
    vsnprintf(error->message, sizeof error->message, format, args);
    va_end(args);
    return status;
}

void err_clear(sc_error *error)
{
    if (!error)
        return;
    memset(error, 0, sizeof *error);
    error->status = SC_OK;
}

const char *sc_error_format(const sc_error *error, char *buf, size_t size)
{
    if (!buf || size == 0)
        return buf;
    if (error->file[0] && error->line > 0)
        snprintf(buf, size, "%s:%d:%d: error: %s", error->file, error->line,
                 error->column, error->message);
    else if (error->file[0])
        snprintf(buf, size, "%s: error: %s", error->file, error->message);
    else
        snprintf(buf, size, "error: %s", error->message);
    return buf;
}

sc_status err_nomem(sc_error *error, const sc_location *loc)
{
    uint64_t limit = mem_limit();
    if (!limit)
        return err_set(error, SC_ERR_NOMEM, loc, "out of memory");
    char text[32];
    return err_set(error, SC_ERR_NOMEM, loc,
                   "out of memory (the memory limit of %s is reached)",
                   mem_format(limit, text, sizeof text));
}
