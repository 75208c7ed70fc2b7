/* cholesky.c -- the radiosity system in its symmetric form, by Cholesky.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * With reciprocity A_i F_ij = A_j F_ji (Goral et al. 1984, eq. 4) the
 * system M B = E, M = I - diag(rho) F, becomes symmetric when multiplied
 * by diag(A/rho): (diag(A/rho) - diag(A) F) B = diag(A/rho) E.  Elements
 * with rho_i = 0 have B_i = E_i; they leave the unknowns (set Z) and their
 * light moves to the right-hand side of the others (set P):
 *
 *     M_PP B_P = E_P + diag(rho_P) F_PZ E_Z.
 *
 * Scaled to a unit diagonal, with D = diag(sqrt(rho_i / A_i)) on P,
 *
 *     K = D^-1 M_PP D,   K_ij = delta_ij - sqrt(rho_i rho_j) sqrt(A_i / A_j) F_ij,
 *     K y = D^-1 (E_P + diag(rho_P) F_PZ E_Z),   B_P = D y,
 *
 * and K is symmetric.  Its eigenvalues lie in [1 - q, 1 + q] with
 * q = max_i rho_i sum_j |F_ij| = ||diag(rho) F||_inf: K - I is similar to
 * -diag(rho) F (through D and diag(sqrt A)), a symmetric matrix's 2-norm
 * is its spectral radius, and the spectral radius is at most any induced
 * norm.  So K is positive definite whenever q < 1, that is when every
 * rho < 1 in a closed scene (rows of F sum to 1) or any scene with
 * rho <= 1 and row sums < 1; and cond_2(K) <= (1 + q) / (1 - q).  The
 * scaling changes nothing in exact arithmetic, and Cholesky's backward
 * error bound is invariant under it (Higham 2002, Accuracy and Stability
 * of Numerical Algorithms, 2nd ed., thm. 10.5 and section 10.1.1, after
 * van der Sluis): the unit diagonal only makes dpocon's estimate say how
 * well the system is posed, not how unevenly the elements are sized.
 *
 * Only K's upper triangle is built, from F's upper triangle (F_ij, i < j),
 * and dpotrf reads nothing else: F's lower triangle, which equals the
 * reciprocal of the upper one only to round-off (two roundings in the
 * fill, ffmatrix.c), cannot make K unsymmetric.  Reciprocity is checked
 * first (fpass.h, 1e-12 relative); a matrix that fails it would turn
 * into another system, and goes to LU instead.  So does one that dpotrf
 * finds not positive definite (rho = 1 in a closed scene, or classic
 * mode's form factors below 0 or above 1): the report's `fallback` says
 * why, nothing is printed.  Cholesky does n^3/3 flops against LU's
 * 2n^3/3, and needs no pivots.
 *
 * Diagnostics as for gauss (solve.c): the reciprocal condition estimate of
 * K (dpocon, 1-norm), and with the form factors' error bound dF the
 * bound k / (1 - k), k = rho_max ||dF||_inf ||M^-1||_inf (Higham 2002,
 * thm. 7.2), with ||M^-1||_inf = ||M^-T||_1 estimated by Hager and
 * Higham's method (LAPACK dlacn2; Higham 2002, algorithm 15.4) through the
 * factor of K: M^-1 and M^-T are applied as block triangular inverses,
 * M having the rows of Z equal to those of I.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#else
#define omp_get_max_threads() 1
#define omp_get_thread_num() 0
#endif

#include "solve/fpass.h"
#include "util/util.h"
#include "solve/solvers.h"


void radi_report_fallback(rad_solve_report *rep, const char *why)
{
    size_t len = strlen(rep->fallback);
    rep->fallbacks++;
    if (len + 3 < sizeof rep->fallback)
        snprintf(rep->fallback + len, sizeof rep->fallback - len, "%s%s", len ? "; " : "", why);
}

/* One reflectance set: P, the scalings and the factor of K. */
typedef struct chol_sys {
    int n, np;
    const double *F, *rho;
    int *idx;          /* np: P in ascending order */
    int *zdx, nz;      /* nz: Z */
    double *v;         /* np: D = diag(v), v_i = sqrt(rho_i / A_i) */
    double *w;         /* np: w_i = sqrt(rho_i A_i) */
    double *K;         /* np x np, upper triangle: K, then its factor */
    double anorm;      /* ||K||_1 */
} chol_sys;

