/* ffcontour_tmpl.h -- the contour's closed forms and adaptive quadrature,
 * written once and compiled twice by ffcontour.c: in double and in long
 * double (64-bit significand on x86), for pairs whose terms cancel beyond
 * what double can carry.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Before including, ffcontour.c defines
 *   R          the floating type,
 *   SUF(name)  name with the type's suffix,
 *   R_LOG, R_LOG1P, R_ATAN2, R_SQRT, R_FABS   its libm functions,
 *   R_EPS      its machine epsilon,
 * and optionally PAR_FLUSH(u, d, dot, m, &s, &mag), which adds the closed
 * forms of m parallel edge pairs (four H arguments each, distance, factor
 * e_p . e_q) to s and their terms' sizes to mag, for the pairs PAR_OK(u, d)
 * accepts; the others go one by one.
 * The formulas and their sources are in ffcontour.c.
 */

typedef struct SUF(vec) {
    R x, y, z;
} SUF(vec);

static inline SUF(vec) SUF(vec_of)(rad_vec3 a)
{
    SUF(vec) r = {a.x, a.y, a.z};
    return r;
}
static inline SUF(vec) SUF(vsub)(SUF(vec) a, SUF(vec) b)
{
    SUF(vec) r = {a.x - b.x, a.y - b.y, a.z - b.z};
    return r;
}
static inline SUF(vec) SUF(vaxpy)(SUF(vec) a, R t, SUF(vec) e) /* a + t e */
{
    SUF(vec) r = {a.x + t * e.x, a.y + t * e.y, a.z + t * e.z};
    return r;
}
static inline SUF(vec) SUF(vscale)(SUF(vec) a, R t)
{
    SUF(vec) r = {a.x * t, a.y * t, a.z * t};
    return r;
}
static inline R SUF(vdot)(SUF(vec) a, SUF(vec) b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/* An edge in the working type. */
typedef struct SUF(edge) {
    SUF(vec) p0, d, e;
    R len;
} SUF(edge);

/* The edge from x's start to the next edge's start (its end), so that the
 * contour closes in this type.  With EXACT_EDGES (long double) both come
 * from the vertices as given less `origin`: differences of doubles that
 * the 64-bit significand holds exactly (up to 11 bits of exponent apart),
 * so neither the rounding of the vertices relative to the centroid nor a
 * gap between edges (an ulp of the coordinates, times the log integral
 * over the other contour) enters S; in double they are x->p0 and x->d. */
static SUF(edge) SUF(edge_of)(const rad_ff_edge *x, const rad_ff_edge *next, SUF(vec) origin)
{
    SUF(edge) r;
#ifdef EXACT_EDGES
    r.p0 = SUF(vsub)(SUF(vec_of)(x->v0), origin);
    r.d = SUF(vsub)(SUF(vec_of)(next->v0), SUF(vec_of)(x->v0));
#else
    (void)next;
    (void)origin;
    r.p0 = SUF(vec_of)(x->p0);
    r.d = SUF(vec_of)(x->d);
#endif
    /* the unit direction again in this type, from d */
    r.len = R_SQRT(SUF(vdot)(r.d, r.d));
    r.e = SUF(vscale)(r.d, 1 / r.len);
    return r;
}

/* H~(u) of ffcontour.c (parallel segments d apart). */
static R SUF(h_parallel)(R u, R d)
{
    if (d == 0)
        return u == 0 ? 0 : u * u * (R_LOG(R_FABS(u)) / 2 - (R)0.75);
    R u2 = u * u, d2 = d * d;
    return u2 / 4 * R_LOG(u2 + d2) - d2 / 4 * R_LOG1P(u2 / d2) - (R)0.75 * u2 +
           d * u * R_ATAN2(u, d);
}

/* G(v) of ffcontour.c (a point h from a line). */
static R SUF(g_point)(R v, R h)
{
    if (h == 0)
        return v == 0 ? 0 : v * (R_LOG(R_FABS(v)) - 1);
    return v / 2 * R_LOG(v * v + h * h) - v + h * R_ATAN2(v, h);
}

/* integral_0^L ln |X - (Q0 + t e)| dt, e a unit vector; *mag gets the
 * size of the two terms it subtracts. */
static R SUF(ln_point_segment)(SUF(vec) x, const SUF(edge) *q, R *mag)
{
    SUF(vec) w = SUF(vsub)(x, q->p0);
    R t0 = SUF(vdot)(w, q->e);
    SUF(vec) perp = SUF(vaxpy)(w, -t0, q->e);
    R h = R_SQRT(SUF(vdot)(perp, perp));
    R g1 = SUF(g_point)(q->len - t0, h), g0 = SUF(g_point)(-t0, h);
    *mag = R_FABS(g1) + R_FABS(g0);
    return g1 - g0;
}

/* Parallel edges: the closed form in p's coordinate.  _setup gives the
 * four arguments of H (signs +, +, -, -), the distance of the lines, and
 * in a[] the distances of q's two ends from p's line. */
static void SUF(parallel_setup)(const SUF(edge) *p, const SUF(edge) *q, R u[4], R *dist, R a[2])
{
    SUF(vec) w0 = SUF(vsub)(q->p0, p->p0);
    SUF(vec) w1 = SUF(vaxpy)(w0, 1, q->d);
    R b1 = SUF(vdot)(w0, p->e), b2 = SUF(vdot)(w1, p->e);
    /* distance between the lines, from both ends of q (mean of two) */
    SUF(vec) x0 = SUF(vaxpy)(w0, -b1, p->e), x1 = SUF(vaxpy)(w1, -b2, p->e);
    a[0] = R_SQRT(SUF(vdot)(x0, x0));
    a[1] = R_SQRT(SUF(vdot)(x1, x1));
    *dist = (a[0] + a[1]) / 2;
    if (b1 > b2) {
        R t = b1;
        b1 = b2;
        b2 = t;
    }
    u[0] = p->len - b1;
    u[1] = -b2;
    u[2] = -b1;
    u[3] = p->len - b2;
}

/* What taking nearly parallel edges as parallel at their mean distance
 * can miss, times |e_p . e_q| (bound (P) of ffcontour.c); a[] as
 * parallel_setup gives it. */
static double SUF(parallel_bound)(const SUF(edge) *p, const SUF(edge) *q, const R a[2],
                                  double dot)
{
    const SUF(vec) v = SUF(vaxpy)(q->d, -SUF(vdot)(q->d, p->e), p->e); /* across p's line */
    const double a0 = (double)a[0], a1 = (double)a[1];
    const double D = (double)R_SQRT(SUF(vdot)(v, v)), amin = fmin(a0, a1);
    if (D == 0)
        return 0;
    const double below = amin > 0 ? fmin(D / 2, D * D / (4 * amin)) : D / 2;
    const double spread = fmin(fabs(a1 - a0), D) / 4 + below;
    const double cmin = amin - D / 2;
    const double K = cmin > 0 ? fmin(RAD_PI, (double)p->len / cmin) : RAD_PI;
    return fabs(dot) * spread * (double)q->len * K;
}

/* ... and its value from them; *mag gets the size of the terms added. */
static R SUF(ln_parallel_u)(const R u[4], R d, R *mag)
{
    R h1 = SUF(h_parallel)(u[0], d), h2 = SUF(h_parallel)(u[1], d);
    R h3 = SUF(h_parallel)(u[2], d), h4 = SUF(h_parallel)(u[3], d);
    *mag = R_FABS(h1) + R_FABS(h2) + R_FABS(h3) + R_FABS(h4);
    return h1 + h2 - h3 - h4;
}


/* Gauss-Kronrod 7-15 on [a, b] of p's parameter: the integral; *err the
 * Kronrod-Gauss difference, *floor 64 eps times the size of the terms. */
static R SUF(gk15)(const SUF(edge) *p, const SUF(edge) *q, R a, R b, R *err, R *floor)
{
    R c = (a + b) / 2, h = (b - a) / 2, m, mk;
    R fc = SUF(ln_point_segment)(SUF(vaxpy)(p->p0, c, p->e), q, &m);
    R rk = (R)gk_wk[7] * fc, rg = (R)gk_wg[3] * fc;
    mk = (R)gk_wk[7] * m;
    for (int k = 0; k < 7; k++) {
        R dx = h * (R)gk_x[k], m1, m2;
        R f1 = SUF(ln_point_segment)(SUF(vaxpy)(p->p0, c - dx, p->e), q, &m1);
        R f2 = SUF(ln_point_segment)(SUF(vaxpy)(p->p0, c + dx, p->e), q, &m2);
        rk += (R)gk_wk[k] * (f1 + f2);
        mk += (R)gk_wk[k] * (m1 + m2);
        if (k % 2 == 1)
            rg += (R)gk_wg[k / 2] * (f1 + f2);
    }
    *err = R_FABS((rk - rg) * h);
    *floor = 64 * R_EPS * mk * R_FABS(h);
    return rk * h;
}

typedef struct SUF(panel) {
    R a, b, r, e, floor;
} SUF(panel);

/* The points where the integrand over p comes near a singularity
 * (ffcontour.c, "near-singular points"): its real part s and its distance
 * dl from the real axis, for the lines' nearest approach when q's foot
 * lies on q, and for q's two ends.  Returns their count (at most 3). */
static int SUF(near_points)(const SUF(edge) *p, const SUF(edge) *q, R *s, R *dl)
{
    const SUF(vec) w0 = SUF(vsub)(p->p0, q->p0);
    const R ef = SUF(vdot)(p->e, q->e), c = 1 - ef * ef;
    int n = 0;
    if (c > 0) {
        const R sc = (ef * SUF(vdot)(w0, q->e) - SUF(vdot)(w0, p->e)) / c;
        const SUF(vec) x = SUF(vaxpy)(w0, sc, p->e);
        const R tc = SUF(vdot)(x, q->e);
        if (tc >= 0 && tc <= q->len) {
            const SUF(vec) perp = SUF(vaxpy)(x, -tc, q->e);
            s[n] = sc;
            dl[n++] = R_SQRT(SUF(vdot)(perp, perp) / c);
        }
    }
    for (int k = 0; k < 2; k++) {
        const SUF(vec) x = SUF(vaxpy)(SUF(vscale)(w0, -1), k ? q->len : 0, q->e);
        const R se = SUF(vdot)(x, p->e);
        const SUF(vec) perp = SUF(vaxpy)(x, -se, p->e);
        s[n] = se;
        dl[n++] = R_SQRT(SUF(vdot)(perp, perp));
    }
    return n;
}

/* The panel ends to start from (sorted, 0 and p's length included; room
 * for ADAPT_MAX_BREAKS), and in *unseen what they leave unresolved.  Each
 * near-singular point closer to [0, L] than L/4, at distance d from it
 * and nearest to s0 there, gets a break at s0: the integrand's kink or
 * x ln x there then lies on a panel end, not inside a panel where the
 * Gauss and Kronrod rules err alike and their difference does not show
 * it.  What the rules still miss is the rounding of the kink over the
 * width d, at most UNSEEN(d) = 4 d^2 (ln(L/d) + 2) (the integral of
 * sqrt(d^2 + x^2) - |x| and of the atan step, times pi, with room); that
 * is added to *unseen when below 1/16 of tol, and resolved otherwise by
 * breaks graded from s0 at d, 2d, 4d, ... up to L/4, on which the
 * singularity is at least a panel's width away. */
static int SUF(breaks)(const SUF(edge) *p, const SUF(edge) *q, R tol, R *brk, R *unseen)
{
    const R L = p->len;
    R s[3], dl[3];
    const int m = SUF(near_points)(p, q, s, dl);
    int n = 0;
    brk[n++] = 0;
    brk[n++] = L;
    for (int i = 0; i < m; i++) {
        const R s0 = s[i] < 0 ? 0 : s[i] > L ? L : s[i];
        const R d = R_SQRT(dl[i] * dl[i] + (s[i] - s0) * (s[i] - s0));
        if (!(d < L / 4))
            continue;
        if (s0 > 0 && s0 < L)
            brk[n++] = s0;
        const R u = d > 0 ? 4 * d * d * (R_LOG(L / d) + 2) : 0;
        if (u <= tol / 16) {
            *unseen += u;
            continue;
        }
        for (R g = d; g < L / 4 && n + 2 <= ADAPT_MAX_BREAKS; g *= 2) {
            if (s0 - g > 0)
                brk[n++] = s0 - g;
            if (s0 + g < L)
                brk[n++] = s0 + g;
        }
    }
    for (int i = 1; i < n; i++) /* insertion sort: a few dozen at most */
        for (int j = i; j > 0 && brk[j - 1] > brk[j]; j--) {
            const R t = brk[j];
            brk[j] = brk[j - 1];
            brk[j - 1] = t;
        }
    return n;
}

/* Globally adaptive integral over p (QAG's strategy), from the panels
 * between the breaks above: returns it, adds its error estimate to
 * *err. */
static R SUF(adaptive)(const SUF(edge) *p, const SUF(edge) *q, R tol, R *err)
{
    SUF(panel) pan[ADAPT_MAX_PANELS];
    R brk[ADAPT_MAX_BREAKS], unseen = 0;
    const int nb = SUF(breaks)(p, q, tol, brk, &unseen);
    int n = 0;
    for (int i = 0; i + 1 < nb; i++) {
        if (!(brk[i + 1] > brk[i]))
            continue; /* a break twice */
        pan[n].a = brk[i];
        pan[n].b = brk[i + 1];
        pan[n].r = SUF(gk15)(p, q, brk[i], brk[i + 1], &pan[n].e, &pan[n].floor);
        n++;
    }
    for (;;) {
        R esum = 0;
        int worst = -1;
        for (int i = 0; i < n; i++) {
            esum += pan[i].e;
            if (pan[i].e > pan[i].floor && pan[i].b - pan[i].a > 1e-15 * p->len &&
                (worst < 0 || pan[i].e - pan[i].floor > pan[worst].e - pan[worst].floor))
                worst = i;
        }
        if (esum <= tol || worst < 0 || n == ADAPT_MAX_PANELS)
            break;
        const R a = pan[worst].a, b = pan[worst].b, m = (a + b) / 2;
        pan[worst].b = m;
        pan[worst].r = SUF(gk15)(p, q, a, m, &pan[worst].e, &pan[worst].floor);
        pan[n].a = m;
        pan[n].b = b;
        pan[n].r = SUF(gk15)(p, q, m, b, &pan[n].e, &pan[n].floor);
        n++;
    }
    R r = 0, e = unseen;
    for (int i = 0; i < n; i++) {
        r += pan[i].r;
        e += pan[i].e > pan[i].floor ? pan[i].e : pan[i].floor;
    }
    *err += e;
    return r;
}

/* The contour sum S over all edge pairs: closed forms for parallel pairs,
 * adaptive quadrature for skew ones with absolute tolerance tol on S shared
 * among them; every I_pq integrates ln(r/s), s^2 = scale2.  *errest gets
 * the quadrature estimates plus 16 eps times the size of the terms, and
 * a bound on the pairs left out as perpendicular. */
static double SUF(contour)(const rad_ff_edge *ea, int na, const rad_ff_edge *eb, int nb,
                           double scale2, double tol, rad_vec3 origin_d, double *errest)
{
    const SUF(vec) origin = SUF(vec_of)(origin_d);
    const R ln_s = R_LOG((R)scale2) / 2;
    R s = 0, err = 0, mag = 0;
    double skip = 0; /* sum of |e_p . e_q| min(lp, lq) over the pairs left out */
    double bent = 0; /* bound (P) summed over the pairs taken as parallel */
#ifdef PAR_FLUSH
    double bu[4 * PAR_BATCH], bd[PAR_BATCH], bdot[PAR_BATCH];
    int nbatch = 0;
#endif
    int pairs = 0; /* contributing edge pairs share the adaptive tolerance */
    for (int p = 0; p < na; p++)
        for (int q = 0; q < nb; q++)
            pairs += fabs(v3_dot(ea[p].e, eb[q].e)) >= 1e-14;
    for (int p = 0; p < na; p++) {
        const SUF(edge) ep = SUF(edge_of)(&ea[p], &ea[(p + 1) % na], origin);
        for (int q = 0; q < nb; q++) {
            const double dot_d = v3_dot(ea[p].e, eb[q].e);
            if (fabs(dot_d) < 1e-14) { /* perpendicular: no contribution */
                skip += fabs(dot_d) * fmin(ea[p].len, eb[q].len); /* but round-off */
                continue;
            }
            const rad_vec3 cr = v3_cross(ea[p].e, eb[q].e);
            const SUF(edge) eq = SUF(edge_of)(&eb[q], &eb[(q + 1) % nb], origin);
            const R dot = SUF(vdot)(ep.e, eq.e), lplq = ep.len * eq.len;
            R I, m;
            /* nearly parallel: the closed form's error bound (ffcontour.c) */
            const double cr2 = v3_dot(cr, cr);
            const int near = cr2 < 1e-26;
            R u[4] = {0, 0, 0, 0}, d = 0, a[2];
            double bend = HUGE_VAL;
            if (near) {
                SUF(parallel_setup)(&ep, &eq, u, &d, a);
                bend = SUF(parallel_bound)(&ep, &eq, a, dot_d);
            }
            if (near && (cr2 == 0 || bend <= tol / (4 * pairs))) {
                bent += bend;
#ifdef PAR_FLUSH
                if (PAR_OK(u, d)) { /* batched: PAR_FLUSH adds dot (H sum) */
                    for (int k = 0; k < 4; k++)
                        bu[4 * nbatch + k] = u[k];
                    bd[nbatch] = d;
                    bdot[nbatch++] = dot;
                    if (nbatch == PAR_BATCH) {
                        PAR_FLUSH(bu, bd, bdot, nbatch, &s, &mag);
                        nbatch = 0;
                    }
                    s -= dot * lplq * ln_s;
                    mag += R_FABS(dot * lplq * ln_s);
                    continue;
                }
#endif
                I = SUF(ln_parallel_u)(u, d, &m) - lplq * ln_s;
                m += lplq * R_FABS(ln_s); /* as the batched path counts it */
            } else {
                R e = 0;
                I = SUF(adaptive)(&ep, &eq, (R)tol / (pairs * R_FABS(dot)), &e);
                err += R_FABS(dot) * e;
                m = 8 * R_FABS(I) + lplq * R_FABS(ln_s);
                I -= lplq * ln_s;
            }
            mag += R_FABS(dot) * m;
            s += dot * I;
        }
    }
#ifdef PAR_FLUSH
    if (nbatch > 0)
        PAR_FLUSH(bu, bd, bdot, nbatch, &s, &mag);
#endif
    /* the pairs left out as perpendicular, |I_pq| <= 2 s min(lp, lq) each,
     * and those taken as parallel, (P) each (ffcontour.c) */
    *errest = (double)(err + 16 * R_EPS * mag) + 2 * sqrt(scale2) * skip + bent;
    return (double)s;
}
