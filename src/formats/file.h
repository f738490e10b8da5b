/* Whole-file reading for the file formats, and the files installed beside
 * the running program (file.c). */
#ifndef SPANCAST_FORMATS_FILE_H
#define SPANCAST_FORMATS_FILE_H

#include <stddef.h>

/* Reads a whole file of at most limit bytes into a malloc'd,
 * NUL-terminated buffer (the caller frees it); returns NULL and sets *why
 * on failure: strerror's text when the file does not open, else one of
 * the three reasons below, which a caller tells apart by the pointer. */
char *file_read(const char *path, size_t limit, size_t *size, const char **why);

extern const char file_too_large[];  /* "file is too large": past limit */
extern const char file_no_memory[];  /* "out of memory" */
extern const char file_read_error[]; /* "read error": opened, not read */

/* Whether file_read's why says that the file did not open (strerror's
 * text), rather than that it opened and could not be read whole. */
int file_not_opened(const char *why);

/* The file a write to path replaces (malloc'd; NULL when memory runs
 * out): the file a symbolic link names, so that the link stays a link,
 * else path itself (a dangling link is replaced). */
char *file_output_target(const char *path);

/* Moves the complete temporary tmp over target (file_output_target), with
 * the mode of the regular file it replaces; 0 with errno set on failure. */
int file_replace(const char *tmp, const char *target);

/* Writes into path (size bytes) the path of the helper file called name
 * (spancast-oiio.so, spancast-bench): the first that exists of the folder
 * of the running executable (/proc/self/exe; the build tree), the helpers'
 * folder of an installed tool (bin/../LIBDIR/spancast) and that of the
 * installed shared library the code runs in (LIBDIR/spancast); when none
 * exists, the first. Returns 1, or 0 when no path can be formed (errno says
 * why) or the result does not fit (errno ENAMETOOLONG). */
int file_beside_program(const char *name, char *path, size_t size);

#endif
