// Writing framebuffers through OpenImageIO (see image_io.h for the formats).
//
// Every write is atomic from the reader's side: the image goes to a new
// temporary file in the target's folder, named ".<stem>.tmp-<6 chars><ext>"
// so that OpenImageIO still picks the format from the extension, and only a
// complete file is renamed over the target. On any failure the temporary is
// removed and an existing target is left as it was. The temporary is created
// with O_EXCL and mode 0666 (less the umask), so the final file has the
// permissions a plain create would give it.
//
// Cancellation: the framebuffer carries the caller's cancel flag (set, for
// instance, by the command line's SIGINT handler). The writer polls it before
// it creates the temporary, before it opens the image in it, and after the
// image is complete, just before the rename; once it is set, the temporary is
// removed and the target is not touched. A write that has begun is finished
// first: stopping one midway (OpenImageIO's progress callback) makes libpng
// print an error of its own on stderr for the file it cannot close, and an
// image write is short beside the render before it. Only a flag read is
// involved, so nothing here has to be async-signal-safe.
//
// This is the one C++ file of the library: a thin layer that converts
// OpenImageIO's errors into sc_error values and never lets an exception out.
#include "formats/image_io.h"

#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#ifndef SPANCAST_VERSION
#define SPANCAST_VERSION "0.1.0" /* as the command line reports it */
#endif

extern "C" {
#include "base/error.h"
#include "formats/color.h"
}

namespace
{

// The extension of the last path component, lower case, without the dot;
// empty when there is none.
std::string extension_of(const std::string &path)
{
    size_t slash = path.find_last_of('/');
    size_t start = slash == std::string::npos ? 0 : slash + 1;
    size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || dot <= start)
        return std::string();
    std::string ext = path.substr(dot + 1);
    for (char &ch : ext)
        if (ch >= 'A' && ch <= 'Z')
            ch = (char)(ch - 'A' + 'a');
    return ext;
}

bool one_of(const std::string &ext, std::initializer_list<const char *> names)
{
    for (const char *name : names)
        if (ext == name)
            return true;
    return false;
}

bool float_color_format(const std::string &ext)
{
    return one_of(ext, {"exr", "sxr", "mxr", "tif", "tiff", "hdr", "rgbe", "pfm"});
}

bool depth_format(const std::string &ext)
{
    return one_of(ext, {"exr", "sxr", "mxr", "tif", "tiff"});
}

// OpenImageIO's messages may end in a newline; ours never do.
std::string trimmed(std::string message)
{
    while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
        message.pop_back();
    if (message.empty())
        message = "unknown OpenImageIO error";
    return message;
}

sc_status check(const char *path, imgio_kind kind, sc_error *error)
{
    std::string ext = extension_of(path);
    // create() only looks up the writer for the extension; it opens nothing.
    std::unique_ptr<OIIO::ImageOutput> probe;
    if (!ext.empty())
        probe = OIIO::ImageOutput::create(path);
    (void)OIIO::geterror(); // clear the lookup's message
    if (!probe)
        return err_set(error, SC_ERR_ARGUMENT, nullptr,
                       "cannot write '%s': unknown image format", path);
    static const char *const float_kinds[] = {nullptr, nullptr, "depth", "normals",
                                              "ids"};
    if (kind >= IMGIO_DEPTH && !depth_format(ext))
        return err_set(error, SC_ERR_ARGUMENT, nullptr,
                       "cannot write %s to '%s': %s needs a floating-point "
                       "format (.exr or .tif)",
                       float_kinds[kind], path, float_kinds[kind]);
    return SC_OK;
}

// Creates an empty temporary file next to path; returns its name, or an
// empty string with errno set.
std::string create_temporary(const std::string &path)
{
    size_t slash = path.find_last_of('/');
    std::string folder =
        slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
    std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    size_t dot = name.find_last_of('.');
    std::string stem = name.substr(0, dot), ext = name.substr(dot);

    static const char digits[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    struct timespec now;
    timespec_get(&now, TIME_UTC);
    uint64_t seed = (uint64_t)now.tv_nsec * 0x9e3779b97f4a7c15ull ^ (uint64_t)now.tv_sec ^
                    ((uint64_t)getpid() << 32);
    for (int attempt = 0; attempt < 100; attempt++) {
        // splitmix64: a fresh pseudo-random word per attempt
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
        std::string tmp = folder + "." + stem + ".tmp-" + tag + ext;
        int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            close(fd);
            return tmp;
        }
        if (errno != EEXIST)
            return std::string();
    }
    errno = EEXIST;
    return std::string();
}

