/* export.c -- element table, Matrix Market, PLY solution, JSON report.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Formats (DESIGN.md section 6):
 *   - element table: tab-separated, one header line, one row per element;
 *   - form factors: Matrix Market (Boisvert, Pozo & Remington 1996),
 *     "array real general": the n*n entries in column-major order, row i =
 *     from element i;
 *   - solution: PLY (Turk 1994), ASCII, so numpy, MeshLab and Blender read
 *     it; vertex radiosity_r/g/b are the smoothed linear values, red/green/
 *     blue the same in 8-bit sRGB with the brightest element mapped to 1;
 *     face radiosity_r/g/b are the element values.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>

#include "radiosity/export.h"
#include "radiosity.h"

unsigned char rad_srgb8(double linear, double exposure)
{
    double x = linear * exposure;
    if (!(x > 0))
        return 0;
    if (x >= 1)
        return 255;
    /* IEC 61966-2-1: 12.92 x below 0.0031308, else 1.055 x^(1/2.4) - 0.055 */
    double s = x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1 / 2.4) - 0.055;
    return (unsigned char)floor(255 * s + 0.5);
}

int rad_export_elements(FILE *out, const rad_mesh *m, const double *B)
{
    const int n = m->nelements;
    fprintf(out, "element\tsurface\tgi\tgj\tcx\tcy\tcz\tnx\tny\tnz\tarea\tr\tg\tb\n");
    for (int e = 0; e < n; e++) {
        const rad_element *el = &m->elements[e];
        fprintf(out, "%d\t%d\t%d\t%d\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g", e,
                el->surface, el->gi, el->gj, el->centroid.x, el->centroid.y, el->centroid.z,
                el->normal.x, el->normal.y, el->normal.z, el->area);
        for (int b = 0; b < RAD_BANDS; b++)
            fprintf(out, "\t%.17g", B[(size_t)e + (size_t)b * n]);
        fputc('\n', out);
    }
    return ferror(out) ? -1 : 0;
}

int rad_export_matrix_market(FILE *out, const double *F, int n, const char *comment)
{
    fprintf(out, "%%%%MatrixMarket matrix array real general\n");
    if (comment)
        fprintf(out, "%% %s\n", comment);
    fprintf(out, "%d %d\n", n, n);
    for (size_t k = 0; k < (size_t)n * n; k++)
        fprintf(out, "%.17g\n", F[k]);
    return ferror(out) ? -1 : 0;
}

int rad_export_ply(FILE *out, const rad_scene *scene, const rad_mesh *m, const double *B,
                   const double *Bv)
{
    const int n = m->nelements, nv = m->nvertices;
    int maxv = 0;
    double bmax = 0;
    for (int e = 0; e < n; e++) {
        maxv = m->elements[e].nverts > maxv ? m->elements[e].nverts : maxv;
        for (int b = 0; b < RAD_BANDS; b++)
            bmax = fmax(bmax, B[(size_t)e + (size_t)b * n]);
    }
    const double exposure = bmax > 0 ? 1 / bmax : 1;
    fprintf(out, "ply\nformat ascii 1.0\ncomment radiosity %s solution\n", PACKAGE_VERSION);
    fprintf(out, "comment scene %s\n", scene->filename ? scene->filename : "-");
    if (scene->camera.defined) {
        const rad_camera *c = &scene->camera;
        fprintf(out, "comment camera eye %.17g %.17g %.17g at %.17g %.17g %.17g up %.17g %.17g %.17g fov %.17g\n",
                c->eye.x, c->eye.y, c->eye.z, c->at.x, c->at.y, c->at.z, c->up.x, c->up.y,
                c->up.z, c->fov);
    }
    fprintf(out, "element vertex %d\n"
                 "property double x\nproperty double y\nproperty double z\n"
                 "property double radiosity_r\nproperty double radiosity_g\n"
                 "property double radiosity_b\n"
                 "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                 "element face %d\nproperty list %s int vertex_indices\n"
                 "property int surface\n"
                 "property double radiosity_r\nproperty double radiosity_g\n"
                 "property double radiosity_b\nend_header\n",
            nv, n, maxv > 255 ? "int" : "uchar");
    for (int v = 0; v < nv; v++) {
        const rad_vec3 p = m->vertices[v];
        double r = Bv[v], g = Bv[(size_t)v + nv], b = Bv[(size_t)v + 2 * (size_t)nv];
        fprintf(out, "%.17g %.17g %.17g %.17g %.17g %.17g %u %u %u\n", p.x, p.y, p.z, r, g, b,
                rad_srgb8(r, exposure), rad_srgb8(g, exposure), rad_srgb8(b, exposure));
    }
    for (int e = 0; e < n; e++) {
        const rad_element *el = &m->elements[e];
        fprintf(out, "%d", el->nverts);
        for (int k = 0; k < el->nverts; k++)
            fprintf(out, " %d", m->vindex[el->first + k]);
        fprintf(out, " %d %.17g %.17g %.17g\n", el->surface, B[e], B[(size_t)e + n],
                B[(size_t)e + 2 * (size_t)n]);
    }
    return ferror(out) ? -1 : 0;
}

