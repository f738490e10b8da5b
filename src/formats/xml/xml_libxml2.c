/* spancast-xml.so: XML documents parsed by libxml2 into the small tree of
 * xml.h. The only code that links libxml2, loaded on demand (xml.c).
 *
 * The document is parsed whole (xmlCtxtReadMemory) without the network,
 * without loading external DTDs or entities, and with libxml2's own limits
 * on entity expansion left on; then copied element by element into one
 * block list that the library frees with spancast_xml_free.
 */
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/xml.h"

/* Memory: blocks linked through their first word. */
typedef struct block {
    struct block *next;
    size_t used, size;
    _Alignas(16) unsigned char data[];
} block;

typedef struct copier {
    block *head;
    size_t elements;
    int failed; /* XML_ERR_NOMEM or XML_ERR_LIMIT */
} copier;

static void *take(copier *c, size_t size)
{
    size = (size + 15) & ~(size_t)15;
    if (!c->head || c->head->size - c->head->used < size) {
        size_t want = size > 65536 ? size : 65536;
        block *b = malloc(sizeof *b + want);
        if (!b) {
            c->failed = XML_ERR_NOMEM;
            return NULL;
        }
        b->next = c->head;
        b->used = 0;
        b->size = want;
        c->head = b;
    }
    void *p = c->head->data + c->head->used;
    c->head->used += size;
    return p;
}

static const char *copy_string(copier *c, const char *s)
{
    size_t n = strlen(s);
    char *out = take(c, n + 1);
    if (out)
        memcpy(out, s, n + 1);
    return out;
}

/* The qualified name (prefix:name) of a node, as libxml2's reader gives
 * it (xmlTextReaderName), which OpenSCAD's readers compare. */
static const char *qualified(copier *c, const xmlNs *ns, const xmlChar *name)
{
    if (!ns || !ns->prefix)
        return copy_string(c, (const char *)name);
    size_t a = strlen((const char *)ns->prefix), b = strlen((const char *)name);
    char *out = take(c, a + b + 2);
    if (out) {
        memcpy(out, ns->prefix, a);
        out[a] = ':';
        memcpy(out + a + 1, name, b + 1);
    }
    return out;
}

static xml_element *copy_element(copier *c, xmlNode *node, int depth)
{
    if (depth > XML_MAX_DEPTH || ++c->elements > XML_MAX_ELEMENTS) {
        c->failed = XML_ERR_LIMIT;
        return NULL;
    }
    xml_element *e = take(c, sizeof *e);
    if (!e)
        return NULL;
    memset(e, 0, sizeof *e);
    e->name = qualified(c, node->ns, node->name);
    e->line = node->line > 0 ? node->line : 0;
    uint32_t count = 0;
    for (xmlAttr *a = node->properties; a; a = a->next)
        count++;
    xml_attr *attrs = count ? take(c, count * sizeof *attrs) : NULL;
    if (count && !attrs)
        return NULL;
    uint32_t i = 0;
    for (xmlAttr *a = node->properties; a; a = a->next, i++) {
        xmlChar *value = xmlNodeListGetString(node->doc, a->children, 1);
        attrs[i].name = qualified(c, a->ns, a->name);
        attrs[i].value = copy_string(c, value ? (const char *)value : "");
        xmlFree(value);
        if (c->failed)
            return NULL;
    }
    e->attrs = attrs;
    e->attr_count = count;
    /* the text directly inside, joined */
    size_t text_size = 0;
    for (xmlNode *k = node->children; k; k = k->next)
        if ((k->type == XML_TEXT_NODE || k->type == XML_CDATA_SECTION_NODE) && k->content)
            text_size += strlen((const char *)k->content);
    char *text = take(c, text_size + 1);
    if (!text)
        return NULL;
    text[0] = 0;
    size_t at = 0;
    xml_element **link = &e->first_child;
    for (xmlNode *k = node->children; k; k = k->next) {
        if ((k->type == XML_TEXT_NODE || k->type == XML_CDATA_SECTION_NODE) &&
            k->content) {
            size_t n = strlen((const char *)k->content);
            memcpy(text + at, k->content, n + 1);
            at += n;
        } else if (k->type == XML_ELEMENT_NODE) {
            xml_element *child = copy_element(c, k, depth + 1);
            if (!child)
                return NULL;
            *link = child;
            link = &child->next;
        }
    }
    e->text = text;
    return c->failed ? NULL : e;
}

void spancast_xml_free(void *mem)
{
    for (block *b = mem; b;) {
        block *next = b->next;
        free(b);
        b = next;
    }
}

int spancast_xml_parse(const char *text, size_t size, xml_element **root, void **mem,
                       char *err, size_t err_size, int *err_line)
{
    *root = NULL;
    *mem = NULL;
    *err_line = 0;
    if (size > (size_t)0x7fffffff) {
        snprintf(err, err_size, "file too large for the XML parser");
        return XML_ERR_LIMIT;
    }
    xmlParserCtxtPtr ctxt = xmlNewParserCtxt();
    if (!ctxt) {
        snprintf(err, err_size, "out of memory");
        return XML_ERR_NOMEM;
    }
    xmlDocPtr doc =
        xmlCtxtReadMemory(ctxt, text, (int)size, NULL, NULL,
                          XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    if (!doc || !ctxt->wellFormed) {
        const xmlError *e = &ctxt->lastError;
        const char *message = e->message ? e->message : "not well-formed XML";
        size_t n = strlen(message);
        while (n && (message[n - 1] == '\n' || message[n - 1] == ' '))
            n--;
        snprintf(err, err_size, "%.*s", (int)n, message);
        *err_line = e->line > 0 ? e->line : 0;
        xmlFreeDoc(doc);
        xmlFreeParserCtxt(ctxt);
        return XML_ERR_SYNTAX;
    }
    xmlNode *top = xmlDocGetRootElement(doc);
    copier c = {NULL, 0, 0};
    int status = XML_OK;
    if (!top) {
        snprintf(err, err_size, "no root element");
        status = XML_ERR_SYNTAX;
    } else if (!(*root = copy_element(&c, top, 0))) {
        status = c.failed ? c.failed : XML_ERR_NOMEM;
        snprintf(err, err_size, "%s",
                 status == XML_ERR_LIMIT ? "too many or too deeply nested elements"
                                         : "out of memory");
    }
    *mem = c.head;
    xmlFreeDoc(doc);
    xmlFreeParserCtxt(ctxt);
    return status;
}
