// The EXR plugin, spancast-exr.so: the only code that links OpenEXR
// (Imath, Iex, IlmThread, OpenEXRCore, libdeflate), loaded by the first EXR
// file written or read (image_plugin.c), so that no other run loads those
// libraries or runs their start-up. Its entry points are the
// spancast_exr_* functions of image_backend.h; they catch every exception.
//
// Below: what the scanline and the tiled EXR writers (image_exr.cpp,
// image_exr_tiled.cpp) do alike, so that a tiled file differs from a
// scanline file of the same image only in its layout. C++ only: these take
// OpenEXR's types and may throw its exceptions, which the callers catch.
#ifndef SPANCAST_FORMATS_EXR_IMAGE_EXR_H
#define SPANCAST_FORMATS_EXR_IMAGE_EXR_H

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfPixelType.h>
#include <Imath/half.h>

#include <cstddef>
#include <vector>

#include "formats/image_backend.h"

// An OpenEXR exception's text into err (trailing newlines and blanks
// dropped; "unknown OpenEXR error" when none is left).
void exr_message(char *err, size_t err_size, const char *what);

// Called in a handler of a std::exception: that exception as a message
// in err ("out of memory" for std::bad_alloc, else OpenEXR's text).
void exr_exception_message(char *err, size_t err_size);

// Adds img's metadata to header as string attributes: "Software", and
// with a camera, "comments" (OpenImageIO's name for the description) and
// "spancast:camera".
void exr_add_metadata(Imf::Header &header, const imgio_image *img);

// The values samples of pixels (of type sample) as the file stores them:
// 8-bit values as half (v / 255: exact for a mask's 0 and 255, as
// OpenImageIO converted them), converted into halves, which must outlive
// the returned data; floats as they are. Sets the file's sample type and
// the size of one sample.
const char *exr_samples(const void *pixels, imgio_sample sample, size_t values,
                        std::vector<Imath::half> &halves, Imf::PixelType &type,
                        size_t &sample_size);

#endif
