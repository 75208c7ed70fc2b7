/* animout.c -- the files `radiosity animate` writes at the end of a run:
 * the per-shot trace, the per-frame errors and the JSON report.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Numbers are printed with %.17g, so that they read back as the same
 * doubles; what was not measured is "nan" in the tables and null in the
 * JSON (RFC 8259 has no NaN).  Columns and keys: radiosity-files(5).
 */
#include <config.h>

#include <math.h>
#include <stdio.h>

#include "cli/animrun.h"
#include "util/util.h"

static void tsv_num(FILE *out, double v)
{
    if (isnan(v))
        fputs("nan", out);
    else
        fprintf(out, "%.17g", v);
}

int cli_anim_trace(FILE *out, const void *ctx)
{
    const anim_run *r = ctx;
    fputs("frame\tstep\tshooter\tkind\tsign\tpower\tunshot\tredistribution_left\terror"
          "\terror_top1\tgather\n", out);
    for (size_t k = 0; k < r->nshots; k++) {
        const rad_anim_shot *s = &r->shots[k];
        fprintf(out, "%d\t%ld\t%d\t%s\t%d\t%.17g\t%.17g\t%.17g\t", s->frame, s->step,
                s->shooter, s->redistribute ? "redistribute" : "propagate", s->sign, s->power,
                s->unshot, s->redistribution_left);
        tsv_num(out, r->shot_err[2 * k]);
        fputc('\t', out);
        tsv_num(out, r->shot_err[2 * k + 1]);
        fprintf(out, "\t%d\n", s->gather);
    }
    return ferror(out) ? -1 : 0;
}

/* --errors: one row per frame run (radiosity-files(5), "Animation errors"). */
int cli_anim_errors(FILE *out, const void *ctx)
{
    const anim_run *r = ctx;
    fputs("frame\tshots\tseconds\tpairs_recomputed\tpairs_share\terror\terror_top1\n", out);
    for (int f = 0; f <= r->changes.nframes; f++) {
        const frame_row *w = &r->frames[f];
        if (!w->ran)
            continue;
        fprintf(out, "%d\t%ld\t%.17g\t%.17g\t", f, w->rep.shots, w->rep.t_total,
                w->rep.pairs_recomputed);
        tsv_num(out, w->rep.pairs_total > 0 ? w->rep.pairs_recomputed / w->rep.pairs_total : 0);
        fputc('\t', out);
        tsv_num(out, w->error);
        fputc('\t', out);
        tsv_num(out, w->error_top);
        fputc('\n', out);
    }
    return ferror(out) ? -1 : 0;
}

static void json_num(FILE *out, const char *key, double v, const char *sep)
{
    if (isfinite(v))
        fprintf(out, "\"%s\": %.17g%s", key, v, sep);
    else
        fprintf(out, "\"%s\": null%s", key, sep);
}

int cli_anim_report(FILE *out, const void *ctx)
{
    const anim_run *r = ctx;
    const rad_mesh *m = rad_anim_mesh(r->anim);
    fputs("{\n  \"scene\": ", out);
    radi_json_string(out, r->scene.filename);
    fputs(",\n  \"changes\": ", out);
    radi_json_string(out, r->changes.filename);
    fprintf(out, ",\n  \"elements\": %d,\n", m->nelements);
    fprintf(out, "  \"strategy\": %d,\n  \"steps\": %ld,\n  ", r->args->opt.strategy,
            r->args->opt.steps);
    json_num(out, "tolerance", r->args->opt.tolerance, ",\n  \"frames\": [\n");
    int sep = 0;
    for (int f = 0; f <= r->changes.nframes; f++) {
        const frame_row *w = &r->frames[f];
        const rad_anim_report *p = &w->rep;
        if (!w->ran)
            continue; /* before a --resume */
        fputs(sep++ ? ",\n" : "", out);
        fprintf(out, "    {\"frame\": %d, \"shots\": %ld, \"redistribution_shots\": %ld, "
                "\"propagation_shots\": %ld, \"converged\": %s, ", f, p->shots,
                p->redistribution_shots, p->propagation_shots, p->converged ? "true" : "false");
        json_num(out, "unshot", p->unshot, ", ");
        json_num(out, "emitted", p->emitted, ", ");
        json_num(out, "pairs_recomputed", p->pairs_recomputed, ", ");
        json_num(out, "pairs_total", p->pairs_total, ", ");
        json_num(out, "pairs_share", p->pairs_total > 0 ? p->pairs_recomputed / p->pairs_total
                                                        : 0, ", ");
        json_num(out, "pairs_changed", p->pairs_changed, ", ");
        json_num(out, "t_formfactor", p->t_formfactor, ", ");
        json_num(out, "t_shoot", p->t_shoot, ", ");
        json_num(out, "t_total", p->t_total, ", ");
        json_num(out, "t_reference", w->t_reference, ", ");
        json_num(out, "t_changed", p->t_changed, ", ");
        json_num(out, "error_eq7", w->error, ", ");
        json_num(out, "error_eq7_top1", w->error_top, ", ");
        fprintf(out, "\"log_pass\": %s, ", p->log_pass ? "true" : "false");
        json_num(out, "log_residual", p->log_residual, "}");
    }
    fputs("\n  ]\n}\n", out);
    return ferror(out) ? -1 : 0;
}
