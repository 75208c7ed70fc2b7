/* progress_snap.h -- the snapshots of `radiosity progress` (command side).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * One snapshot is PREFIX-METHOD-STEP.png, and on request its error picture
 * PREFIX-METHOD-STEP-error.png and element table PREFIX-METHOD-STEP.tsv.
 * The mesh is given with each snapshot, so the adaptive race (whose mesh
 * changes every step) and the fixed-mesh race share this code.
 */
#ifndef RAD_PROGRESS_SNAP_H
#define RAD_PROGRESS_SNAP_H

#include "solve/solve.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/render.h"

typedef struct progress_snap {
    const char *prefix;
    rad_render_options ropt;    /* camera and exposure of every picture */
    int error_images;           /* --error-images */
    int elements;               /* --snapshot-elements */
    rad_error err;              /* why the snapshots stopped */
    int failed;
} progress_snap;

/* What one snapshot shows. */
typedef struct progress_frame {
    const rad_mesh *mesh;
    const double *B, *Bv;       /* elements, vertices (n x RAD_BANDS, nv x RAD_BANDS) */
    const double *Bref;         /* the converged solution on these elements */
    const int *level;           /* --adaptive: the table's last column, or NULL */
} progress_frame;

/* The snapshot of `method` after `step` steps; 0, or 1 (c->failed, c->err). */
int progress_snap_write(progress_snap *c, int method, int step, const progress_frame *f);

/* Every snapshot goes beside the first: the directory, and the first
 * step's picture, error picture and table of methods first .. last,
 * checked before the work.  0, or 1 (printed). */
int progress_snap_check(const char *prefix, const rad_race_options *race, int error_images,
                        int elements, int first);

#endif /* RAD_PROGRESS_SNAP_H */
