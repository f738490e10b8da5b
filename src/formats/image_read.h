/* Reading images as float pixels: PNG and EXR directly, every other format
 * through the OpenImageIO plugin (image_backend.h).
 *
 * Used by surface() for PNG height maps, and by the tests and tools that
 * check spancast's own outputs (masks, depth EXRs) against independent
 * expectations.
 */
#ifndef SPANCAST_FORMATS_IMAGE_READ_H
#define SPANCAST_FORMATS_IMAGE_READ_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct image_data {
    int width, height, channels;
    float *pixels; /* width * height * channels, row 0 at the top; malloc'd */
} image_data;

/* Reads the first subimage of path into *out as floats (8-bit values become
 * 0..1, 16-bit ones too); channels in OpenImageIO's order (R, G, B, A
 * first). Returns 1 on success; on failure 0 and a message in err. */
int image_read(const char *path, image_data *out, char *err, int err_size);

void image_data_free(image_data *img);

#ifdef __cplusplus
}
#endif

#endif
