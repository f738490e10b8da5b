/* Writing framebuffers to image files (see image_io.h for the formats).
 *
 * The file's extension picks the back end (image_backend.h): PNG and EXR
 * are written directly, everything else through the OpenImageIO plugin,
 * loaded only then. What is common to all of them lives here, once: the
 * format check, the pixel layout, the metadata, and the atomic write.
 *
 * Every write is atomic from the reader's side: the image goes to a new
 * temporary file in the target's folder, named ".<stem>.tmp-<6 chars><ext>"
 * so that OpenImageIO still picks the format from the extension, and only a
 * complete file is renamed over the target. On any failure the temporary is
 * removed and an existing target is left as it was. The temporary is created
 * with O_EXCL and mode 0666 (less the umask), so a new file has the
 * permissions a plain create would give it; an existing one keeps its own.
 * A target that is a symbolic link to a file is written through: the file
 * it names is replaced, and the link stays (file_output_target).
 *
 * Cancellation: the framebuffer carries the caller's cancel flag (set, for
 * instance, by the command line's SIGINT handler). The writer polls it before
 * it creates the temporary, before it starts the image in it, and after the
 * image is complete, just before the rename; once it is set, the temporary is
 * removed and the target is not touched. A write that has begun is finished
 * first: an image write is short beside the render before it. Only a flag
 * read is involved, so nothing here has to be async-signal-safe.
 *
 * Tiled outputs (image_stream.h) take the same temporary and rename, with
 * the tiles written into the temporary as they arrive.
 */
#define _XOPEN_SOURCE 700

#include "formats/image_io.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/error.h"
#include "formats/color.h"
#include "formats/file.h"
#include "formats/image_backend.h"
#include "formats/image_stream.h"

#ifndef SPANCAST_VERSION
#define SPANCAST_VERSION "0.1.0" /* as the command line reports it */
#endif

#define MESSAGE_SIZE 512

typedef enum backend { BACKEND_PNG, BACKEND_EXR, BACKEND_PLUGIN } backend;

/* Copies the extension of path's last component, lower case and without
 * the dot, into ext (empty when there is none or it does not fit). */
static void extension_of(const char *path, char *ext, size_t size)
{
    const char *slash = strrchr(path, '/');
    const char *name = slash ? slash + 1 : path;
    const char *dot = strrchr(name, '.');
    ext[0] = '\0';
    if (!dot || dot == name || strlen(dot + 1) >= size)
        return;
    size_t k = 0;
    for (const char *c = dot + 1; *c; c++)
        ext[k++] = (*c >= 'A' && *c <= 'Z') ? (char)(*c - 'A' + 'a') : *c;
    ext[k] = '\0';
}

/* 1 if ext is one of the names of the NULL-terminated list. */
static int one_of(const char *ext, const char *const *names)
{
    for (; *names; names++)
        if (strcmp(ext, *names) == 0)
            return 1;
    return 0;
}

static int float_color_format(const char *ext)
{
    static const char *const names[] = {"exr", "sxr",  "mxr", "tif", "tiff",
                                        "hdr", "rgbe", "pfm", NULL};
    return one_of(ext, names);
}

int imgio_lossy(const char *path)
{
    static const char *const names[] = {"jpg", "jpeg", "jpe", "jfif", NULL};
    char ext[16];
    extension_of(path, ext, sizeof ext);
    return one_of(ext, names);
}

static int depth_format(const char *ext)
{
    static const char *const names[] = {"exr", "sxr", "mxr", "tif", "tiff", NULL};
    return one_of(ext, names);
}

static backend backend_of(const char *ext)
{
    static const char *const exr[] = {"exr", "sxr", "mxr", NULL};
    if (strcmp(ext, "png") == 0)
        return BACKEND_PNG;
    return one_of(ext, exr) ? BACKEND_EXR : BACKEND_PLUGIN;
}

static int tiff_format(const char *ext)
{
    static const char *const names[] = {"tif", "tiff", NULL};
    return one_of(ext, names);
}

/* The format check. PNG, EXR and TIFF are known here (TIFF is written
 * tiled by libtiff, untiled by OpenImageIO, which always has it: its TIFF
 * writer is part of its core library, not an optional one); for any other
 * extension the plugin is loaded and OpenImageIO asked whether it has a
 * writer, so that the list of formats is OpenImageIO's own. Not loading
 * the plugin to check a TIFF keeps it out of a streamed render, whose
 * memory it would triple. */
