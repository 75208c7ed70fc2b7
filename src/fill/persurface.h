/* persurface.h -- form factors between whole surfaces, from the elements'.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_PERSURFACE_H
#define RAD_PERSURFACE_H

#include "radiosity/mesh.h"

/* The surface-to-surface form factors of a meshed scene, the area-weighted
 * sums of its element factors (additivity, Siegel & Howell, "Thermal
 * Radiation Heat Transfer", the factor from a sum of areas):
 *     F_SK = (1 / A_S) sum_{i in S} sum_{j in K} A_i F_ij,
 *     A_S  = sum_{i in S} A_i.
 * F is the n x n element matrix (F[i + j*n] = F_ij), FS the ns x ns result
 * (FS[S + K*ns] = F_SK, ns = mesh->nsurfaces).  If E (the elements'
 * estimated absolute errors) and ES are not NULL, ES receives the same sums
 * of E: a bound on F_SK's error when every |dF_ij| <= E_ij.  AS (ns
 * doubles) receives the surface areas A_S. */
void radi_ff_surfaces(const rad_mesh *mesh, const double *F, const double *E, double *FS,
                     double *ES, double *AS);

#endif /* RAD_PERSURFACE_H */
