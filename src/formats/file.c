/* Whole-file reading for the file formats (meshes, height maps, DXF):
 * one bounded read into memory, with the reason of a failure as text. And
 * the path of a helper file (the OpenImageIO plugin, spancast-bench): beside
 * the running program in the build tree, in the helpers' folder
 * (LIBDIR/spancast) where installed. And the replacement of an output by
 * its complete temporary, through a symbolic link, keeping the mode.
 */
#define _GNU_SOURCE /* dladdr; readlink; realpath */

#include "formats/file.h"

#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

const char file_too_large[] = "file is too large";
const char file_no_memory[] = "out of memory";
const char file_read_error[] = "read error";

int file_not_opened(const char *why)
{
    return why != file_too_large && why != file_no_memory && why != file_read_error;
}

char *file_read(const char *path, size_t limit, size_t *size, const char **why)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        *why = strerror(errno);
        return NULL;
    }
    size_t len = 0, cap = limit < 65536 ? limit : 65536;
    char *buf = malloc(cap + 1);
    *why = buf ? NULL : file_no_memory;
    while (!*why) {
        if (len == cap) {
            char past; /* a full buffer of limit bytes is whole if nothing follows */
            if (cap == limit) {
                if (fread(&past, 1, 1, f) == 1)
                    *why = file_too_large;
                break;
            }
            cap = cap <= limit / 2 ? 2 * cap : limit;
            char *next = realloc(buf, cap + 1);
            if (!next) {
                *why = file_no_memory;
                break;
            }
            buf = next;
        }
        size_t got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0)
            break;
    }
    if (!*why && ferror(f))
        *why = file_read_error;
    fclose(f);
    if (*why) {
        free(buf);
        return NULL;
    }
    buf[len] = 0;
    *size = len;
    return buf;
}

/* The helpers' folder relative to the installed tool's folder (bin/ ->
 * lib/spancast) and to the installed shared library's (lib/ -> lib/spancast);
 * CMakeLists.txt sets both from the install layout. */
#ifndef SPANCAST_HELPERS_FROM_BIN
#define SPANCAST_HELPERS_FROM_BIN "../lib/spancast"
#endif
#ifndef SPANCAST_HELPERS_FROM_LIB
#define SPANCAST_HELPERS_FROM_LIB "spancast"
#endif

/* Writes folder (its first folder_length bytes), sub (when not NULL) and
 * name, joined by slashes, into path; 0 (errno ENAMETOOLONG) when it does
 * not fit. */
static int join(char *path, size_t size, const char *folder, size_t folder_length,
                const char *sub, const char *name)
{
    int n = snprintf(path, size, "%.*s/%s%s%s", (int)folder_length, folder,
                     sub ? sub : "", sub ? "/" : "", name);
    if (n < 0 || (size_t)n >= size) {
        errno = ENAMETOOLONG;
        return 0;
    }
    return 1;
}

static int exists(const char *path)
{
    return access(path, F_OK) == 0;
}

/* Any object of this library: dladdr of its address names the file the
 * code was loaded from, the shared library or the executable. */
static const char where_am_i = 0;

int file_beside_program(const char *name, char *path, size_t size)
{
    char exe[4096], candidate[4096];
    int have_exe = 0;
    ssize_t length = readlink("/proc/self/exe", exe, sizeof exe - 1);
    int readlink_errno = length < 0 ? errno : ENOENT;
    if (length > 0) {
        exe[length] = '\0';
        char *slash = strrchr(exe, '/');
        size_t folder = slash ? (size_t)(slash - exe) : 0;
        /* Beside the program: the build tree. */
        if (!join(path, size, exe, folder, NULL, name))
            return 0;
        have_exe = 1;
        if (exists(path))
            return 1;
        /* The installed tool: PREFIX/bin -> PREFIX/LIBDIR/spancast. */
        if (join(candidate, sizeof candidate, exe, folder, SPANCAST_HELPERS_FROM_BIN,
                 name) &&
            exists(candidate)) {
            if (strlen(candidate) >= size) {
                errno = ENAMETOOLONG;
                return 0;
            }
            strcpy(path, candidate);
            return 1;
        }
    }
    /* The installed shared library, in another program: PREFIX/LIBDIR ->
     * PREFIX/LIBDIR/spancast. Only an absolute name is trusted: a relative
     * one would be looked up from the current folder. */
    Dl_info info;
    if (dladdr(&where_am_i, &info) && info.dli_fname && info.dli_fname[0] == '/') {
        const char *slash = strrchr(info.dli_fname, '/');
        if (join(candidate, sizeof candidate, info.dli_fname,
                 (size_t)(slash - info.dli_fname), SPANCAST_HELPERS_FROM_LIB, name) &&
            exists(candidate) && strlen(candidate) < size) {
            strcpy(path, candidate);
            return 1;
        }
    }
    /* Nowhere: the path beside the program, for the caller's message. */
    if (have_exe)
        return 1;
    errno = readlink_errno;
    return 0;
}

char *file_output_target(const char *path)
{
    struct stat st;
    char *real = NULL;
    if (lstat(path, &st) == 0 && S_ISLNK(st.st_mode))
        real = realpath(path, NULL); /* NULL for a dangling link: replaced */
    return real ? real : strdup(path);
}

int file_replace(const char *tmp, const char *target)
{
    struct stat st;
    if (stat(target, &st) == 0 && S_ISREG(st.st_mode) &&
        chmod(tmp, st.st_mode & 07777) != 0)
        return 0;
    return rename(tmp, target) == 0;
}
