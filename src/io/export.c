/* export.c -- element table, Matrix Market, PLY solution, JSON report.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Formats (radiosity-files(5)):
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

#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#else
#define omp_get_max_threads() 1
#define omp_get_thread_num() 0
#define omp_get_num_threads() 1
#endif

#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/mesh.h"
#include "radiosity/formfactor.h"
#include "radiosity/solve.h"
#include "radiosity/render.h"
#include "radiosity/export.h"
#include "radiosity/export.h"
#include "util/util.h"

rad_status rad_export_elements(FILE *out, const rad_mesh *m, const double *B)
{
    return rad_export_elements_level(out, m, B, NULL);
}

rad_status rad_export_elements_level(FILE *out, const rad_mesh *m, const double *B,
                                     const int *level)
{
    const int n = m->nelements;
    fprintf(out, "element\tsurface\tgi\tgj\tcx\tcy\tcz\tnx\tny\tnz\tarea\tr\tg\tb%s\n",
            level ? "\tlevel" : "");
    for (int e = 0; e < n; e++) {
        const rad_element *el = &m->elements[e];
        fprintf(out, "%d\t%d\t%d\t%d\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g", e,
                el->surface, el->gi, el->gj, el->centroid.x, el->centroid.y, el->centroid.z,
                el->normal.x, el->normal.y, el->normal.z, el->area);
        for (int b = 0; b < RAD_BANDS; b++)
            fprintf(out, "\t%.17g", B[(size_t)e + (size_t)b * n]);
        if (level)
            fprintf(out, "\t%d", level[e]);
        fputc('\n', out);
    }
    return ferror(out) ? RAD_ERR_IO : RAD_OK;
}

/* ---- big tables: formatted in parallel, written in order ------------------
 *
 * The form-factor table of an n-element mesh has n (n - 1) lines (5.76
 * million for the 20 x 20 cube).  Its items (a row of the table, a column
 * of the matrix) are formatted by radi_fmt_g (fmtdouble.h: the bytes of
 * %.17g without printf's multiple-precision arithmetic), a block of items
 * at a time into the buffer of one of T threads: thread t takes blocks t,
 * t + T, t + 2T, ...  A thread writes its block when the blocks before it
 * are written, and the others format theirs meanwhile; the file is the
 * one the serial loop of printf calls wrote, byte for byte.
 *
 * The turn passes under a mutex and a condition variable, so a thread
 * that waits sleeps: OpenMP's `ordered` spins instead, and on a machine
 * busy with other work a spinning thread burnt more CPU than the
 * formatting (the 20 x 20 cube's table cost 1.06 s of CPU with two
 * threads against 0.28 s with one).  A block is at least 8 items: the
 * rows of the form-factor table read the column-major matrix across, and
 * 8 consecutive rows share each cache line they read. */

/* Format item `item` into buf (at least item_max bytes); return the bytes. */
typedef size_t (*item_fmt)(char *buf, const void *ctx, size_t item);

enum { BLOCK_BYTES = 1 << 20, BLOCK_MIN_ITEMS = 8 };

/* Whose turn it is to write: block `next`. */
typedef struct turn {
    pthread_mutex_t lock;
    pthread_cond_t cond;
    size_t next;
} turn;

static void wait_turn(turn *t, size_t b)
{
    pthread_mutex_lock(&t->lock);
    while (t->next != b)
        pthread_cond_wait(&t->cond, &t->lock);
    pthread_mutex_unlock(&t->lock);
}

static void pass_turn(turn *t)
{
    pthread_mutex_lock(&t->lock);
    t->next++;
    pthread_cond_broadcast(&t->cond);
    pthread_mutex_unlock(&t->lock);
}

/* A writer's status from write_items' 0, -1 (a write error) or -2 (out of
 * memory). */
static rad_status as_status(int r)
{
    return r == 0 ? RAD_OK : r == -2 ? RAD_ERR_NOMEM : RAD_ERR_IO;
}

static int write_items(FILE *out, size_t nitems, size_t item_max, item_fmt fmt,
                       const void *ctx)
{
    int threads = omp_get_max_threads();
    size_t per_block = item_max < BLOCK_BYTES / BLOCK_MIN_ITEMS ? BLOCK_BYTES / item_max
                                                                  : BLOCK_MIN_ITEMS;
    char *buf = malloc((size_t)threads * per_block * item_max);
    if (!buf) {                         /* the least: one item at a time */
        threads = 1;
        per_block = 1;
        buf = malloc(item_max);
        if (!buf) {
            errno = ENOMEM;
            return -2;
        }
    }
    const size_t nblocks = (nitems + per_block - 1) / per_block;
    turn tn = {PTHREAD_MUTEX_INITIALIZER, PTHREAD_COND_INITIALIZER, 0};
    int status = 0;                     /* written only by the thread whose turn it is */
#pragma omp parallel num_threads(threads)
    {
        const size_t t = (size_t)omp_get_thread_num(), T = (size_t)omp_get_num_threads();
        char *mine = buf + t * per_block * item_max;
        for (size_t b = t; b < nblocks; b += T) {
            size_t used = 0;
            for (size_t item = b * per_block; item < (b + 1) * per_block && item < nitems; item++)
                used += fmt(mine + used, ctx, item);
            wait_turn(&tn, b);
            if (status == 0 && fwrite(mine, 1, used, out) != used)
                status = -1;
            pass_turn(&tn);
        }
    }
    pthread_cond_destroy(&tn.cond);
    pthread_mutex_destroy(&tn.lock);
    free(buf);
    return status || ferror(out) ? -1 : 0;
}