/* JSON numbers: %.17g, and null for what is not a finite number. */
static void jnum(FILE *out, const char *key, double v, int comma)
{
    if (isfinite(v))
        fprintf(out, "  \"%s\": %.17g%s\n", key, v, comma ? "," : "");
    else
        fprintf(out, "  \"%s\": null%s\n", key, comma ? "," : "");
}

static void jbands(FILE *out, const char *key, const double *v)
{
    fprintf(out, "  \"%s\": [", key);
    for (int b = 0; b < RAD_BANDS; b++) {
        if (isfinite(v[b]))
            fprintf(out, "%.17g", v[b]);
        else
            fprintf(out, "null");
        fprintf(out, b + 1 < RAD_BANDS ? ", " : "],\n");
    }
}

/* A JSON string with the needed escapes. */
static void jstr(FILE *out, const char *key, const char *s)
{
    fprintf(out, "  \"%s\": \"", key);
    for (; s && *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fprintf(out, "\\%c", c);
        else if (c < 0x20)
            fprintf(out, "\\u%04x", c);
        else
            fputc(c, out);
    }
    fprintf(out, "\",\n");
}

int rad_export_report(FILE *out, const rad_run_info *in)
{
    static const char *const solvers[] = {"gauss",       "jacobi",   "gauss-seidel",
                                          "progressive", "cholesky", "cg"};
    const rad_solve_report *s = in->solve;
    const rad_ff_stats *f = in->ff;
    fprintf(out, "{\n");
    jstr(out, "program", "radiosity " PACKAGE_VERSION);
    jstr(out, "scene", in->scene);
    jstr(out, "status", in->status);
    fprintf(out, "  \"elements\": %d,\n", in->nelements);
    jstr(out, "accuracy", in->accuracy);
    fprintf(out, "  \"quadrature\": %d,\n", in->quadrature);
    jnum(out, "memory_bytes", in->memory_bytes, 1);
    jnum(out, "memory_available_bytes", in->memory_available, 1);
    fprintf(out, "  \"seconds\": {\"parse\": %.6g, \"mesh\": %.6g, \"form_factors\": %.6g, "
                 "\"solve\": %.6g, \"smooth\": %.6g, \"output\": %.6g},\n",
            in->t_parse, in->t_mesh, in->t_formfactor, in->t_solve, in->t_smooth, in->t_output);
    jnum(out, "form_factor_pairs_per_second", in->ff_pairs_per_second, 1);
    if (f) {
        jnum(out, "form_factor_min", f->min_value, 1);
        jnum(out, "form_factor_max", f->max_value, 1);
        fprintf(out, "  \"form_factors_negative\": %ld,\n  \"form_factors_above_one\": %ld,\n",
                f->negative, f->above_one);
        jnum(out, "form_factor_max_error_estimate", f->max_errest, 1);
        jnum(out, "form_factor_max_relative_error_estimate", f->max_relerr, 1);
        jnum(out, "form_factor_max_row_error_estimate", f->max_row_error, 1);
        fprintf(out,
                "  \"visibility\": {\"needed\": %s, \"pairs_tested\": %.0f, "
                "\"pairs_blockable\": %.0f, \"pairs_blocked\": %.0f, \"pairs_partial\": %.0f, "
                "\"seconds\": %.6g},\n",
                f->vis_needed ? "true" : "false", f->vis_pairs_tested, f->vis_pairs_blockable,
                f->vis_pairs_blocked, f->vis_pairs_partial, f->vis_seconds);
    }
    if (s) {
        jstr(out, "solver", solvers[s->solver]);
        fprintf(out, "  \"bounces\": %d,\n  \"systems_factorised\": %d,\n  \"sweeps\": %d,\n",
                s->bounces, s->systems, s->sweeps);
        jnum(out, "residual", s->residual, 1);
        jnum(out, "rcond", s->rcond, 1);
        jnum(out, "b_error_bound_from_form_factors", s->ff_error_bound, 1);
        jnum(out, "forward_error_bound", s->ferr, 1);
        jnum(out, "backward_error_bound", s->berr, 1);
        jnum(out, "convergence_factor", s->spectral_radius, 1);
        jnum(out, "row_sum_min", s->row_sum_min, 1);
        jnum(out, "row_sum_max", s->row_sum_max, 1);
        jbands(out, "emitted_power", s->emitted);
        jbands(out, "absorbed_power", s->absorbed);
        jbands(out, "escaped_power", s->escaped);
        jbands(out, "energy_balance_relative", s->balance);
    }
    fprintf(out, "  \"format\": 1\n}\n");
    return ferror(out) ? -1 : 0;
}