static void sys_free(chol_sys *s)
{
    free(s->idx);
    free(s->zdx);
    free(s->v);
    free(s->w);
    free(s->K);
}

static int sys_alloc(chol_sys *s, const rad_mesh *m, const double *F, const double *rho)
{
    const int n = m->nelements;
    memset(s, 0, sizeof *s);
    s->n = n;
    s->F = F;
    s->rho = rho;
    s->idx = malloc(sizeof *s->idx * (size_t)(n + 1));
    s->zdx = malloc(sizeof *s->zdx * (size_t)(n + 1));
    s->v = malloc(sizeof *s->v * (size_t)(n + 1));
    s->w = malloc(sizeof *s->w * (size_t)(n + 1));
    if (!s->idx || !s->zdx || !s->v || !s->w)
        return -1;
    for (int i = 0; i < n; i++) {
        const double a = m->elements[i].area;
        if (rho[i] > 0) {
            s->v[s->np] = sqrt(rho[i] / a);
            s->w[s->np] = sqrt(rho[i] * a);
            s->idx[s->np++] = i;
        } else {
            s->zdx[s->nz++] = i;
        }
    }
    s->K = malloc(sizeof *s->K * ((size_t)s->np * s->np + 1));
    return s->K ? 0 : -1;
}

/* K's upper triangle from F's, K_ij = -w_i F_ij v_j (i < j), and ||K||_1
 * from the column sums of |K| (K symmetric: row i of the lower part is
 * column i of the upper).  Each thread adds into its own row sums. */
static int sys_build(chol_sys *s)
{
    const int np = s->np, n = s->n, nt = omp_get_max_threads();
    double *sum = calloc((size_t)np * nt + 1, sizeof *sum);
    if (!sum)
        return -1;
#pragma omp parallel for schedule(dynamic, 16)
    for (int jj = 0; jj < np; jj++) {
        double *my = sum + (size_t)np * omp_get_thread_num();
        const double *fj = s->F + (size_t)s->idx[jj] * n;
        double *kj = s->K + (size_t)jj * np, col = 0;
        const double vj = s->v[jj];
        for (int ii = 0; ii < jj; ii++) {
            const double k = -s->w[ii] * fj[s->idx[ii]] * vj;
            kj[ii] = k;
            col += fabs(k);
            my[ii] += fabs(k);
        }
        kj[jj] = 1 - s->rho[s->idx[jj]] * fj[s->idx[jj]];
        my[jj] += col + fabs(kj[jj]);
    }
    s->anorm = 0;
    for (int ii = 0; ii < np; ii++) {
        double c = 0;
        for (int t = 0; t < nt; t++)
            c += sum[(size_t)np * t + ii];
        s->anorm = fmax(s->anorm, c);
    }
    free(sum);
    return 0;
}

/* X := M^-1 X for nrhs columns of length n (leading dimension n):
 * X_P := D K^-1 D^-1 (X_P + diag(rho_P) F_PZ X_Z), X_Z unchanged.  t is
 * np x nrhs scratch. */
static void apply_minv(const chol_sys *s, double *X, int nrhs, double *t)
{
    const int np = s->np, n = s->n;
    int info;
    for (int r = 0; r < nrhs; r++) {
        double *x = X + (size_t)r * n, *tr = t + (size_t)r * np;
        for (int ii = 0; ii < np; ii++)
            tr[ii] = 0;
        for (int z = 0; z < s->nz; z++) { /* F_PZ x_Z, column by column */
            const double xz = x[s->zdx[z]], *fz = s->F + (size_t)s->zdx[z] * n;
            if (xz != 0)
                for (int ii = 0; ii < np; ii++)
                    tr[ii] += fz[s->idx[ii]] * xz;
        }
        for (int ii = 0; ii < np; ii++) {
            const int i = s->idx[ii];
            tr[ii] = (x[i] + s->rho[i] * tr[ii]) / s->v[ii];
        }
    }
    if (np > 0)
        dpotrs_("U", &np, &nrhs, s->K, &np, t, &np, &info, 1);
    for (int r = 0; r < nrhs; r++)
        for (int ii = 0; ii < np; ii++)
            X[(size_t)s->idx[ii] + (size_t)r * n] = s->v[ii] * t[(size_t)ii + (size_t)r * np];
}