static sc_status check(const char *path, imgio_kind kind, sc_error *error)
{
    char ext[16];
    extension_of(path, ext, sizeof ext);
    int known = ext[0] != '\0';
    if (known && backend_of(ext) == BACKEND_PLUGIN && !tiff_format(ext)) {
        imgio_plugin plugin;
        char why[MESSAGE_SIZE];
        if (!imgio_plugin_open(&plugin, why, sizeof why))
            return err_set(error, SC_ERR_IO, NULL, "cannot write '%s': %s", path, why);
        known = plugin.writable(path);
        imgio_plugin_close(&plugin);
    }
    struct stat st;
    if (!known && stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "cannot write '%s': it is a folder (an image is a file with an "
                       "extension: .png, .exr, ...)",
                       path);
    if (!known)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "cannot write '%s': unknown image format", path);
    static const char *const float_kinds[] = {NULL, NULL, "depth", "normals", "ids"};
    if (kind >= IMGIO_DEPTH && !depth_format(ext))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "cannot write %s to '%s': %s needs a floating-point "
                       "format (.exr or .tif)",
                       float_kinds[kind], path, float_kinds[kind]);
    return SC_OK;
}

/* Creates an empty temporary file next to target, with the extension of
 * path (the name the user gave, which picks the format); returns its name
 * (malloc'd, the caller frees it), or NULL with errno set. */
static char *create_temporary(const char *target, const char *path)
{
    const char *slash = strrchr(target, '/');
    size_t folder_len = slash ? (size_t)(slash + 1 - target) : 0;
    const char *name = target + folder_len;
    const char *name_dot = strrchr(name, '.');
    size_t stem_len = name_dot ? (size_t)(name_dot - name) : strlen(name);
    const char *user_name = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    const char *dot = strrchr(user_name, '.'); /* check() made sure there is one */
    size_t size = strlen(target) + strlen(dot) + sizeof "/..tmp-123456";
    char *tmp = malloc(size);
    if (!tmp) {
        errno = ENOMEM;
        return NULL;
    }

    static const char digits[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    struct timespec now;
    timespec_get(&now, TIME_UTC);
    uint64_t seed = (uint64_t)now.tv_nsec * 0x9e3779b97f4a7c15ull ^ (uint64_t)now.tv_sec ^
                    ((uint64_t)getpid() << 32);
    for (int attempt = 0; attempt < 100; attempt++) {
        /* splitmix64: a fresh pseudo-random word per attempt */
        seed += 0x9e3779b97f4a7c15ull;
        uint64_t z = seed;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        z ^= z >> 31;
        char tag[7];
        for (int k = 0; k < 6; k++) {
            tag[k] = digits[z % 36];
            z /= 36;
        }
        tag[6] = '\0';
        snprintf(tmp, size, "%.*s.%.*s.tmp-%s%s", (int)folder_len, target, (int)stem_len,
                 name, tag, dot);
        int fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            close(fd);
            return tmp;
        }
        if (errno != EEXIST)
            break;
    }
    int saved = errno;
    free(tmp);
    errno = saved;
    return NULL;
}

static int cancelled(const volatile sig_atomic_t *cancel)
{
    return cancel && *cancel;
}

/* Writes img to path through a temporary file, with the back end of path's
 * extension. Gives up (SC_ERR_CANCELLED) as soon as *cancel is set. */
