// Tiled EXR files written tile by tile, for images too large to hold whole.
//
// A render that streams its outputs (image_stream.h) hands each finished
// tile to imgio_exr_tiles_write (image_plugin.c), and so to
// spancast_exr_tiles_write here, as soon as it has it. The file is a single
// tiled part with square tiles of one level, ZIP compression (each tile
// compressed on its own) and the channels, sample types and metadata of
// spancast_exr_write, so that only the layout differs from a scanline file of
// the same image. Tiles are written in INCREASING_Y order (row by row,
// left to right): the caller delivers them in that order, so OpenEXR
// writes each at once and buffers nothing, and the file's bytes do not
// depend on when each tile was finished. Memory is one tile's conversion
// buffer and OpenEXR's table of tile offsets (8 bytes a tile).
//
// As in image_exr.cpp, OpenEXR's exceptions become messages here and
// never leave this file.
#include "formats/exr/image_exr.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfTileDescription.h>
#include <OpenEXR/ImfTiledOutputFile.h>
#include <Imath/half.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

struct exr_tiles {
    std::unique_ptr<Imf::TiledOutputFile> file;
    int width, height, tile, channels;
    std::vector<std::string> names;
    imgio_sample sample;
    std::vector<Imath::half> halves; // one tile of 8-bit values as half
};

extern "C" exr_tiles *spancast_exr_tiles_open(const imgio_image *img, int tile,
                                              const char *path, char *err,
                                              size_t err_size)
{
    exr_tiles *t = nullptr;
    try {
        t = new exr_tiles;
        t->width = img->width;
        t->height = img->height;
        t->tile = tile;
        t->channels = img->channels;
        t->sample = img->sample;
        for (int c = 0; c < img->channels; c++)
            t->names.push_back(img->channel_names[c]);
        Imf::Header header(img->width, img->height);
        header.compression() = Imf::ZIP_COMPRESSION;
        header.lineOrder() = Imf::INCREASING_Y;
        header.setTileDescription(Imf::TileDescription((unsigned)tile, (unsigned)tile,
                                                       Imf::ONE_LEVEL, Imf::ROUND_DOWN));
        exr_add_metadata(header, img);
        Imf::PixelType type = img->sample == IMGIO_UINT8 ? Imf::HALF : Imf::FLOAT;
        for (int c = 0; c < img->channels; c++)
            header.channels().insert(img->channel_names[c], Imf::Channel(type));
        t->file.reset(new Imf::TiledOutputFile(path, header));
        return t;
    } catch (const std::exception &) {
        exr_exception_message(err, err_size);
    }
    delete t;
    return nullptr;
}

extern "C" int spancast_exr_tiles_write(exr_tiles *t, int tx, int ty, const void *pixels,
                                        char *err, size_t err_size)
{
    try {
        int w = t->width - tx * t->tile < t->tile ? t->width - tx * t->tile : t->tile;
        int h = t->height - ty * t->tile < t->tile ? t->height - ty * t->tile : t->tile;
        size_t values = (size_t)w * (size_t)h * (size_t)t->channels;
        Imf::PixelType type;
        size_t sample_size;
        const char *data =
            exr_samples(pixels, t->sample, values, t->halves, type, sample_size);
        // Slices in tile coordinates: pixel (x, y) of the tile at
        // data + x * x_stride + y * y_stride.
        Imf::FrameBuffer frame;
        size_t x_stride = sample_size * (size_t)t->channels;
        for (int c = 0; c < t->channels; c++)
            frame.insert(t->names[(size_t)c],
                         Imf::Slice(type, const_cast<char *>(data) + c * sample_size,
                                    x_stride, x_stride * (size_t)w, 1, 1, 0.0, true,
                                    true));
        t->file->setFrameBuffer(frame);
        t->file->writeTile(tx, ty);
        return 1;
    } catch (const std::exception &) {
        exr_exception_message(err, err_size);
    }
    return 0;
}

extern "C" int spancast_exr_tiles_close(exr_tiles *t, char *err, size_t err_size)
{
    if (!t)
        return 1;
    int ok = 1;
    try {
        t->file.reset(); // writes the tile offsets and closes the file
    } catch (const std::exception &) {
        exr_exception_message(err, err_size);
        ok = 0;
    }
    delete t;
    return ok;
}
