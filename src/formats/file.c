/* Whole-file reading for the file formats (meshes, height maps, DXF):
 * one bounded read into memory, with the reason of a failure as text. And
 * the path of a file installed beside the running program.
 */
#define _POSIX_C_SOURCE 200809L /* readlink */

#include "formats/file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

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

int file_beside_program(const char *name, char *path, size_t size)
{
    if (size < 2) {
        errno = ENAMETOOLONG;
        return 0;
    }
    ssize_t length = readlink("/proc/self/exe", path, size - 1);
    if (length <= 0) {
        if (length == 0)
            errno = ENOENT;
        return 0;
    }
    path[length] = '\0';
    /* Keep the folder up to its last slash ("/" for a program at the root). */
    char *slash = strrchr(path, '/');
    size_t folder = slash ? (size_t)(slash - path) + 1 : 0;
    if (folder + strlen(name) + 1 > size) {
        errno = ENAMETOOLONG;
        return 0;
    }
    strcpy(path + folder, name);
    return 1;
}