/* "%.17g" of v followed by c. */
static size_t put_g17(char *p, double v, char c)
{
    size_t k = (size_t)radi_fmt_g(p, v, 17);
    p[k] = c;
    return k + 1;
}

typedef struct ff_table {
    const double *F, *E;
    size_t n;
    const char *index;          /* "j\t" of every j, INDEX_W bytes each */
    int diagonal;               /* 1: the pairs i = i too */
} ff_table;

/* The longest index (10 digits) and its tab, rounded up for fixed copies. */
enum { INDEX_W = 16 };

/* Row i of the table: "i\tj\tF\terror\n" for every j != i (every j with
 * t->diagonal: at most n lines either way).  A line has at most 10 + 10 +
 * 24 + 24 bytes and four separators, and radi_fmt_g may use
 * RAD_FMT_G_MAX bytes where it writes: 96 a line is room enough.  The
 * indices' text is made once (the last byte of each slot holds its
 * length), every row copies it. */
enum { FF_LINE_MAX = 96 };

static size_t ff_table_row(char *buf, const void *ctx, size_t i)
{
    const ff_table *t = ctx;
    char *p = buf;
    const char *is = t->index + i * INDEX_W;
    const size_t il = (size_t)is[INDEX_W - 1];
    for (size_t j = 0; j < t->n; j++) {
        if (j == i && !t->diagonal)
            continue;
        const size_t k = i + j * t->n;
        const char *js = t->index + j * INDEX_W;
        memcpy(p, is, INDEX_W);
        p += il;
        memcpy(p, js, INDEX_W);
        p += (size_t)js[INDEX_W - 1];
        p += put_g17(p, t->F[k], '\t');
        p += radi_fmt_g(p, t->E ? t->E[k] : (double)NAN, 3);
        *p++ = '\n';
    }
    return (size_t)(p - buf);
}

static rad_status ff_table_write(FILE *out, const double *F, const double *E, int n,
                                 int diagonal)
{
    if (fputs("i\tj\tF\terror\n", out) == EOF)
        return RAD_ERR_IO;
    const size_t m = (size_t)(n > 0 ? n : 0);
    char *index = malloc(m * INDEX_W + 1);
    if (!index) {
        errno = ENOMEM;
        return RAD_ERR_NOMEM;
    }
    for (size_t j = 0; j < m; j++) {
        char *s = index + j * INDEX_W;
        const int len = radi_fmt_uint(s, (unsigned)j);
        s[len] = '\t';
        s[INDEX_W - 1] = (char)(len + 1);
    }
    const ff_table t = {F, E, m, index, diagonal};
    const int status = write_items(out, m, m * FF_LINE_MAX + INDEX_W, ff_table_row, &t);
    free(index);
    return as_status(status);
}

rad_status rad_export_ff_table(FILE *out, const double *F, const double *E, int n)
{
    return ff_table_write(out, F, E, n, 0);
}

rad_status rad_export_ff_table_diagonal(FILE *out, const double *F, const double *E, int n)
{
    return ff_table_write(out, F, E, n, 1);
}

typedef struct mm_column {
    const double *F;
    size_t n;
} mm_column;

/* Column j of the matrix, one entry a line. */
static size_t mm_column_lines(char *buf, const void *ctx, size_t j)
{
    const mm_column *c = ctx;
    const double *col = c->F + j * c->n;
    char *p = buf;
    for (size_t i = 0; i < c->n; i++)
        p += put_g17(p, col[i], '\n');
    return (size_t)(p - buf);
}

rad_status rad_export_matrix_market(FILE *out, const double *F, int n, const char *comment)
{
    fprintf(out, "%%%%MatrixMarket matrix array real general\n");
    if (comment)
        fprintf(out, "%% %s\n", comment);
    fprintf(out, "%d %d\n", n, n);
    if (ferror(out))
        return RAD_ERR_IO;
    const mm_column c = {F, (size_t)(n > 0 ? n : 0)};
    return as_status(write_items(out, c.n, c.n * RAD_FMT_G_MAX + 1, mm_column_lines, &c));
}

