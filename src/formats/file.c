/* Whole-file reading for the file formats (meshes, height maps, DXF):
 * one bounded read into memory, with the reason of a failure as text.
 */
#include "formats/file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

char *file_read(const char *path, size_t limit, size_t *size, const char **why)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        *why = strerror(errno);
        return NULL;
    }
    char *buf = NULL;
    size_t len = 0, cap = 0;
    for (;;) {
        if (len == cap) {
            if (cap >= limit) {
                *why = "file is too large";
                free(buf);
                fclose(f);
                return NULL;
            }
            cap = cap ? 2 * cap : 65536;
            char *next = realloc(buf, cap + 1);
            if (!next) {
                *why = "out of memory";
                free(buf);
                fclose(f);
                return NULL;
            }
            buf = next;
        }
        size_t got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0)
            break;
    }
    int failed = ferror(f);
    fclose(f);
    if (failed) {
        *why = "read error";
        free(buf);
        return NULL;
    }
    buf[len] = 0;
    *size = len;
    return buf;
}