static sc_status write_image(const char *path, imgio_kind kind, const imgio_image *img,
                             const volatile sig_atomic_t *cancel, sc_error *error)
{
    sc_status st = check(path, kind, error);
    if (st)
        return st;
    if (cancelled(cancel))
        return err_set(error, SC_ERR_CANCELLED, NULL, "interrupted");
    char ext[16];
    extension_of(path, ext, sizeof ext);
    backend back = backend_of(ext);
    imgio_plugin plugin = {0};
    char failure[MESSAGE_SIZE] = "";
    if (back == BACKEND_PLUGIN && !imgio_plugin_open(&plugin, failure, sizeof failure))
        return err_set(error, SC_ERR_IO, NULL, "cannot write '%s': %s", path, failure);

    char *target = file_output_target(path);
    char *tmp = target ? create_temporary(target, path) : NULL;
    if (!tmp) {
        int code = target ? errno : ENOMEM;
        free(target);
        imgio_plugin_close(&plugin);
        return err_set(error, SC_ERR_IO, NULL, "cannot write '%s': %s", path,
                       strerror(code));
    }
    /* Loading a format's library may take a while: look at the flag again
     * before starting a file that would have to be finished. */
    int ok = 1;
    if (!cancelled(cancel)) {
        if (back == BACKEND_PNG)
            ok = imgio_png_write(img, tmp, failure, sizeof failure);
        else if (back == BACKEND_EXR)
            ok = imgio_exr_write(img, tmp, failure, sizeof failure);
        else
            ok = plugin.write(img, tmp, failure, sizeof failure);
    }
    imgio_plugin_close(&plugin);
    if (cancelled(cancel)) {
        remove(tmp);
        free(tmp);
        free(target);
        return err_set(error, SC_ERR_CANCELLED, NULL, "interrupted");
    }
    if (ok && !file_replace(tmp, target)) {
        ok = 0;
        snprintf(failure, sizeof failure, "%s", strerror(errno));
    }
    free(target);
    if (!ok) {
        remove(tmp);
        free(tmp);
        return err_set(error, SC_ERR_IO, NULL, "cannot write '%s': %s", path, failure);
    }
    free(tmp);
    return SC_OK;
}

/* The common start of every writer: the path, the buffer, and the image
 * around it (float samples in channels channels under names), metadata
 * included. */
static sc_status start(const sc_framebuffer *fb, const void *buffer, const char *what,
                       const char *path, int channels, const char *const *names,
                       imgio_image *img, sc_error *error)
{
    if (!path)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no output file name");
    if (!fb || !buffer)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "the framebuffer has no %s buffer",
                       what);
    memset(img, 0, sizeof *img);
    img->width = fb->width;
    img->height = fb->height;
    img->channels = channels;
    img->channel_names = names;
    img->sample = IMGIO_FLOAT;
    img->pixels = buffer;
    img->software = "spancast " SPANCAST_VERSION;
    img->camera = fb->camera_info[0] ? fb->camera_info : NULL;
    return SC_OK;
}

/* A writer that stores the buffer as it is, in samples of type sample. */
static sc_status write_buffer(const sc_framebuffer *fb, const void *buffer,
                              const char *what, const char *path, imgio_kind kind,
                              int channels, const char *const *names, imgio_sample sample,
                              sc_error *error)
{
    imgio_image img;
    sc_status st = start(fb, buffer, what, path, channels, names, &img, error);
    if (st)
        return st;
    img.sample = sample;
    return write_image(path, kind, &img, fb->cancel, error);
}

static sc_status out_of_memory(const char *path, sc_error *error)
{
    return err_set(error, SC_ERR_NOMEM, NULL, "cannot write '%s': out of memory", path);
}

static const char *const rgb_names[] = {"R", "G", "B"};
static const char *const xyz_names[] = {"X", "Y", "Z"};

sc_status imgio_check(const char *path, imgio_kind kind, sc_error *error)
{
    if (!path)
        return err_set(error, SC_ERR_ARGUMENT, NULL, "no output file name");
    return check(path, kind, error);
}

sc_status sc_framebuffer_write_color(const sc_framebuffer *fb, const char *path,
                                     sc_error *error)
{
    imgio_image img;
    sc_status st =
        start(fb, fb ? fb->color : NULL, "colour", path, 3, rgb_names, &img, error);
    if (st)
        return st;
    char ext[16];
    extension_of(path, ext, sizeof ext);
    if (float_color_format(ext)) { /* linear (color.h) */
        img.color_space = "Linear";
        return write_image(path, IMGIO_COLOR, &img, fb->cancel, error);
    }
    /* 8-bit: sRGB-encoded */
    size_t values = (size_t)fb->width * (size_t)fb->height * 3;
    unsigned char *encoded = malloc(values ? values : 1);
    if (!encoded)
        return out_of_memory(path, error);
    color_srgb8_table table;
    color_srgb8_table_init(&table);
    for (size_t k = 0; k < values; k++)
        encoded[k] = color_srgb8_encode(&table, fb->color[k]);
    img.sample = IMGIO_UINT8;
    img.pixels = encoded;
    img.color_space = "sRGB";
    st = write_image(path, IMGIO_COLOR, &img, fb->cancel, error);
    free(encoded);
    return st;
}