/* x := M^-T x: x_P := D^-1 K^-1 D x_P, then x_Z := x_Z + F_PZ^T diag(rho_P) x_P. */
static void apply_minvt(const chol_sys *s, double *x, double *t)
{
    const int np = s->np, n = s->n, one = 1;
    int info;
    for (int ii = 0; ii < np; ii++)
        t[ii] = s->v[ii] * x[s->idx[ii]];
    if (np > 0)
        dpotrs_("U", &np, &one, s->K, &np, t, &np, &info, 1);
    for (int ii = 0; ii < np; ii++)
        x[s->idx[ii]] = t[ii] / s->v[ii];
    for (int z = 0; z < s->nz; z++) {
        const double *fz = s->F + (size_t)s->zdx[z] * n;
        double sum = 0;
        for (int ii = 0; ii < np; ii++)
            sum += fz[s->idx[ii]] * s->rho[s->idx[ii]] * x[s->idx[ii]];
        x[s->zdx[z]] += sum;
    }
}

/* ||M^-1||_inf = ||M^-T||_1 by dlacn2 (Higham 2002, alg. 15.4): kase 1
 * applies the operator M^-T, kase 2 its transpose M^-1.  -1 on no memory. */
static double minv_norm_inf(const chol_sys *s)
{
    const int n = s->n;
    double *v = malloc(sizeof *v * (size_t)n), *x = malloc(sizeof *x * (size_t)n);
    double *t = malloc(sizeof *t * (size_t)(s->np + 1)), est = -1;
    int *isgn = malloc(sizeof *isgn * (size_t)n), kase = 0, isave[3];
    if (v && x && t && isgn) {
        do {
            dlacn2_(&n, v, x, isgn, &est, &kase, isave);
            if (kase == 1)
                apply_minvt(s, x, t);
            else if (kase == 2)
                apply_minv(s, x, 1, t);
        } while (kase != 0);
    }
    free(v);
    free(x);
    free(t);
    free(isgn);
    return est;
}

/* The bound F's error puts on B, as gauss (lusolve.c); RAD_ERR_SINGULAR
 * when that error could make the system singular. */
static rad_status ff_bound(const chol_sys *s, const rad_solve_options *opt,
                           rad_solve_report *rep, rad_error *err)
{
    double rho_max = 0;
    for (int i = 0; i < s->n; i++)
        rho_max = fmax(rho_max, s->rho[i]);
    const double ninv = minv_norm_inf(s);
    if (ninv < 0)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    const double k = rho_max * opt->ff_row_error * ninv;
    const double bound = k < 1 ? k / (1 - k) : INFINITY;
    rep->ff_error_bound = isnan(rep->ff_error_bound) ? bound : fmax(rep->ff_error_bound, bound);
    if (!(k < 1))
        return radi_fail(err, RAD_ERR_SINGULAR,
                        "the radiosity system is singular within the accuracy of its form "
                        "factors: their error (up to %.3g per row) could make it singular "
                        "(||(I - rho F)^-1|| ||rho dF|| = %.3g >= 1); a closed enclosure "
                        "that reflects (nearly) everything needs them exact",
                        opt->ff_row_error, k);
    return RAD_OK;
}

/* Factor K for one reflectance set and solve the bands in bands[0..nb).
 * Returns RAD_OK, an error, or RAD_ERR_SINGULAR with *not_pd set when
 * dpotrf found K not positive definite (nothing written to B then). */
