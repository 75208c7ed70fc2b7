/* progress_adaptive.c -- `radiosity progress --adaptive`: the race of
 * figure 7 with adaptive subdivision, on the command's side.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * What a student runs to watch adaptive subdivision (Cohen, Chen, Wallace
 * & Greenberg 1988, section 4) work, step by step: the shooting methods of
 * the race (in file order, sorted, sorted with the ambient term) each
 * shoot from the starting mesh's elements as fixed patches and split
 * elements after each shot, exactly as `solve --solver progressive
 * --adaptive` does (the sorted run is that solve).  Gathering is left
 * out: Gauss-Seidel updates the rows of a fixed mesh, with no shot after
 * which to split; the table, the plot and the snapshots have no gathering.
 *
 *   prepare  both shooting orders converged, through the library's
 *            pipeline as `solve` runs them (the shooting order decides
 *            where the mesh is refined, so each order has its own limit);
 *            the starting mesh for the race
 *   race     adaptrace.c: each order again, watched step by step and
 *            measured against its own converged solution projected onto
 *            the leaves of the step (adaptproject.c); snapshots of the
 *            leaves of the step through progress_snap.c
 *
 * The options and their refusals are solve's (cli_adaptive.c), so the
 * same words mean the same run: with --adaptive the form factors are
 * computed on the fly (--matrix none; dense is refused), the mesh's
 * elements are the patches (--patches is refused), and the contour
 * integral is needed (the hemicube is refused).
 */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adapt/adapt.h"
#include "cli/progress_adaptive.h"

void progress_adaptive_init(progress_adaptive *o)
{
    memset(o, 0, sizeof *o);
    rad_solve_options_init(&o->solve);
    o->solve.solver = RAD_SOLVER_PROGRESSIVE;
}

int progress_adaptive_option(progress_adaptive *o, int opt, const char *arg)
{
    return cli_adaptive_option(&o->solve, &o->given_option, opt, arg);
}

int progress_adaptive_check(const progress_adaptive *o, const cli_common *c, int patches,
                            rad_matrix_mode matrix)
{
    const char *bad = NULL;
    if (o->given_option && !o->solve.adaptive)
        bad = "--subdivide-threshold, --subdivide-test and --max-depth apply to --adaptive";
    else if (o->solve.adaptive && patches)
        bad = "--adaptive: the mesh's elements are the patches that shoot; give --mesh, "
              "not --patches";
    else if (o->solve.adaptive && c->ff.method == RAD_FF_HEMICUBE)
        bad = "--adaptive integrates the new elements' form factors on their outlines: it "
              "needs the contour integral, not the hemicube";
    else if (o->solve.adaptive && matrix == RAD_MATRIX_DENSE)
        bad = "--adaptive computes its form factors on the fly (as --matrix none): no "
              "--matrix dense";
    if (!bad)
        return 0;
    cli_error("%s", bad);
    return 2;
}

/* One shooting order to convergence: the pipeline of `solve`. */
static int converge(const progress_adaptive *o, const cli_common *c, const rad_scene *scene,
                    int sort, rad_result *r)
{
    rad_error err;
    rad_pipeline_options po;
    rad_pipeline_options_init(&po);
    po.ff = c->ff;
    po.solve = o->solve;
    po.solve.sort = sort;
    po.matrix = RAD_MATRIX_NONE;
    if (rad_pipeline_run(scene, &po, r, &err) == RAD_OK)
        return 0;
    if (r->ff_done)
        cli_error("the converged adaptive solution (%s): %s",
                  sort ? "sorted" : "shooting in file order", err.message);
    else
        cli_error_rec(&err);
    return 1;
}

int progress_adaptive_prepare(const progress_adaptive *o, cli_common *c, const rad_scene *scene,
                              rad_result *sorted, progress_adaptive_run *run)
{
    rad_error err;
    memset(run, 0, sizeof *run);
    if (converge(o, c, scene, 1, sorted) || converge(o, c, scene, 0, &run->file_order))
        return 1;
    const rad_scene *present = scene;
    if (rad_scene_has_absent(scene)) { /* as the pipeline solved it */
        if (rad_scene_present_copy(scene, NULL, &run->present, &err) != RAD_OK) {
            cli_error_rec(&err);
            return 1;
        }
        present = &run->present;
    }
    if (rad_mesh_build(&run->start, present, &err) != RAD_OK) {
        cli_error_rec(&err);
        return 1;
    }
    return 0;
}

int progress_adaptive_steps(const progress_adaptive_run *run, const rad_result *sorted)
{
    const int a = sorted->solve.sweeps, b = run->file_order.solve.sweeps;
    return a > b ? a : b > 1 ? b : 1;
}

/* A frame of the race to the snapshot writer. */
static int snapshot(void *user, int method, int step, const rad_adapt_frame *f)
{
    const progress_frame pf = {f->mesh, f->B, f->Bv, f->Bref, f->level};
    return progress_snap_write(user, method, step, &pf);
}

int progress_adaptive_race(const progress_adaptive *o, const cli_common *c,
                           const progress_adaptive_run *run, const rad_result *sorted,
                           rad_race_options *race, progress_snap *snap, double *rms,
                           int *reached)
{
    rad_error err;
    const rad_adapt_race ar = {&run->start,
                               &c->ff,
                               &o->solve,
                               {{&run->file_order.mesh, run->file_order.B, run->file_order.level},
                                {&sorted->mesh, sorted->B, sorted->level}},
                               snap ? snapshot : NULL,
                               snap};
    race->progress = c->ff.progress;
    race->progress_user = c->ff.progress_user;
    if (radi_adapt_race_run(&ar, race, rms, reached, &err) == RAD_OK)
        return 0;
    cli_error_rec(snap && snap->failed ? &snap->err : &err);
    return 1;
}

void progress_adaptive_summary(const progress_adaptive_run *run, const rad_result *sorted)
{
    fprintf(stderr,
            CLI_PROGRAM ": --adaptive: %d patches shoot; converged with %d elements after %d "
            "steps sorted, %d elements after %d steps in file order; gathering left out (no "
            "shot to subdivide after)\n",
            run->start.nelements, sorted->mesh.nelements,
            sorted->solve.sweeps, run->file_order.mesh.nelements,
            run->file_order.solve.sweeps);
}

void progress_adaptive_run_free(progress_adaptive_run *run)
{
    rad_result_free(&run->file_order);
    rad_mesh_free(&run->start);
    rad_scene_free(&run->present);
}