bool cancelled(const volatile sig_atomic_t *cancel)
{
    return cancel && *cancel;
}

sc_status interrupted(sc_error *error)
{
    return err_set(error, SC_ERR_CANCELLED, nullptr, "interrupted");
}

// Writes width x height pixels of channels values of data_type (rows from
// the top, no padding) to path as file_type, through a temporary file.
// Gives up (SC_ERR_CANCELLED) as soon as *cancel is set.
sc_status write_image(const char *path, imgio_kind kind, int width, int height,
                      const std::vector<std::string> &channel_names,
                      OIIO::TypeDesc file_type, OIIO::TypeDesc data_type,
                      const void *data, const char *camera,
                      const volatile sig_atomic_t *cancel, sc_error *error)
{
    sc_status st = check(path, kind, error);
    if (st)
        return st;
    if (cancelled(cancel))
        return interrupted(error);
    std::string tmp = create_temporary(path);
    if (tmp.empty())
        return err_set(error, SC_ERR_IO, nullptr, "cannot write '%s': %s", path,
                       std::strerror(errno));

    std::string failure;
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(tmp);
    if (!out) {
        failure = trimmed(OIIO::geterror());
    } else {
        OIIO::ImageSpec spec(width, height, (int)channel_names.size(), file_type);
        spec.channelnames = channel_names;
        if (kind == IMGIO_COLOR) // 8-bit: sRGB-encoded; float: linear (color.h)
            spec.attribute("oiio:ColorSpace",
                           file_type == OIIO::TypeDesc::UINT8 ? "sRGB" : "Linear");
        spec.attribute("Software", "spancast " SPANCAST_VERSION);
        if (camera && camera[0]) {
            spec.attribute("ImageDescription", std::string("camera: ") + camera);
            spec.attribute("spancast:camera", camera);
        }
        // Loading the format's plugin takes a while the first time: look at
        // the flag again before open() starts a file that close() would
        // have to finish (libpng complains about a file without rows).
        if (cancelled(cancel)) {
            out.reset();
            std::remove(tmp.c_str());
            return interrupted(error);
        }
        if (!out->open(tmp, spec))
            failure = trimmed(out->geterror());
        else if (!out->write_image(data_type, data))
            failure = trimmed(out->geterror());
        if (!out->close() && failure.empty())
            failure = trimmed(out->geterror());
    }
    if (cancelled(cancel)) {
        std::remove(tmp.c_str());
        return interrupted(error);
    }
    if (failure.empty() && std::rename(tmp.c_str(), path) != 0)
        failure = std::strerror(errno);
    if (!failure.empty()) {
        std::remove(tmp.c_str());
        return err_set(error, SC_ERR_IO, nullptr, "cannot write '%s': %s", path,
                       failure.c_str());
    }
    return SC_OK;
}

sc_status no_buffer(const char *what, sc_error *error)
{
    return err_set(error, SC_ERR_ARGUMENT, nullptr, "the framebuffer has no %s buffer",
                   what);
}

sc_status guarded(sc_error *error,
                  sc_status (*body)(const sc_framebuffer *, const char *, sc_error *),
                  const sc_framebuffer *fb, const char *path)
{
    if (!path)
        return err_set(error, SC_ERR_ARGUMENT, nullptr, "no output file name");
    try {
        return body(fb, path, error);
    } catch (const std::bad_alloc &) {
        return err_set(error, SC_ERR_NOMEM, nullptr, "cannot write '%s': out of memory",
                       path);
    } catch (const std::exception &e) {
        return err_set(error, SC_ERR_IO, nullptr, "cannot write '%s': %s", path,
                       e.what());
    }
}

