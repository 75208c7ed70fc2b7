/* cmd_render.c -- `radiosity render`: a picture of a solution.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The input is either a scene (solved here through the library's pipeline,
 * cmd_solve.c's cli_run, so every solve option applies) or a solution PLY written by `radiosity solve
 * --output` (read by plyread.c).  The camera comes from the scene's camera
 * line or the PLY's camera comment; --eye, --at, --up and --fov override
 * it piece by piece.  Every output goes through a temporary file, so it
 * appears whole or not at all.
 */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "cli/cli.h"
#include "render/render.h"
#include "radiosity/base.h"
#include "radiosity/scene.h"
#include "radiosity/render.h"
#include "radiosity/plyread.h"
#include "radiosity/plyread.h"

enum {
    OPT_WIDTH = 1200,
    OPT_HEIGHT,
    OPT_EYE,
    OPT_AT,
    OPT_UP,
    OPT_FOV,
    OPT_SHADING,
    OPT_EDGES,
    OPT_EXPOSURE,
    OPT_EXPOSURE_FROM,
    OPT_SCANLINE,
    OPT_PROFILE,
    OPT_PLOT
};

static void help(void)
{
    printf("Usage: radiosity render [OPTIONS] SCENE|SOLUTION.ply -o IMAGE.png\n"
           "Draw a radiosity solution as a PNG picture: a software z-buffer with\n"
           "flat or smooth (Gouraud) shading, one-sided surfaces (back faces are\n"
           "not drawn), the sRGB curve on linear radiosity.  The input is a scene\n"
           "file, which is solved first (the solve options below apply), or a\n"
           "solution written by 'radiosity solve --output FILE.ply'.\n"
           "\n"
           "Options:\n"
           "  -o, --output FILE       the picture (PNG; required)\n"
           "      --width W           picture width in pixels (default 512)\n"
           "      --height H          picture height in pixels (default 512)\n"
           "      --eye X,Y,Z         camera position\n"
           "      --at X,Y,Z          point the camera looks at\n"
           "      --up X,Y,Z          camera up direction (default 0,1,0 when the\n"
           "                          input has no camera)\n"
           "      --fov DEGREES       vertical field of view (default 45 when the\n"
           "                          input has no camera)\n"
           "                          Each camera option overrides that part of the\n"
           "                          scene's camera line or the PLY's camera comment;\n"
           "                          without either, --eye and --at are required.\n"
           "      --shading MODE      flat (each element in its radiosity) or smooth\n"
           "                          (vertex radiosity interpolated; default)\n"
           "      --edges             draw the element edges in black\n"
           "      --exposure X        multiply radiosity by X before the sRGB curve\n"
           "                          (default: automatic, see --exposure-from)\n"
           CLI_EXPOSURE_FROM_HELP
           "      --scanline ROW      the image row (0 = top) for --profile and --plot\n"
           "      --profile FILE      the row's linear radiosity as TSV: x r g b\n"
           "      --plot FILE         the row's radiosity plotted as a PNG\n"
           "\n"
           "Solving a scene (refused with a PLY input, except -q and --help):\n"
           CLI_SOLVE_HELP
           "\n"
           "Examples:\n"
           "  radiosity render data/goral1984-cube.scene -o cube.png\n"
           "  radiosity render --shading flat --edges --mesh 4x4 \\\n"
           "      data/cornell-box.scene -o c.png\n"
           "  radiosity render cube.ply --scanline 256 --plot row.png -o cube.png\n"
           "\n"
           "Exit status: 0 on success, 1 on an error, 2 on a usage error.\n");
}

/* What the command line asked for. */
typedef struct render_args {
    const char *output, *profile, *plot, *input;
    rad_render_options ropt;
    int have_eye, have_at, have_up, have_fov;
    rad_camera cam;             /* the overriding parts */
    int scanline;               /* -1: none */
    int solve_opt;              /* a scene-only option that was given, or 0 */
} render_args;

/* --NAME of an option id, for messages. */
static const char *option_name(const struct option *longopts, int id)
{
    for (const struct option *o = longopts; o->name; o++)
        if (o->val == id)
            return o->name;
    return "?";
}

