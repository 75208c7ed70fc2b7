/* analytic.h -- closed-form form factors (internal helpers).
 *
 * Copyright (C) 2026 The radiosity authors.
 * This program is free software: you can redistribute it and/or modify it
 * under the terms of the GNU General Public License as published by the Free
 * Software Foundation, either version 3 of the License, or (at your option)
 * any later version.  See COPYING.
 *
 * The four public closed forms (rad_analytic_point_disk, _disk_disk,
 * _parallel_rectangles, _perpendicular_rectangles) are declared in
 * radiosity.h.  The helpers below are the cancellation-free building blocks
 * they share; they are exported (with the rad_ prefix) so that the form
 * factor kernel and the tests may use them.  Every helper takes
 * non-negative finite arguments and returns a non-negative value with a
 * relative error of a few units in the last place.
 */
#ifndef RAD_ANALYTIC_H
#define RAD_ANALYTIC_H

#include "radiosity/formfactor.h"

#ifdef __cplusplus
extern "C" {
#endif

/* tau(u) = u - atan(u), u >= 0, without cancellation. */
double radi_analytic_u_minus_atan(double u);

/* phi(p) = atan(p) - p / (1 + p^2), p >= 0, without cancellation. */
double radi_analytic_atan_minus_rational(double p);

#ifdef __cplusplus
}
#endif

#endif /* RAD_ANALYTIC_H */
