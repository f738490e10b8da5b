/* Whole-file reading for the file formats (file.c). */
#ifndef SPANCAST_FORMATS_FILE_H
#define SPANCAST_FORMATS_FILE_H

#include <stddef.h>

/* Reads a whole file of at most about limit bytes into a malloc'd,
 * NUL-terminated buffer (the caller frees it); returns NULL and sets *why
 * (strerror's text, "file is too large", "out of memory" or "read error")
 * on failure. */
char *file_read(const char *path, size_t limit, size_t *size, const char **why);

#endif
