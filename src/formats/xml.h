/* XML documents read into a small tree of elements, for the readers of
 * XML formats (svg.c, amf.c), and zip archives opened for a zipped AMF.
 * The parsing is libxml2's, the unzipping libzip's, in the plugin
 * spancast-xml.so (xml/xml_libxml2.c, xml/xml_zip.c) that the library loads
 * on the first XML file it reads: libxml2 brings ICU (about 30 MB of shared
 * objects), which no other run should load (plugin.h).
 *
 * The tree holds what the readers use: each element's qualified name
 * (prefix:name, as OpenSCAD's readers see it), its line, its attributes with entities
 * replaced, and the text directly inside it. Comments, processing
 * instructions and the DTD are left out; external entities and the
 * network are never read.
 */
#ifndef SPANCAST_FORMATS_XML_H
#define SPANCAST_FORMATS_XML_H

#include <stddef.h>
#include <stdint.h>

typedef struct xml_attr {
    const char *name; /* qualified name */
    const char *value;
} xml_attr;

typedef struct xml_element xml_element;
struct xml_element {
    const char *name; /* qualified name */
    int line;         /* of the start tag, from 1 (0: unknown) */
    uint32_t attr_count;
    const xml_attr *attrs;
    const char *text;                /* the text nodes directly inside, joined; "" */
    xml_element *first_child, *next; /* elements, in document order */
};

/* A parsed document: the root element and the memory that holds it. */
typedef struct xml_doc {
    xml_element *root;
    void *mem;               /* owned by the plugin; freed by xml_free */
    void *plugin;            /* the plugin's handle (plugin.h) */
    void (*release)(void *); /* the plugin's spancast_xml_free */
} xml_doc;

/* The plugin's entry points (xml/xml_libxml2.c). */
typedef int (*xml_parse_fn)(const char *text, size_t size, xml_element **root, void **mem,
                            char *err, size_t err_size, int *err_line);
typedef void (*xml_free_fn)(void *mem);
typedef int (*xml_unzip_fn)(const char *data, size_t size, const char *entry,
                            size_t max_size, char **out, size_t *out_size, char *single,
                            size_t single_size, char *err, size_t err_size);

#define XML_PLUGIN_FILE "spancast-xml.so"
/* Most elements of one document; most nesting. */
#define XML_MAX_ELEMENTS 20000000u
#define XML_MAX_DEPTH 256

enum {
    XML_OK = 0,
    XML_ERR_SYNTAX,
    XML_ERR_NOMEM,
    XML_ERR_LIMIT,
    XML_ERR_PLUGIN,
    XML_NOT_ZIP /* xml_unzip: the data is not a zip archive */
};

/* Parses size bytes of text into *doc. Returns XML_OK, or an XML_ERR_ code
 * with a message in err (libxml2's, its first line) and the document's
 * line in *err_line (0 when there is none). Free with xml_free, also
 * after an error. */
int xml_parse(const char *text, size_t size, xml_doc *doc, char *err, size_t err_size,
              int *err_line);
void xml_free(xml_doc *doc);

/* An entry of the zip archive data (size bytes), as OpenSCAD 2021.01 reads
 * a zipped AMF with libzip (xml/xml_zip.c): the entry named entry in any
 * folder, else the archive's only entry, whose name then goes to single
 * ("" otherwise). Returns XML_OK with the entry's bytes in *out (malloc'd,
 * NUL-terminated, *out_size bytes without the NUL); XML_NOT_ZIP when
 * libzip cannot open data as an archive; XML_ERR_SYNTAX when there is no
 * such entry or it cannot be read, XML_ERR_LIMIT past max_size bytes,
 * XML_ERR_NOMEM, XML_ERR_PLUGIN, each with a message in err. */
int xml_unzip(const char *data, size_t size, const char *entry, size_t max_size,
              char **out, size_t *out_size, char *single, size_t single_size, char *err,
              size_t err_size);

/* The value of e's attribute name, or NULL. */
const char *xml_attr_value(const xml_element *e, const char *name);

#endif