rad_status rad_export_surface_table(FILE *out, const rad_scene *scene, const rad_mesh *m,
                                    const double *FS, const double *ES, const double *AS)
{
    const int ns = m->nsurfaces;
    fprintf(out, "S\tK\tF\terror\tS_line\tK_line\tS_area\n");
    for (int S = 0; S < ns; S++)
        for (int K = 0; K < ns; K++) {
            const size_t k = (size_t)S + (size_t)K * (size_t)ns;
            fprintf(out, "%d\t%d\t%.17g\t%.3g\t%d\t%d\t%.17g\n", S, K, FS[k],
                    ES ? ES[k] : (double)NAN, scene->surfaces[S].line, scene->surfaces[K].line,
                    AS[S]);
        }
    return ferror(out) ? RAD_ERR_IO : RAD_OK;
}

rad_status rad_export_ply(FILE *out, const rad_scene *scene, const rad_mesh *m, const double *B,
                          const double *Bv)
{
    const int n = m->nelements, nv = m->nvertices;
    int maxv = 0;
    for (int e = 0; e < n; e++)
        maxv = m->elements[e].nverts > maxv ? m->elements[e].nverts : maxv;
    /* the preview colours: the brightest reflector white (exposure.c) */
    const double exposure = rad_mesh_auto_exposure(m, B, RAD_EXPOSURE_REFLECTORS);
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
                 "property double radiosity_b\nproperty uchar emitting\n"
                 "property int element\nend_header\n",
            nv, n, maxv > 255 ? "int" : "uchar");
    for (int v = 0; v < nv; v++) {
        const rad_vec3 p = m->vertices[v];
        double r = Bv[v], g = Bv[(size_t)v + nv], b = Bv[(size_t)v + 2 * (size_t)nv];
        fprintf(out, "%.17g %.17g %.17g %.17g %.17g %.17g %u %u %u\n", p.x, p.y, p.z, r, g, b,
                rad_tone_byte(r, exposure), rad_tone_byte(g, exposure), rad_tone_byte(b, exposure));
    }
    /* faces grouped by vertex count, each group in element order: readers
     * that keep one array per cell type (meshio) need each type's faces
     * together; `element` keeps the element's index */
    int *start = calloc((size_t)maxv + 2, sizeof *start);
    int *order = malloc(sizeof *order * (size_t)(n ? n : 1));
    if (!start || !order) {
        free(start);
        free(order);
        return RAD_ERR_NOMEM;
    }
    for (int e = 0; e < n; e++) /* a counting sort, stable */
        start[m->elements[e].nverts + 1]++;
    for (int c = 0; c <= maxv; c++)
        start[c + 1] += start[c];
    for (int e = 0; e < n; e++)
        order[start[m->elements[e].nverts]++] = e;
    for (int i = 0; i < n; i++) {
        const int e = order[i];
        const rad_element *el = &m->elements[e];
        fprintf(out, "%d", el->nverts);
        for (int k = 0; k < el->nverts; k++)
            fprintf(out, " %d", m->vindex[el->first + k]);
        fprintf(out, " %d %.17g %.17g %.17g %d %d\n", el->surface, B[e], B[(size_t)e + n],
                B[(size_t)e + 2 * (size_t)n],
                el->emit[0] > 0 || el->emit[1] > 0 || el->emit[2] > 0, e);
    }
    free(start);
    free(order);
    return ferror(out) ? RAD_ERR_IO : RAD_OK;
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

/* A JSON string with the needed escapes (no name: ""). */
static void jstr(FILE *out, const char *key, const char *s)
{
    fprintf(out, "  \"%s\": ", key);
    radi_json_string(out, s ? s : "");
    fputs(",\n", out);
}

/* What reading the scene repaired: the counts of rad_scene_repairs and
 * the lines the program printed for them (rad_scene_repair_text). */
static void jrepairs(FILE *out, const rad_scene *scene)
{
    const rad_scene_repairs *p = &scene->repairs;
    fprintf(out, "  \"repairs\": {\"undefined_materials\": %d, \"spaced_names\": %d, "
                 "\"degenerate_faces\": %d, \"split_faces\": %d, \"split_triangles\": %d, "
                 "\"said\": [",
            p->undefined_materials, p->spaced_names, p->degenerate_faces, p->split_faces,
            p->split_triangles);
    char line[RAD_ERRMSG_MAX];
    int n = 0;
    for (int k = 0; k < RAD_SCENE_REPAIR_KINDS; k++)
        if (rad_scene_repair_text(scene, k, line, sizeof line)) {
            fputs(n++ ? ", " : "", out);
            radi_json_string(out, line);
        }
    fputs("]},\n", out);
}