static rad_status solve_set(const rad_mesh *m, const double *F, const double *rho,
                            const double *E, double *B, const int *bands, int nb,
                            const rad_solve_options *opt, rad_solve_report *rep, int *not_pd,
                            rad_error *err)
{
    const int n = m->nelements;
    chol_sys s;
    rad_status st = RAD_OK;
    double *X = malloc(sizeof *X * (size_t)n * nb), *t = NULL, *work = NULL, rcond = 1;
    int *iwork = NULL, info = 0;
    *not_pd = 0;
    if (sys_alloc(&s, m, F, rho) || !X || sys_build(&s)) {
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory for the %d x %d system", n, n);
        goto done;
    }
    t = malloc(sizeof *t * ((size_t)s.np * nb + 1));
    work = malloc(sizeof *work * (3 * (size_t)s.np + 1));
    iwork = malloc(sizeof *iwork * ((size_t)s.np + 1));
    if (!t || !work || !iwork) {
        st = radi_fail(err, RAD_ERR_NOMEM, "out of memory");
        goto done;
    }
    if (s.np > 0) {
        dpotrf_("U", &s.np, s.K, &s.np, &info, 1);
        if (info > 0) {
            char why[160];
            snprintf(why, sizeof why, "the symmetric form is not positive definite (its "
                     "leading %d x %d block is not): solved by LU", info, info);
            radi_report_fallback(rep, why);
            *not_pd = 1;
            st = RAD_ERR_SINGULAR;
            goto done;
        }
        dpocon_("U", &s.np, s.K, &s.np, &s.anorm, &rcond, work, iwork, &info, 1);
    }
    rep->rcond = rep->systems == 1 ? rcond : fmin(rep->rcond, rcond);
    if (!(rcond >= RAD_RCOND_MIN)) {
        st = radi_fail(err, RAD_ERR_SINGULAR,
                      "the radiosity system is singular (reciprocal condition %.3g < %g): "
                      "a closed enclosure that reflects everything (rho = 1) never "
                      "absorbs light, so no steady state exists",
                      rcond, RAD_RCOND_MIN);
        goto done;
    }
    if (opt->ff_row_error >= 0 && (st = ff_bound(&s, opt, rep, err)) != RAD_OK)
        goto done;
    for (int k = 0; k < nb; k++)
        memcpy(X + (size_t)k * n, E + (size_t)bands[k] * n, sizeof *X * (size_t)n);
    apply_minv(&s, X, nb, t); /* B = M^-1 E, B_Z = E_Z */
    for (int k = 0; k < nb; k++)
        memcpy(B + (size_t)bands[k] * n, X + (size_t)k * n, sizeof *B * (size_t)n);
done:
    sys_free(&s);
    free(X);
    free(t);
    free(work);
    free(iwork);
    return st;
}

/* Is F reciprocal enough for the symmetric form?  0 yes, 1 no (the
 * reason in the report), -1 out of memory. */
static int check_reciprocity(const rad_mesh *m, const double *F, rad_solve_report *rep)
{
    const int n = m->nelements;
    double *area = malloc(sizeof *area * (size_t)(n + 1));
    rad_fscan sc;
    if (!area)
        return -1;
    for (int i = 0; i < n; i++)
        area[i] = m->elements[i].area;
    int r = radi_fscan_run(n, F, area, &sc);
    free(area);
    if (r)
        return -1;
    if (sc.defect > RAD_RECIPROCITY_TOL) {
        char why[200];
        snprintf(why, sizeof why, "F is not reciprocal (A_i F_ij and A_j F_ji differ by %.3g "
                 "relative at i = %d, j = %d; > %g): solved by LU", sc.defect, sc.di, sc.dj,
                 RAD_RECIPROCITY_TOL);
        radi_report_fallback(rep, why);
        r = 1;
    }
    radi_fscan_free(&sc);
    return r;
}

rad_status radi_solve_cholesky(const rad_mesh *m, const double *F, const double *rho,
                              const double *E, double *B, const rad_solve_options *opt,
                              rad_solve_report *rep, rad_error *err)
{
    const int n = m->nelements;
    int done[RAD_BANDS] = {0}, bands[RAD_BANDS], nb;
    if (radi_solve_matrix_check(n, 1, "the symmetric form's working matrix", err) != RAD_OK)
        return err ? err->status : RAD_ERR_TOOBIG;
    const int lu_only = check_reciprocity(m, F, rep);
    if (lu_only < 0)
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory");
    while ((nb = radi_next_band_set(n, rho, done, bands)) > 0) {
        const double *rb = rho + (size_t)bands[0] * n;
        int not_pd = 0;
        rep->systems++;
        if (opt->progress && opt->progress(opt->progress_user, "solve", rep->systems - 1, RAD_BANDS))
            return radi_fail(err, RAD_ERR_INVALID, "interrupted");
        rad_status st = RAD_ERR_SINGULAR;
        if (!lu_only)
            st = solve_set(m, F, rb, E, B, bands, nb, opt, rep, &not_pd, err);
        if (lu_only || not_pd)
            st = radi_solve_lu(n, F, rb, E, B, bands, nb, opt, rep, err);
        if (st)
            return st;
    }
    if (opt->progress)
        opt->progress(opt->progress_user, "solve", RAD_BANDS, RAD_BANDS);
    return RAD_OK;
}
