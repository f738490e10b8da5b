// The OpenImageIO plugin, spancast-oiio.so: every image format other than
// PNG and EXR, written and read through OpenImageIO.
//
// Built as a loadable module (not part of libspancast) so that only a run
// that needs one of these formats loads OpenImageIO and its dependencies;
// image_plugin.c finds it and looks up the three entry points below by
// name. It writes exactly the file it is given (the temporary of
// image_io.c), with the channel names, sample type and metadata of the
// imgio_image, and reports failures as text. No exception leaves it.
#include "formats/image_backend.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace
{

// OpenImageIO's messages may end in a newline; ours never do.
void message(char *err, size_t err_size, std::string text)
{
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();
    if (text.empty())
        text = "unknown OpenImageIO error";
    std::snprintf(err, err_size, "%s", text.c_str());
}

int write_body(const imgio_image *img, const char *path, char *err, size_t err_size)
{
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) {
        message(err, err_size, OIIO::geterror());
        return 0;
    }
    OIIO::TypeDesc type =
        img->sample == IMGIO_UINT8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(img->width, img->height, img->channels, type);
    spec.channelnames.assign(img->channel_names, img->channel_names + img->channels);
    if (img->color_space)
        spec.attribute("oiio:ColorSpace", img->color_space);
    spec.attribute("Software", img->software);
    if (img->camera) {
        spec.attribute("ImageDescription", std::string("camera: ") + img->camera);
        spec.attribute("spancast:camera", img->camera);
    }
    std::string failure;
    if (!out->open(path, spec))
        failure = out->geterror();
    else if (!out->write_image(type, img->pixels))
        failure = out->geterror();
    if (!out->close() && failure.empty())
        failure = out->geterror();
    if (!failure.empty()) {
        message(err, err_size, failure);
        return 0;
    }
    return 1;
}

int read_body(const char *path, image_data *out, char *err, size_t err_size)
{
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        std::snprintf(err, err_size, "cannot read '%s': %s", path,
                      OIIO::geterror().c_str());
        return 0;
    }
    const OIIO::ImageSpec &spec = in->spec();
    size_t count = (size_t)spec.width * (size_t)spec.height * (size_t)spec.nchannels;
    float *pixels =
        static_cast<float *>(std::malloc((count ? count : 1) * sizeof(float)));
    if (!pixels) {
        std::snprintf(err, err_size, "cannot read '%s': out of memory", path);
        return 0;
    }
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels)) {
        std::snprintf(err, err_size, "cannot read '%s': %s", path,
                      in->geterror().c_str());
        std::free(pixels);
        return 0;
    }
    in->close();
    out->width = spec.width;
    out->height = spec.height;
    out->channels = spec.nchannels;
    out->pixels = pixels;
    return 1;
}

} // namespace

extern "C" {

// Declared here with the types of image_backend.h, so that a change there
// fails to compile rather than to run.
imgio_plugin_writable_fn spancast_oiio_writable;
imgio_plugin_write_fn spancast_oiio_write;
imgio_plugin_read_fn spancast_oiio_read;

// create() only looks up the writer for the extension; it opens nothing.
int spancast_oiio_writable(const char *path)
{
    try {
        std::unique_ptr<OIIO::ImageOutput> probe = OIIO::ImageOutput::create(path);
        (void)OIIO::geterror(); // clear the lookup's message
        return probe != nullptr;
    } catch (const std::exception &) {
        return 0;
    }
}

int spancast_oiio_write(const imgio_image *img, const char *path, char *err,
                        size_t err_size)
{
    try {
        return write_body(img, path, err, err_size);
    } catch (const std::bad_alloc &) {
        message(err, err_size, "out of memory");
    } catch (const std::exception &e) {
        message(err, err_size, e.what());
    }
    return 0;
}

int spancast_oiio_read(const char *path, image_data *out, char *err, size_t err_size)
{
    out->width = out->height = out->channels = 0;
    out->pixels = nullptr;
    try {
        return read_body(path, out, err, err_size);
    } catch (const std::exception &e) {
        std::snprintf(err, err_size, "cannot read '%s': %s", path, e.what());
    }
    return 0;
}
}