sc_status color_body(const sc_framebuffer *fb, const char *path, sc_error *error)
{
    if (!fb || !fb->color)
        return no_buffer("colour", error);
    if (float_color_format(extension_of(path)))
        return write_image(path, IMGIO_COLOR, fb->width, fb->height, {"R", "G", "B"},
                           OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::FLOAT, fb->color,
                           fb->camera_info, fb->cancel, error);
    size_t values = (size_t)fb->width * (size_t)fb->height * 3;
    std::vector<unsigned char> encoded(values);
    for (size_t k = 0; k < values; k++)
        encoded[k] = color_linear_to_srgb8(fb->color[k]);
    return write_image(path, IMGIO_COLOR, fb->width, fb->height, {"R", "G", "B"},
                       OIIO::TypeDesc::UINT8, OIIO::TypeDesc::UINT8, encoded.data(),
                       fb->camera_info, fb->cancel, error);
}

sc_status mask_body(const sc_framebuffer *fb, const char *path, sc_error *error)
{
    if (!fb || !fb->mask)
        return no_buffer("mask", error);
    return write_image(path, IMGIO_MASK, fb->width, fb->height, {"Y"},
                       OIIO::TypeDesc::UINT8, OIIO::TypeDesc::UINT8, fb->mask,
                       fb->camera_info, fb->cancel, error);
}

sc_status depth_body(const sc_framebuffer *fb, const char *path, sc_error *error)
{
    if (!fb || !fb->depth)
        return no_buffer("depth", error);
    return write_image(path, IMGIO_DEPTH, fb->width, fb->height, {"Z"},
                       OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::FLOAT, fb->depth,
                       fb->camera_info, fb->cancel, error);
}

sc_status normal_body(const sc_framebuffer *fb, const char *path, sc_error *error)
{
    if (!fb || !fb->normal)
        return no_buffer("normal", error);
    return write_image(path, IMGIO_NORMAL, fb->width, fb->height, {"X", "Y", "Z"},
                       OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::FLOAT, fb->normal,
                       fb->camera_info, fb->cancel, error);
}

sc_status id_body(const sc_framebuffer *fb, const char *path, sc_error *error)
{
    if (!fb || !fb->id)
        return no_buffer("id", error);
    // Ids as floats: exact up to 2^24 leaves, and -1 survives.
    size_t pixels = (size_t)fb->width * (size_t)fb->height;
    std::vector<float> ids(pixels);
    for (size_t k = 0; k < pixels; k++)
        ids[k] = (float)fb->id[k];
    return write_image(path, IMGIO_ID, fb->width, fb->height, {"id"},
                       OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::FLOAT, ids.data(),
                       fb->camera_info, fb->cancel, error);
}

} // namespace

extern "C" sc_status imgio_check(const char *path, imgio_kind kind, sc_error *error)
{
    if (!path)
        return err_set(error, SC_ERR_ARGUMENT, nullptr, "no output file name");
    try {
        return check(path, kind, error);
    } catch (const std::exception &e) {
        return err_set(error, SC_ERR_ARGUMENT, nullptr, "cannot write '%s': %s", path,
                       e.what());
    }
}

extern "C" sc_status sc_framebuffer_write_color(const sc_framebuffer *fb,
                                                const char *path, sc_error *error)
{
    return guarded(error, color_body, fb, path);
}

extern "C" sc_status sc_framebuffer_write_mask(const sc_framebuffer *fb, const char *path,
                                               sc_error *error)
{
    return guarded(error, mask_body, fb, path);
}

extern "C" sc_status sc_framebuffer_write_depth(const sc_framebuffer *fb,
                                                const char *path, sc_error *error)
{
    return guarded(error, depth_body, fb, path);
}

extern "C" sc_status sc_framebuffer_write_normal(const sc_framebuffer *fb,
                                                 const char *path, sc_error *error)
{
    return guarded(error, normal_body, fb, path);
}

extern "C" sc_status sc_framebuffer_write_id(const sc_framebuffer *fb, const char *path,
                                             sc_error *error)
{
    return guarded(error, id_body, fb, path);
}
