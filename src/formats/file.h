/* Whole-file reading for the file formats, and the files installed beside
 * the running program (file.c). */
#ifndef SPANCAST_FORMATS_FILE_H
#define SPANCAST_FORMATS_FILE_H

#include <stddef.h>

/* Reads a whole file of at most about limit bytes into a malloc'd,
 * NUL-terminated buffer (the caller frees it); returns NULL and sets *why
 * (strerror's text, "file is too large", "out of memory" or "read error")
 * on failure. */
char *file_read(const char *path, size_t limit, size_t *size, const char **why);

/* Writes into path (size bytes) the path of the helper file called name
 * (spancast-oiio.so, spancast-bench): the first that exists of the folder
 * of the running executable (/proc/self/exe; the build tree), the helpers'
 * folder of an installed tool (bin/../LIBDIR/spancast) and that of the
 * installed shared library the code runs in (LIBDIR/spancast); when none
 * exists, the first. Returns 1, or 0 when no path can be formed (errno says
 * why) or the result does not fit (errno ENAMETOOLONG). */
int file_beside_program(const char *name, char *path, size_t size);

#endif
