// EXR files through OpenEXR's own library, written and read directly.
//
// The writer stores what OpenImageIO's EXR writer stored before it: one
// scanline part, ZIP compression (16 rows a block), the channels under their
// names, 32-bit float where the data is float and half where it is 8-bit (a
// mask: 0 or 1), and the metadata as string attributes "Software",
// "comments" (OpenImageIO's name for the image description) and
// "spancast:camera". OpenImageIO also added "capDate", the time of writing;
// it is left out, so that the same render gives the same file.
//
// The reader returns every channel as float, in OpenImageIO's order (R, G,
// B, A, then the others as the file stores them: alphabetical), row 0 at
// the top of the data window.
//
// This file converts OpenEXR's exceptions into messages and never lets one
// out.
#include "formats/exr/image_exr.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <Imath/half.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>
#include <vector>

void exr_message(char *err, size_t err_size, const char *what)
{
    std::string text = what;
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();
    std::snprintf(err, err_size, "%s",
                  text.empty() ? "unknown OpenEXR error" : text.c_str());
}

void exr_exception_message(char *err, size_t err_size)
{
    try {
        throw;
    } catch (const std::bad_alloc &) {
        exr_message(err, err_size, "out of memory");
    } catch (const std::exception &e) {
        exr_message(err, err_size, e.what());
    }
}

void exr_add_metadata(Imf::Header &header, const imgio_image *img)
{
    header.insert("Software", Imf::StringAttribute(img->software));
    if (img->camera) {
        header.insert("comments",
                      Imf::StringAttribute(std::string("camera: ") + img->camera));
        header.insert("spancast:camera", Imf::StringAttribute(img->camera));
    }
}

const char *exr_samples(const void *pixels, imgio_sample sample, size_t values,
                        std::vector<Imath::half> &halves, Imf::PixelType &type,
                        size_t &sample_size)
{
    type = Imf::FLOAT;
    sample_size = sizeof(float);
    if (sample != IMGIO_UINT8)
        return static_cast<const char *>(pixels);
    halves.resize(values);
    const unsigned char *bytes = static_cast<const unsigned char *>(pixels);
    for (size_t k = 0; k < values; k++)
        halves[k] = Imath::half(bytes[k] / 255.0f);
    type = Imf::HALF;
    sample_size = sizeof(Imath::half);
    return reinterpret_cast<const char *>(halves.data());
}

extern "C" int spancast_exr_write(const imgio_image *img, const char *path, char *err,
                                  size_t err_size)
{
    try {
        Imf::Header header(img->width, img->height);
        header.compression() = Imf::ZIP_COMPRESSION;
        exr_add_metadata(header, img);
        size_t pixels = (size_t)img->width * (size_t)img->height;
        size_t values = pixels * (size_t)img->channels;
        // (A frame buffer slice must have the file's type.)
        std::vector<Imath::half> halves;
        Imf::PixelType type;
        size_t sample_size;
        const char *data =
            exr_samples(img->pixels, img->sample, values, halves, type, sample_size);
        Imf::FrameBuffer frame;
        size_t x_stride = sample_size * (size_t)img->channels;
        for (int c = 0; c < img->channels; c++) {
            header.channels().insert(img->channel_names[c], Imf::Channel(type));
            frame.insert(img->channel_names[c],
                         Imf::Slice(type, const_cast<char *>(data) + c * sample_size,
                                    x_stride, x_stride * (size_t)img->width));
        }
        Imf::OutputFile file(path, header);
        file.setFrameBuffer(frame);
        file.writePixels(img->height);
        return 1;
    } catch (const std::exception &) {
        exr_exception_message(err, err_size);
    }
    return 0;
}

extern "C" int spancast_exr_read(const char *path, image_data *out, char *err,
                                 size_t err_size)
{
    out->width = out->height = out->channels = 0;
    out->pixels = nullptr;
    float *pixels = nullptr;
    try {
        Imf::InputFile file(path);
        const Imath::Box2i window = file.header().dataWindow();
        int width = window.max.x - window.min.x + 1;
        int height = window.max.y - window.min.y + 1;
        // OpenImageIO's order: R, G, B, A first, then the rest as stored.
        const Imf::ChannelList &list = file.header().channels();
        std::vector<std::string> names;
        for (const char *name : {"R", "G", "B", "A"})
            if (list.findChannel(name))
                names.push_back(name);
        for (Imf::ChannelList::ConstIterator it = list.begin(); it != list.end(); ++it) {
            std::string name = it.name();
            if (name != "R" && name != "G" && name != "B" && name != "A")
                names.push_back(name);
        }
        int channels = (int)names.size();
        size_t values = (size_t)width * (size_t)height * (size_t)channels;
        pixels = static_cast<float *>(std::malloc((values ? values : 1) * sizeof(float)));
        if (!pixels)
            throw std::bad_alloc();
        Imf::FrameBuffer frame;
        size_t x_stride = sizeof(float) * (size_t)channels;
        size_t y_stride = x_stride * (size_t)width;
        // Slices address pixel (x, y) of the data window at base + x, y.
        char *base = (char *)pixels - (ptrdiff_t)window.min.x * (ptrdiff_t)x_stride -
                     (ptrdiff_t)window.min.y * (ptrdiff_t)y_stride;
        for (int c = 0; c < channels; c++)
            frame.insert(
                names[(size_t)c],
                Imf::Slice(Imf::FLOAT, base + c * sizeof(float), x_stride, y_stride));
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        out->width = width;
        out->height = height;
        out->channels = channels;
        out->pixels = pixels;
        return 1;
    } catch (const std::bad_alloc &) {
        std::snprintf(err, err_size, "cannot read '%s': out of memory", path);
    } catch (const std::exception &e) {
        char why[400];
        exr_message(why, sizeof why, e.what());
        std::snprintf(err, err_size, "cannot read '%s': %s", path, why);
    }
    std::free(pixels);
    return 0;
}