sc_status sc_framebuffer_write_mask(const sc_framebuffer *fb, const char *path,
                                    sc_error *error)
{
    static const char *const names[] = {"Y"};
    return write_buffer(fb, fb ? fb->mask : NULL, "mask", path, IMGIO_MASK, 1, names,
                        IMGIO_UINT8, error);
}

sc_status sc_framebuffer_write_depth(const sc_framebuffer *fb, const char *path,
                                     sc_error *error)
{
    static const char *const names[] = {"Z"};
    return write_buffer(fb, fb ? fb->depth : NULL, "depth", path, IMGIO_DEPTH, 1, names,
                        IMGIO_FLOAT, error);
}

sc_status sc_framebuffer_write_normal(const sc_framebuffer *fb, const char *path,
                                      sc_error *error)
{
    return write_buffer(fb, fb ? fb->normal : NULL, "normal", path, IMGIO_NORMAL, 3,
                        xyz_names, IMGIO_FLOAT, error);
}

sc_status sc_framebuffer_write_id(const sc_framebuffer *fb, const char *path,
                                  sc_error *error)
{
    static const char *const names[] = {"id"};
    imgio_image img;
    sc_status st = start(fb, fb ? fb->id : NULL, "id", path, 1, names, &img, error);
    if (st)
        return st;
    /* Ids as floats: exact up to 2^24 leaves, and -1 survives. */
    size_t pixels = (size_t)fb->width * (size_t)fb->height;
    float *ids = malloc((pixels ? pixels : 1) * sizeof *ids);
    if (!ids)
        return out_of_memory(path, error);
    for (size_t k = 0; k < pixels; k++)
        ids[k] = (float)fb->id[k];
    img.pixels = ids;
    st = write_image(path, IMGIO_ID, &img, fb->cancel, error);
    free(ids);
    return st;
}

/* ---- tiled outputs (image_stream.h) ---- */

struct imgio_stream {
    imgio_kind kind;
    char *path, *tmp;
    char *target;           /* the file replaced (file_output_target) */
    imgio_exr_tiles *tiles; /* a tiled EXR, or */
    imgio_tiff_tiles *tiff; /* a tiled TIFF, through */
    imgio_tiff_plugin tiff_plugin;
    int tile;
    float *ids; /* one tile of ids as float */
};

int imgio_stream_supported(const char *path)
{
    char ext[16];
    extension_of(path, ext, sizeof ext);
    return backend_of(ext) == BACKEND_EXR || tiff_format(ext);
}

void imgio_stream_abandon(imgio_stream *s)
{
    if (!s)
        return;
    char ignored[MESSAGE_SIZE];
    imgio_exr_tiles_close(s->tiles, ignored, sizeof ignored);
    if (s->tiff)
        s->tiff_plugin.close(s->tiff, ignored, sizeof ignored);
    imgio_tiff_plugin_close(&s->tiff_plugin);
    if (s->tmp)
        remove(s->tmp);
    free(s->tmp);
    free(s->path);
    free(s->target);
    free(s->ids);
    free(s);
}

