/* The library's side of the XML plugin (xml.h): loads spancast-xml.so for
 * each document, parses, and drops the plugin's reference when the
 * document is freed; likewise for each zip archive opened. */
#include "formats/xml.h"

#include <string.h>

#include "formats/plugin.h"

int xml_parse(const char *text, size_t size, xml_doc *doc, char *err, size_t err_size,
              int *err_line)
{
    memset(doc, 0, sizeof *doc);
    *err_line = 0;
    static const char *const names[] = {"spancast_xml_parse", "spancast_xml_free"};
    void *fns[2];
    if (!plugin_load(XML_PLUGIN_FILE, "XML", names, 2, fns, &doc->plugin, err, err_size))
        return XML_ERR_PLUGIN;
    xml_parse_fn parse;
    /* Function pointers from dlsym: POSIX guarantees the conversion. */
    *(void **)&parse = fns[0];
    *(void **)&doc->release = fns[1];
    return parse(text, size, &doc->root, &doc->mem, err, err_size, err_line);
}

int xml_unzip(const char *data, size_t size, const char *entry, size_t max_size,
              char **out, size_t *out_size, char *single, size_t single_size, char *err,
              size_t err_size)
{
    *out = NULL;
    *out_size = 0;
    static const char *const names[] = {"spancast_xml_unzip"};
    void *fns[1], *handle = NULL;
    if (!plugin_load(XML_PLUGIN_FILE, "XML", names, 1, fns, &handle, err, err_size))
        return XML_ERR_PLUGIN;
    xml_unzip_fn unzip;
    /* Function pointers from dlsym: POSIX guarantees the conversion. */
    *(void **)&unzip = fns[0];
    int code = unzip(data, size, entry, max_size, out, out_size, single, single_size, err,
                     err_size);
    plugin_unload(&handle);
    return code;
}

void xml_free(xml_doc *doc)
{
    if (doc->release && doc->mem)
        doc->release(doc->mem);
    plugin_unload(&doc->plugin);
    memset(doc, 0, sizeof *doc);
}
const char *xml_attr_value(const xml_element *e, const char *name)
{
    for (uint32_t i = 0; i < e->attr_count; i++)
        if (!strcmp(e->attrs[i].name, name))
            return e->attrs[i].value;
    return NULL;
}
