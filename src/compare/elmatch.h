/* elmatch.h -- another solver's element order, matched to ours by
 * centroid (internal).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Another solver numbers its elements its own way.  Given its element
 * table, in the format of `solve --elements` (tab- or space-separated, one
 * header line naming the columns, among them `element`, its 0-based index,
 * and `cx cy cz`, its centroid; other columns are ignored), each of its
 * elements is matched to the scene element whose centroid is nearest.
 *
 * The tolerance is RAD_MATCH_TOL times the diagonal of the scene's
 * bounding box: an element matches when exactly one of ours lies that
 * close.  None (the geometry differs), two (coincident centroids, as the
 * two sides of a thin wall) or one of ours claimed twice is an error
 * "FILE:LINE: ..." naming the element, as is a table whose element count
 * or indices are not the scene's 0..n-1.
 */
#ifndef RAD_ELMATCH_H
#define RAD_ELMATCH_H

#include "radiosity/base.h"
#include "radiosity/mesh.h"

#define RAD_MATCH_TOL 1e-6

/* perm[k] = the scene element matched to the table's element k (n =
 * mesh->nelements entries, caller-owned). */
rad_status radi_elements_match(const char *path, const rad_mesh *mesh, int *perm,
                              rad_error *err);

#endif /* RAD_ELMATCH_H */