static int parse_vec_option(const char *name, const char *arg, rad_vec3 *out, int *have)
{
    if (cli_parse_vec3(arg, out)) {
        cli_error("--%s takes X,Y,Z (three numbers separated by commas), not '%s'", name, arg);
        return 2;
    }
    *have = 1;
    return 0;
}

/* A render option: 0 handled, 1 not a render option, 2 usage error. */
static int render_option(render_args *a, int opt, const char *arg)
{
    switch (opt) {
    case 'o':
        a->output = arg;
        return 0;
    case OPT_WIDTH:
    case OPT_HEIGHT:
        if (cli_parse_int(arg, 1, RAD_RENDER_MAX_SIDE,
                          opt == OPT_WIDTH ? &a->ropt.width : &a->ropt.height)) {
            cli_error("--%s takes a whole number from 1 to %d, not '%s'",
                      opt == OPT_WIDTH ? "width" : "height", RAD_RENDER_MAX_SIDE, arg);
            return 2;
        }
        return 0;
    case OPT_EYE: return parse_vec_option("eye", arg, &a->cam.eye, &a->have_eye);
    case OPT_AT: return parse_vec_option("at", arg, &a->cam.at, &a->have_at);
    case OPT_UP: return parse_vec_option("up", arg, &a->cam.up, &a->have_up);
    case OPT_FOV:
        if (cli_parse_double(arg, &a->cam.fov) || !(a->cam.fov > 0 && a->cam.fov < 180)) {
            cli_error("--fov takes degrees between 0 and 180, not '%s'", arg);
            return 2;
        }
        a->have_fov = 1;
        return 0;
    case OPT_SHADING:
        if (strcmp(arg, "flat") == 0)
            a->ropt.shading = RAD_SHADING_FLAT;
        else if (strcmp(arg, "smooth") == 0)
            a->ropt.shading = RAD_SHADING_SMOOTH;
        else {
            cli_error("--shading takes flat or smooth, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_EDGES:
        a->ropt.edges = 1;
        return 0;
    case OPT_EXPOSURE:
        if (cli_parse_double(arg, &a->ropt.exposure) || !(a->ropt.exposure > 0)) {
            cli_error("--exposure takes a positive number, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_EXPOSURE_FROM:
        return cli_parse_exposure_from(arg, &a->ropt.exposure_from);
    case OPT_SCANLINE:
        if (cli_parse_int(arg, 0, RAD_RENDER_MAX_SIDE - 1, &a->scanline)) {
            cli_error("--scanline takes a row number from 0, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_PROFILE:
        a->profile = arg;
        return 0;
    case OPT_PLOT:
        a->plot = arg;
        return 0;
    default:
        return 1;
    }
}

/* Options that only make sense together; 0 fine, 2 usage error. */
static int check_args(const render_args *a)
{
    const rad_render_options *o = &a->ropt;
    if (!a->output) {
        cli_error("render needs -o IMAGE.png");
        return 2;
    }
    if (cli_png_name_check(a->output, "-o") || (a->plot && cli_png_name_check(a->plot, "--plot")))
        return 2;
    if ((double)o->width * o->height > RAD_RENDER_MAX_PIXELS) {
        cli_error("a %d x %d picture is more than %d pixels", o->width, o->height,
                  RAD_RENDER_MAX_PIXELS);
        return 2;
    }
    if (a->scanline >= 0 && !a->profile && !a->plot) {
        cli_error("--scanline needs --profile FILE or --plot FILE");
        return 2;
    }
    if (a->scanline < 0 && (a->profile || a->plot)) {
        cli_error("--profile and --plot need --scanline ROW");
        return 2;
    }
    if (a->scanline >= o->height) {
        cli_error("--scanline %d is outside the picture (rows 0 to %d)", a->scanline,
                  o->height - 1);
        return 2;
    }
    return 0;
}

static int ends_with_ply(const char *path)
{
    size_t n = strlen(path);
    return n >= 4 && strcasecmp(path + n - 4, ".ply") == 0;
}

/* The input's camera with the command line's parts over it; 0 or 1 (printed). */
static int make_camera(const render_args *a, const rad_camera *base, rad_camera *cam)
{
    rad_error err;
    if (base->defined) {
        *cam = *base;
    } else {
        if (!a->have_eye || !a->have_at) {
            cli_error("%s has no camera: give --eye X,Y,Z and --at X,Y,Z (and --up, --fov "
                      "if the defaults 0,1,0 and 45 do not suit)", a->input);
            return 1;
        }
        memset(cam, 0, sizeof *cam);
        cam->up = (rad_vec3){0, 1, 0};
        cam->fov = 45;
    }
    cam->defined = 1;
    if (a->have_eye)
        cam->eye = a->cam.eye;
    if (a->have_at)
        cam->at = a->cam.at;
    if (a->have_up)
        cam->up = a->cam.up;
    if (a->have_fov)
        cam->fov = a->cam.fov;
    if (rad_camera_check(cam, &err) != RAD_OK) {
        cli_error("%s", err.message);
        return 1;
    }
    return 0;
}

/* The solve's model: its mesh with element and vertex radiosity. */
static int model_from_run(const cli_run *run, rad_render_model *model)
{
    rad_error err;
    if (rad_render_model_from_mesh(model, &run->res.mesh, run->res.B, run->res.Bv, &err) !=
        RAD_OK) {
        cli_error_rec(&err);
        return 1;
    }
    return 0;
}

/* ---- the outputs ---------------------------------------------------------- */

typedef struct picture {
    const render_args *a;
    const cli_solve *s;
    rad_image img;
} picture;

static int w_profile(FILE *out, const void *c)
{
    const picture *p = c;
    const double *row = rad_image_row(&p->img, p->a->scanline);
    fprintf(out, "x\tr\tg\tb\n");
    for (int x = 0; x < p->img.width; x++)
        fprintf(out, "%d\t%.17g\t%.17g\t%.17g\n", x, row[3 * x], row[3 * x + 1],
                row[3 * x + 2]);
    return ferror(out) ? -1 : 0;
}

static void plot_title(const render_args *a, const cli_solve *s, char *buf, size_t n)
{
    const char *base = strrchr(a->input, '/');
    int k = snprintf(buf, n, "%s, row %d, %s", base ? base + 1 : a->input, a->scanline,
                     a->ropt.shading == RAD_SHADING_FLAT ? "flat" : "smooth");
    if (k > 0 && (size_t)k < n && s->common.mesh_n > 0)
        k += snprintf(buf + k, n - (size_t)k, ", mesh %dx%d", s->common.mesh_n,
                      s->common.mesh_m);
    if (k > 0 && (size_t)k < n && s->common.max_size > 0)
        k += snprintf(buf + k, n - (size_t)k, ", elements <= %g", s->common.max_size);
    if (k > 0 && (size_t)k < n && s->solve.bounces >= 0 && !ends_with_ply(a->input))
        snprintf(buf + k, n - (size_t)k, ", %d bounce%s", s->solve.bounces,
                 s->solve.bounces == 1 ? "" : "s");
}

/* A library call that failed is reported here; the writer then says only
 * that it failed (cli_output.c adds the path). */
static int report(rad_status st, const rad_error *err)
{
    if (st != RAD_OK) {
        cli_error_rec(err);
        return -1;
    }
    return 0;
}

static int w_plot(FILE *out, const void *c)
{
    const picture *p = c;
    char title[256];
    rad_error err;
    plot_title(p->a, p->s, title, sizeof title);
    return report(radi_plot_scanline(rad_image_row(&p->img, p->a->scanline), p->img.width,
                                    title, RAD_PLOT_WIDTH, RAD_PLOT_HEIGHT, out, &err),
                  &err);
}

static int w_png(FILE *out, const void *c)
{
    const picture *p = c;
    rad_error err;
    return report(rad_image_write_png(&p->img, out, &err), &err);
}

/* The picture, the profile and the plot, as outputs; returns how many. */
static int picture_outputs(const picture *p, cli_output *o)
{
    int n = 0;
    o[n++] = (cli_output){p->a->output, w_png, p};
    if (p->a->scanline >= 0) {
        o[n++] = (cli_output){p->a->profile, w_profile, p};
        o[n++] = (cli_output){p->a->plot, w_plot, p};
    }
    return n;
}

/* Camera first, then every output path, then the work: nothing that can
 * be found wrong is found after the solve. */
static int render_input(const render_args *a, cli_solve *s, picture *pic)
{
    rad_render_model model;
    rad_camera base = {0};
    rad_error err;
    cli_run run;
    cli_output o[CLI_MAX_OUTPUTS], own[3];
    const int is_ply = ends_with_ply(a->input);
    int status = 1, n = 0;
    const int nown = picture_outputs(pic, own);
    memset(&model, 0, sizeof model);
    memset(&run, 0, sizeof run);
    if (is_ply) {
        if (rad_ply_read(&model, &base, a->input, &err) != RAD_OK) {
            cli_error_rec(&err);
            return 1;
        }
    } else {
        if (cli_run_load(&run, s, a->input))
            return 1;
        base = run.scene.camera;
        n = cli_run_outputs(&run, 0, o);
    }
    for (int k = 0; k < nown; k++)
        o[n++] = own[k];
    rad_render_options ropt = a->ropt;
    if (make_camera(a, &base, &ropt.camera) || cli_outputs_check(o, n))
        goto done;
    if (!is_ply) {
        if (cli_run_solve(&run)) {
            cli_run_write(&run, NULL, 0); /* the report says why */
            goto done;
        }
        if (model_from_run(&run, &model))
            goto done;
    }
    if (rad_render(&model, &ropt, &pic->img, &err) != RAD_OK) {
        cli_error_rec(&err);
        goto done;
    }
    status = is_ply ? cli_outputs_write(own, nown) : cli_run_write(&run, own, nown);
done:
    rad_render_model_free(&model);
    if (!is_ply)
        cli_run_free(&run);
    return status;
}

int cmd_render(int argc, char **argv)
{
    static const struct option longopts[] = {
        {"output", required_argument, NULL, 'o'},
        {"width", required_argument, NULL, OPT_WIDTH},
        {"height", required_argument, NULL, OPT_HEIGHT},
        {"eye", required_argument, NULL, OPT_EYE},
        {"at", required_argument, NULL, OPT_AT},
        {"up", required_argument, NULL, OPT_UP},
        {"fov", required_argument, NULL, OPT_FOV},
        {"shading", required_argument, NULL, OPT_SHADING},
        {"edges", no_argument, NULL, OPT_EDGES},
        {"exposure", required_argument, NULL, OPT_EXPOSURE},
        {"exposure-from", required_argument, NULL, OPT_EXPOSURE_FROM},
        {"scanline", required_argument, NULL, OPT_SCANLINE},
        {"profile", required_argument, NULL, OPT_PROFILE},
        {"plot", required_argument, NULL, OPT_PLOT},
        CLI_SOLVE_LONGOPTS,
        {NULL, 0, NULL, 0}};
    render_args a;
    cli_solve s;
    int opt, r;
    memset(&a, 0, sizeof a);
    rad_render_options_init(&a.ropt);
    a.scanline = -1;
    cli_solve_init(&s);
    cli_join_optional(&argc, argv);
    while ((opt = getopt_long(argc, argv, "ho:q", longopts, NULL)) != -1) {
        if (opt == OPT_HELP || opt == 'h') {
            help();
            return 0;
        }
        if (opt == '?' || opt == ':')
            return cli_usage_hint("render");
        r = render_option(&a, opt, optarg);
        if (r == 1) {
            r = cli_solve_option(&s, opt, optarg);
            if (r == 0 && opt != 'q' && opt != OPT_QUIET && !a.solve_opt)
                a.solve_opt = opt;
        }
        if (r != 0)
            return cli_usage_hint("render");
    }
    if (optind != argc - 1) {
        cli_error(optind >= argc ? "render needs a SCENE or a SOLUTION.ply"
                                 : "render takes one SCENE or SOLUTION.ply");
        return cli_usage_hint("render");
    }
    a.input = argv[optind];
    if (check_args(&a) || cli_solve_check(&s))
        return cli_usage_hint("render");
    if (ends_with_ply(a.input) && a.solve_opt) {
        cli_error("--%s applies to a scene, not to a solution PLY",
                  option_name(longopts, a.solve_opt));
        return cli_usage_hint("render");
    }
    picture pic;
    memset(&pic, 0, sizeof pic);
    pic.a = &a;
    pic.s = &s;
    int status = render_input(&a, &s, &pic);
    rad_image_free(&pic.img);
    return status;
}
