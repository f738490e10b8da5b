// Reading images back as floats through OpenImageIO: see image_read.h.
#include "formats/image_read.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

extern "C" int image_read(const char *path, image_data *out, char *err, int err_size)
{
    out->width = out->height = out->channels = 0;
    out->pixels = nullptr;
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        std::snprintf(err, (size_t)err_size, "cannot read '%s': %s", path,
                      OIIO::geterror().c_str());
        return 0;
    }
    const OIIO::ImageSpec &spec = in->spec();
    size_t count = (size_t)spec.width * (size_t)spec.height * (size_t)spec.nchannels;
    float *pixels = static_cast<float *>(std::malloc(count * sizeof(float)));
    if (!pixels) {
        std::snprintf(err, (size_t)err_size, "out of memory");
        return 0;
    }
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels)) {
        std::snprintf(err, (size_t)err_size, "cannot read '%s': %s", path,
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

extern "C" void image_data_free(image_data *img)
{
    std::free(img->pixels);
    img->pixels = nullptr;
}