rad_status rad_export_report(FILE *out, const rad_run_info *in)
{
    const rad_solve_report *s = in->solve;
    const rad_ff_stats *f = in->ff;
    fprintf(out, "{\n");
    jstr(out, "program", "radiosity " PACKAGE_VERSION);
    jstr(out, "scene", in->scene);
    jstr(out, "status", in->status);
    fprintf(out, "  \"elements\": %d,\n", in->nelements);
    if (in->accuracy) /* NULL: not the contour's (the hemicube's) */
        jstr(out, "accuracy", in->accuracy);
    else
        fprintf(out, "  \"accuracy\": null,\n");
    jnum(out, "quadrature", in->quadrature > 0 ? in->quadrature : NAN, 1);
    jnum(out, "memory_bytes", in->memory_bytes, 1);
    jnum(out, "memory_available_bytes", in->memory_available, 1);
    fprintf(out, "  \"seconds\": {\"parse\": %.6g, \"mesh\": %.6g, \"form_factors\": %.6g, "
                 "\"solve\": %.6g, \"smooth\": %.6g, \"output\": %.6g},\n",
            in->t_parse, in->t_mesh, in->t_formfactor, in->t_solve, in->t_smooth, in->t_output);
    jnum(out, "form_factor_pairs_per_second", in->ff_pairs_per_second, 1);
    if (in->matrix) /* "none": the form factors were computed shot by shot */
        jstr(out, "matrix", in->matrix);
    if (in->method) /* the hemicube's rows have no error estimates */
        jstr(out, "form_factors_method", in->method);
    if (in->method && strcmp(in->method, "hemicube") == 0)
        fprintf(out, "  \"hemicube_resolution\": %d,\n", in->resolution);
    if (in->repaired)
        jrepairs(out, in->repaired);
    if (f) {
        jnum(out, "form_factor_min", f->min_value, 1);
        jnum(out, "form_factor_max", f->max_value, 1);
        fprintf(out, "  \"form_factors_negative\": %ld,\n  \"form_factors_above_one\": %ld,\n",
                f->negative, f->above_one);
        jnum(out, "form_factor_max_error_estimate", f->max_errest, 1);
        jnum(out, "form_factor_max_relative_error_estimate", f->max_relerr, 1);
        jnum(out, "form_factor_max_row_error_estimate", f->max_row_error, 1);
        jnum(out, "form_factors_promise", f->promise, 1);
        fprintf(out, "  \"form_factors_promise_unmet\": %ld,\n", f->promise_unmet);
        fprintf(out, "  \"form_factor_rows_above_one\": %ld,\n", f->rows_above_one);
        jnum(out, "form_factors_clamped_to_one", f->clamped_to_one, 1);
        fprintf(out,
                "  \"visibility\": {\"needed\": %s, \"pairs_tested\": %.0f, "
                "\"pairs_blockable\": %.0f, \"pairs_blocked\": %.0f, \"pairs_partial\": %.0f, "
                "\"candidates\": %.0f, \"evaluations\": %.0f, \"seconds\": %.6g},\n",
                f->vis_needed ? "true" : "false", f->vis_pairs_tested, f->vis_pairs_blockable,
                f->vis_pairs_blocked, f->vis_pairs_partial, f->vis_candidates,
                f->vis_evaluations, f->vis_seconds);
    }
    if (s) {
        jstr(out, "solver", rad_solver_name(s->solver));
        fprintf(out, "  \"bounces\": %d,\n  \"systems_factorised\": %d,\n  \"sweeps\": %d,\n",
                s->bounces, s->systems, s->sweeps);
        jnum(out, "residual", s->residual, 1);
        jnum(out, "rcond", s->rcond, 1);
        jnum(out, "b_error_bound_from_form_factors", s->ff_error_bound, 1);
        jnum(out, "forward_error_bound", s->ferr, 1);
        jnum(out, "backward_error_bound", s->berr, 1);
        jnum(out, "convergence_factor", s->spectral_radius, 1);
        jnum(out, "iteration_error_bound", s->error_bound, 1);
        jnum(out, "contraction_factor", s->contraction, 1);
        fprintf(out, "  \"fallbacks\": %d,\n", s->fallbacks);
        jstr(out, "fallback", s->fallback);
        jnum(out, "row_sum_min", s->row_sum_min, 1);
        jnum(out, "row_sum_max", s->row_sum_max, 1);
        jbands(out, "emitted_power", s->emitted);
        jbands(out, "absorbed_power", s->absorbed);
        jbands(out, "escaped_power", s->escaped);
        jbands(out, "energy_balance_relative", s->balance);
        if (in->b_negative >= 0)
            fprintf(out, "  \"b_negative\": %ld,\n", in->b_negative);
    }
    fprintf(out, "  \"format\": 1\n}\n");
    return ferror(out) ? RAD_ERR_IO : RAD_OK;
}