sc_status imgio_stream_open(const char *path, imgio_kind kind, int width, int height,
                            int tile, const char *camera, imgio_stream **out,
                            sc_error *error)
{
    *out = NULL;
    sc_status st = imgio_check(path, kind, error);
    if (st)
        return st;
    if (!imgio_stream_supported(path))
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "cannot write '%s' tile by tile: only .exr and .tif are written "
                       "that way",
                       path);
    imgio_stream *s = calloc(1, sizeof *s);
    if (!s || !(s->path = strdup(path)) || !(s->target = file_output_target(path)) ||
        (kind == IMGIO_ID &&
         !(s->ids = malloc((size_t)tile * (size_t)tile * sizeof *s->ids)))) {
        imgio_stream_abandon(s);
        return out_of_memory(path, error);
    }
    s->kind = kind;
    s->tile = tile;
    s->tmp = create_temporary(s->target, path);
    if (!s->tmp) {
        int code = errno;
        imgio_stream_abandon(s);
        return err_set(error, SC_ERR_IO, NULL, "cannot write '%s': %s", path,
                       strerror(code));
    }
    static const char *const color_names[] = {"R", "G", "B"};
    static const char *const normal_names[] = {"X", "Y", "Z"};
    static const char *const mask_names[] = {"Y"};
    static const char *const depth_names[] = {"Z"};
    static const char *const id_names[] = {"id"};
    imgio_image img;
    memset(&img, 0, sizeof img);
    img.width = width;
    img.height = height;
    img.sample = kind == IMGIO_MASK ? IMGIO_UINT8 : IMGIO_FLOAT;
    img.channels = kind == IMGIO_COLOR || kind == IMGIO_NORMAL ? 3 : 1;
    img.channel_names = kind == IMGIO_COLOR    ? color_names
                        : kind == IMGIO_NORMAL ? normal_names
                        : kind == IMGIO_MASK   ? mask_names
                        : kind == IMGIO_DEPTH  ? depth_names
                                               : id_names;
    img.color_space = kind == IMGIO_COLOR ? "Linear" : NULL;
    img.software = "spancast " SPANCAST_VERSION;
    img.camera = camera && camera[0] ? camera : NULL;
    char failure[MESSAGE_SIZE] = "", ext[16];
    extension_of(path, ext, sizeof ext);
    if (tiff_format(ext)) {
        if (imgio_tiff_plugin_open(&s->tiff_plugin, failure, sizeof failure))
            s->tiff = s->tiff_plugin.open(&img, tile, s->tmp, failure, sizeof failure);
    } else
        s->tiles = imgio_exr_tiles_open(&img, tile, s->tmp, failure, sizeof failure);
    if (!s->tiles && !s->tiff) {
        imgio_stream_abandon(s);
        return err_set(error, SC_ERR_IO, NULL, "cannot write '%s': %s", path, failure);
    }
    *out = s;
    return SC_OK;
}

sc_status imgio_stream_write(imgio_stream *s, int tx, int ty, const sc_framebuffer *tile,
                             sc_error *error)
{
    const void *pixels = s->kind == IMGIO_COLOR    ? (const void *)tile->color
                         : s->kind == IMGIO_MASK   ? (const void *)tile->mask
                         : s->kind == IMGIO_DEPTH  ? (const void *)tile->depth
                         : s->kind == IMGIO_NORMAL ? (const void *)tile->normal
                                                   : (const void *)tile->id;
    if (!pixels || tile->width > s->tile || tile->height > s->tile)
        return err_set(error, SC_ERR_ARGUMENT, NULL,
                       "cannot write '%s': a tile does not fit the file's tiles",
                       s->path);
    if (s->kind == IMGIO_ID) { /* as sc_framebuffer_write_id: floats */
        size_t pixel_count = (size_t)tile->width * (size_t)tile->height;
        for (size_t k = 0; k < pixel_count; k++)
            s->ids[k] = (float)tile->id[k];
        pixels = s->ids;
    }
    char failure[MESSAGE_SIZE] = "";
    int ok =
        s->tiff
            ? s->tiff_plugin.write(s->tiff, tx, ty, pixels, failure, sizeof failure)
            : imgio_exr_tiles_write(s->tiles, tx, ty, pixels, failure, sizeof failure);
    if (!ok)
        return err_set(error, SC_ERR_IO, NULL, "cannot write '%s': %s", s->path, failure);
    return SC_OK;
}

sc_status imgio_stream_finish(imgio_stream *s, const volatile sig_atomic_t *cancel,
                              sc_error *error)
{
    char failure[MESSAGE_SIZE] = "";
    int ok = s->tiff ? s->tiff_plugin.close(s->tiff, failure, sizeof failure)
                     : imgio_exr_tiles_close(s->tiles, failure, sizeof failure);
    s->tiles = NULL;
    s->tiff = NULL;
    sc_status st = SC_OK;
    if (cancelled(cancel))
        st = err_set(error, SC_ERR_CANCELLED, NULL, "interrupted");
    else if (!ok)
        st = err_set(error, SC_ERR_IO, NULL, "cannot write '%s': %s", s->path, failure);
    else if (!file_replace(s->tmp, s->target))
        st = err_set(error, SC_ERR_IO, NULL, "cannot write '%s': %s", s->path,
                     strerror(errno));
    else {
        free(s->tmp);
        s->tmp = NULL; /* renamed: nothing to remove */
    }
    imgio_stream_abandon(s);
    return st;
}
