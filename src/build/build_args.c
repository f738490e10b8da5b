/* The 2D part of a multmatrix, for the builders of 2D subtrees
 * (build_ctx.h). */
#include <string.h>

#include "build/build_ctx.h"

sc_status build_matrix_xy(const build_ctx *c, const parse_node *n,
                          const double outer[2][3], double inner[2][3])
{
    double a[4][4];
    sc_status st = model_matrix(BUILD_READER(c), n, a);
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
