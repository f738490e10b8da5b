/* Watching model files with inotify.
 *
 * Each file is watched through its folder, not its own inode: editors save
 * by writing a new file and renaming it over the old one (vim, most IDEs),
 * and a watch on the old inode would see that once and then nothing more.
 * The folder's events are filtered by name: a file changes when it is
 * written and closed, modified, created, moved into place, or removed (a
 * reload then reports the missing file, and the next save brings it back).
 * Several files of one folder share the folder's watch descriptor, as
 * inotify_add_watch returns the same one for the same folder.
 *
 * The set only grows: a file that a .scad model no longer includes stays
 * watched, which costs at most a needless reload, where dropping a file
 * whose conversion failed would miss the fix.
 */
#define _XOPEN_SOURCE 700 /* realpath */

#include "cli/watch.h"

#include <errno.h>
#include <limits.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/inotify.h>
#include <unistd.h>

#define WATCH_EVENTS                                                                     \
    (IN_CLOSE_WRITE | IN_MODIFY | IN_CREATE | IN_MOVED_TO | IN_DELETE | IN_MOVED_FROM |  \
     IN_ATTRIB)

typedef struct watch_entry {
    int wd;     /* the folder's watch descriptor */
    char *name; /* the file's name in that folder */
    char *path; /* as it was added, for messages */
} watch_entry;

struct watch_set {
    int fd;
    watch_entry *entries;
    size_t count, capacity;
    const char *changed; /* the path of the file the last change was to, or NULL */
};

static sc_status fail(sc_error *error, const char *format, const char *path, int code)
{
    memset(error, 0, sizeof *error);
    error->status = SC_ERR_IO;
    snprintf(error->message, sizeof error->message, format, path, strerror(code));
    return SC_ERR_IO;
}

watch_set *watch_open(sc_error *error)
{
    watch_set *set = calloc(1, sizeof *set);
    if (!set) {
        fail(error, "cannot watch files%s: %s", "", ENOMEM);
        return NULL;
    }
    set->fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (set->fd < 0) {
        fail(error, "cannot watch files%s: %s", "", errno);
        free(set);
        return NULL;
    }
    return set;
}

void watch_close(watch_set *set)
{
    if (!set)
        return;
    for (size_t k = 0; k < set->count; k++) {
        free(set->entries[k].name);
        free(set->entries[k].path);
    }
    free(set->entries);
    close(set->fd);
    free(set);
}

int watch_fd(const watch_set *set)
{
    return set->fd;
}

sc_status watch_add(watch_set *set, const char *path, sc_error *error)
{
    /* The folder, resolved, and the file's own name in it. */
    const char *slash = strrchr(path, '/');
    const char *name = slash ? slash + 1 : path;
    char folder[PATH_MAX], resolved[PATH_MAX];
    if (!slash) {
        strcpy(folder, ".");
    } else {
        size_t n = slash == path ? 1 : (size_t)(slash - path);
        if (n >= sizeof folder)
            return fail(error, "cannot watch '%s': %s", path, ENAMETOOLONG);
        memcpy(folder, path, n);
        folder[n] = '\0';
    }
    if (!*name)
        return fail(error, "cannot watch '%s': %s", path, EISDIR);
    if (!realpath(folder, resolved))
        return fail(error, "cannot watch '%s': %s", path, errno);
    int wd = inotify_add_watch(set->fd, resolved, WATCH_EVENTS);
    if (wd < 0)
        return fail(error, "cannot watch '%s': %s", path, errno);
    for (size_t k = 0; k < set->count; k++)
        if (set->entries[k].wd == wd && !strcmp(set->entries[k].name, name))
            return SC_OK;
    if (set->count == set->capacity) {
        size_t capacity = set->capacity ? 2 * set->capacity : 8;
        watch_entry *grown = realloc(set->entries, capacity * sizeof *grown);
        if (!grown)
            return fail(error, "cannot watch '%s': %s", path, ENOMEM);
        set->entries = grown;
        set->capacity = capacity;
    }
    char *copy = strdup(name), *whole = strdup(path);
    if (!copy || !whole) {
        free(copy);
        free(whole);
        return fail(error, "cannot watch '%s': %s", path, ENOMEM);
    }
    set->entries[set->count].wd = wd;
    set->entries[set->count].name = copy;
    set->entries[set->count].path = whole;
    set->count++;
    return SC_OK;
}

void watch_add_file(void *set, const char *path)
{
    sc_error ignored;
    (void)watch_add(set, path, &ignored);
}

/* Whether the event is a change to a file of the set; set->changed
 * becomes that file's path (NULL when events were lost). */
static int concerns_set(watch_set *set, const struct inotify_event *event)
{
    if (event->mask & IN_Q_OVERFLOW) {
        set->changed = NULL;
        return 1; /* events were lost: one of them may have been ours */
    }
    if (!event->len)
        return 0;
    for (size_t k = 0; k < set->count; k++)
        if (set->entries[k].wd == event->wd &&
            !strcmp(set->entries[k].name, event->name)) {
            set->changed = set->entries[k].path;
            return 1;
        }
    return 0;
}

int watch_changed(watch_set *set)
{
    /* Aligned as inotify(7) asks, large enough for many events at once. */
    _Alignas(struct inotify_event) char buf[8192];
    int changed = 0;
    for (;;) {
        ssize_t n = read(set->fd, buf, sizeof buf);
        if (n <= 0)
            return changed; /* EAGAIN: nothing more pending */
        for (char *p = buf; p < buf + n;) {
            const struct inotify_event *event = (const struct inotify_event *)p;
            changed |= concerns_set(set, event);
            p += sizeof *event + event->len;
        }
    }
}

/* Waits up to timeout_ms (-1: forever) for the descriptor; 1 when it is
 * readable, 0 on timeout, -1 on an interrupt or error. */
static int wait_readable(const watch_set *set, int timeout_ms)
{
    struct pollfd p = {set->fd, POLLIN, 0};
    int n = poll(&p, 1, timeout_ms);
    if (n < 0)
        return -1;
    return n > 0;
}

int watch_wait(watch_set *set, const volatile sig_atomic_t *stop)
{
    (void)watch_changed(set); /* what happened before the wait was handled */
    for (;;) {
        if (stop && *stop)
            return 0;
        int ready = wait_readable(set, -1);
        if (ready < 0 && errno != EINTR)
            return 0;
        if (ready > 0 && watch_changed(set))
            break;
    }
    /* Settle: wait for WATCH_SETTLE_MS without a further change. */
    for (;;) {
        if (stop && *stop)
            return 0;
        int ready = wait_readable(set, WATCH_SETTLE_MS);
        if (ready == 0)
            return 1;
        if (ready < 0 && errno != EINTR)
            return 0;
        if (ready > 0)
            (void)watch_changed(set);
    }
}

const char *watch_last_change(const watch_set *set)
{
    return set->changed;
}
