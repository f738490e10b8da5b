/* Filling sc_error values. Every module reports failures through err_set:
 * a status, an optional source position and a printf-style message. The
 * message never includes the "file:line:col: error:" prefix; sc_error_format
 * adds it, so library callers and the CLI print the same text. */
#ifndef SPANCAST_BASE_ERROR_H
#define SPANCAST_BASE_ERROR_H

#include "spancast/spancast.h"

#if defined(__GNUC__)
#define SC_PRINTF(fmt, args) __attribute__((format(printf, fmt, args)))
#else
#define SC_PRINTF(fmt, args)
#endif

/* Sets *error (when error is not NULL) and returns status, so callers can
 * write `return err_set(error, SC_ERR_SYNTAX, &loc, "...")`. loc may be
 * NULL. */
sc_status err_set(sc_error *error, sc_status status, const sc_location *loc,
                  const char *format, ...) SC_PRINTF(4, 5);

/* err_nomem(error, loc): the one message of a
 * failed allocation, at loc (NULL: no position): "out of memory", and
 * under a memory limit (base/mem.h) which limit was reached. */
sc_status err_nomem(sc_error *error, const sc_location *loc);

/* Clears *error to SC_OK with an empty message. */
void err_clear(sc_error *error);

#endif
