/* The zip side of spancast-xml.so: an entry of a zip archive held in
 * memory, read by libzip as OpenSCAD 2021.01 reads a zipped AMF
 * (import_amf.cc): the entry whose name, without its folders, is the one
 * asked for (ZIP_FL_NODIR), else the archive's only entry. libzip stays in
 * this plugin, beside libxml2, so that only a run reading an XML file
 * loads it (xml.h). The entry grows by the project's rule (base/grow.c,
 * built into the plugin).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zip.h>

#include "base/grow.h"
#include "formats/xml.h"

/* The reading end of an entry: its bytes into a malloc'd buffer of at
 * most max_size bytes, NUL-terminated. */
static int read_entry(zip_t *archive, zip_uint64_t index, size_t max_size, char **out,
                      size_t *out_size, char *err, size_t err_size)
{
    zip_file_t *file = zip_fopen_index(archive, index, 0);
    if (!file) {
        snprintf(err, err_size, "%s", zip_strerror(archive));
        return XML_ERR_SYNTAX;
    }
    size_t size = 0, cap = 0;
    char *text = NULL;
    int code = XML_OK;
    for (;;) {
        /* a chunk and the NUL */
        if (!grow_array((void **)&text, &cap, size + 65536 + 1, 1)) {
            code = XML_ERR_NOMEM;
            break;
        }
        zip_int64_t got = zip_fread(file, text + size, 65536);
        if (got < 0) {
            snprintf(err, err_size, "%s", zip_file_strerror(file));
            code = XML_ERR_SYNTAX;
            break;
        }
        if (got == 0)
            break;
        size += (size_t)got;
        if (size > max_size) {
            snprintf(err, err_size, "the zipped entry is larger than %zu bytes",
                     max_size);
            code = XML_ERR_LIMIT;
            break;
        }
    }
    zip_fclose(file);
    if (code != XML_OK) {
        free(text);
        return code;
    }
    text[size] = 0;
    *out = text;
    *out_size = size;
    return XML_OK;
}

int spancast_xml_unzip(const char *data, size_t size, const char *entry, size_t max_size,
                       char **out, size_t *out_size, char *single, size_t single_size,
                       char *err, size_t err_size);

int spancast_xml_unzip(const char *data, size_t size, const char *entry, size_t max_size,
                       char **out, size_t *out_size, char *single, size_t single_size,
                       char *err, size_t err_size)
{
    *out = NULL;
    *out_size = 0;
    if (single_size)
        single[0] = 0;
    if (err_size)
        err[0] = 0;
    zip_error_t why;
    zip_error_init(&why);
    zip_source_t *source = zip_source_buffer_create(data, size, 0, &why);
    if (!source) {
        zip_error_fini(&why);
        return XML_ERR_NOMEM;
    }
    /* as OpenSCAD: a file libzip cannot open as an archive is read as it
     * is */
    zip_t *archive = zip_open_from_source(source, ZIP_RDONLY, &why);
    zip_error_fini(&why);
    if (!archive) {
        zip_source_free(source);
        return XML_NOT_ZIP;
    }
    int code;
    zip_int64_t index = zip_name_locate(archive, entry, ZIP_FL_NODIR);
    if (index < 0 && zip_get_num_entries(archive, 0) == 1) {
        index = 0;
        const char *name = zip_get_name(archive, 0, 0);
        snprintf(single, single_size, "%s", name ? name : "");
    }
    if (index < 0) {
        snprintf(err, err_size, "none of its %lld entries is named '%s'",
                 (long long)zip_get_num_entries(archive, 0), entry);
        code = XML_ERR_SYNTAX;
    } else {
        code = read_entry(archive, (zip_uint64_t)index, max_size, out, out_size, err,
                          err_size);
    }
    zip_discard(archive); /* frees the source too */
    return code;
}
