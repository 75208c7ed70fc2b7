/* hemiview.c -- GET /api/hemicube: what an element's hemicube sees, for
 * the page's teaching view of the shooter.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Cohen & Greenberg 1985 (hemicube.h): a half cube on the element's
 * centre, its five faces drawn as item buffers.  The answer holds, for
 * the scene as loaded, each pixel's element (-1: nothing; the top face
 * R x R, then the four sides R/2 x R, as radi_hemicube_row_items orders
 * them) and the row of F the hemicube gives (the sum of the delta form
 * factors of the pixels that show each element), so that the page can
 * draw the unfolded cube in the elements' colours and a student can see
 * where F_ij comes from.  The mesh is the converged solution's; a
 * hemicube is built for each request (R at most VIEW_HEMI_MAX, R even).
 */
#include <config.h>

#include <stdlib.h>

#include "view/viewint.h"
#include "hemicube/hemicube.h"
#include "mesh/mesh.h"
#include "util/util.h"

int view_hemicube_json(const view_session *s, int i, int res, jbuf *b, rad_error *err)
{
    rad_mesh unit;
    rad_frame fr;
    rad_hemicube *hc = NULL;
    const int n = s->mesh->nelements;
    const size_t np = 3 * (size_t)res * (size_t)res;
    double *row = malloc(sizeof *row * (size_t)(n ? n : 1));
    int *items = malloc(sizeof *items * np);
    if (!row || !items) {
        free(row);
        free(items);
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for a hemicube"), -1;
    }
    rad_status st = radi_mesh_normalized(s->mesh, &unit, &fr, err);
    if (st == RAD_OK) {
        st = radi_hemicube_create(&hc, &unit, res, err);
        if (st == RAD_OK)
            st = radi_hemicube_row_items(hc, i, row, items, err);
        radi_hemicube_free(hc);
        rad_mesh_free(&unit);
    }
    if (st == RAD_OK) {
        jb_printf(b, "{\"element\":%d,\"resolution\":%d,\"items\":[", i, res);
        for (size_t p = 0; p < np; p++)
            jb_printf(b, "%s%d", p ? "," : "", items[p]);
        jb_printf(b, "],\"row\":[");
        for (int j = 0; j < n; j++) {
            jb_printf(b, "%s", j ? "," : "");
            jb_num(b, row[j], 1);
        }
        jb_printf(b, "]}");
    }
    free(row);
    free(items);
    return st == RAD_OK ? 0 : -1;
}
