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

/* Writes into path (size bytes) the path of the file called name in the
 * folder of the running executable (/proc/self/exe): where the tool finds
 * spancast-oiio.so and spancast-bench. Returns 1, or 0 when the executable's
 * path cannot be read (errno says why) or the result does not fit (errno
 * ENAMETOOLONG). */
int file_beside_program(const char *name, char *path, size_t size);

#endif
