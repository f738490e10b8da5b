/* The builders' argument readers (build_curved.h): the model's readers
 * (model/args.h) seen through a build_ctx, and the 2D part of a
 * multmatrix. */
#include <string.h>

#include "build/build_curved.h"
#include "model/args.h"

static model_reader reader(const build_ctx *c)
{
    model_reader r = {c->file, c->error};
    return r;
}

const parse_value *build_arg(const parse_node *n, const char *name, int position)
{
    return model_arg(n, name, position);
}

sc_location build_loc(const build_ctx *c, const parse_value *v)
{
    model_reader r = reader(c);
    return model_loc(&r, v);
}

sc_status build_wrong_type(const build_ctx *c, const parse_node *n, const char *param,
                           const parse_value *v, const char *expected)
{
    model_reader r = reader(c);
    return model_wrong_type(&r, n, param, v, expected);
}

sc_status build_number(const build_ctx *c, const parse_node *n, const char *name,
                       int position, double *out)
{
    model_reader r = reader(c);
    return model_number(&r, n, name, position, out);
}

sc_status build_bool(const build_ctx *c, const parse_node *n, const char *name,
                     int position, int *out)
{
    model_reader r = reader(c);
    return model_bool(&r, n, name, position, out);
}

sc_status build_matrix(const build_ctx *c, const parse_node *n, double m[4][4])
{
    model_reader r = reader(c);
    return model_matrix(&r, n, m);
}

sc_status build_matrix_xy(const build_ctx *c, const parse_node *n,
                          const double outer[2][3], double inner[2][3])
{
    double a[4][4];
    sc_status st = build_matrix(c, n, a);
    if (st != SC_OK)
        return st;
    double o[2][3];
    memcpy(o, outer, sizeof o); /* inner may be outer */
    for (int r = 0; r < 2; r++) {
        inner[r][0] = o[r][0] * a[0][0] + o[r][1] * a[1][0];
        inner[r][1] = o[r][0] * a[0][1] + o[r][1] * a[1][1];
        inner[r][2] = o[r][0] * a[0][3] + o[r][1] * a[1][3] + o[r][2];
    }
    return SC_OK;
}

sc_status build_square(const build_ctx *c, const parse_node *n, double *sx, double *sy,
                       int *center)
{
    model_reader r = reader(c);
    return model_square(&r, n, sx, sy, center);
}

sc_status build_polygon(const build_ctx *c, const parse_node *n,
                        const parse_value **points, const parse_value **paths)
{
    model_reader r = reader(c);
    return model_polygon(&r, n, points, paths);
}

sc_status build_polygon_index(const build_ctx *c, const parse_value *v, uint32_t path,
                              uint32_t count, uint32_t *index)
{
    model_reader r = reader(c);
    return model_polygon_index(&r, v, path, count, index);
}

sc_status build_cube_args(const build_ctx *c, const parse_node *n, double size[3],
                          int *center)
{
    model_reader r = reader(c);
    return model_cube(&r, n, size, center);
}
