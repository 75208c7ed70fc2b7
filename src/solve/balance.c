/* balance.c -- the energy balance of a solution.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Emitted = absorbed + escaped, per band (Goral et al. 1984, eq. 6 summed
 * over the elements with their areas): with H = F B the irradiance of
 * Cohen et al. 1988, element i absorbs A_i (1 - rho_i) H_i and lets
 * A_i B_i (1 - sum_j F_ij) escape an open scene.  The residual is
 * max |B - rho H - E| relative to max |E|.  Every solver's report, the
 * distributed one's too, is filled here.
 */
#include <config.h>

#include <math.h>

#include "radiosity/base.h"
#include "radiosity/solve.h"
#include "solve/solvers.h"

/* The report's powers are sum A_i x_i in the user's units: the sums are
 * taken with the scaled areas and E (2^-ka, 2^-ke) and scaled back, so
 * they are inf only when the power itself exceeds the double range; the
 * balance, a ratio, is computed before that.  H = F B and rs, the row
 * sums of F, come from the caller (solvers.h). */
void radi_solve_balance(int n, const double *H, const double *rs, const double *rho,
                       const double *E, const double *B, const double *area, int ka, int ke,
                       rad_solve_report *rep)
{
    rep->row_sum_min = n ? HUGE_VAL : 0;
    rep->row_sum_max = n ? -HUGE_VAL : 0;
    for (int i = 0; i < n; i++) {
        rep->row_sum_min = fmin(rep->row_sum_min, rs[i]);
        rep->row_sum_max = fmax(rep->row_sum_max, rs[i]);
    }
    double emax = radi_max_abs(E, (size_t)n * RAD_BANDS), res = 0;
    for (int b = 0; b < RAD_BANDS; b++) {
        double em = 0, ab = 0, es = 0;
        for (int i = 0; i < n; i++) {
            size_t k = (size_t)i + (size_t)b * n;
            double a = area[i];
            res = fmax(res, fabs(B[k] - rho[k] * H[k] - E[k]));
            em += a * E[k];
            ab += a * (1 - rho[k]) * H[k];
            es += a * B[k] * (1 - rs[i]);
        }
        rep->emitted[b] = ldexp(em, ka + ke);
        rep->absorbed[b] = ldexp(ab, ka + ke);
        rep->escaped[b] = ldexp(es, ka + ke);
        rep->balance[b] = em > 0 ? (em - ab - es) / em : ldexp(em - ab - es, ka + ke);
    }
    rep->residual = emax > 0 ? res / emax : res;
}
