/* cmd_view.c -- `radiosity view`: watch progressive refinement converge in
 * a browser (view/view.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * scene -> mesh -> form factors -> gauss (the converged solution, the
 * error plot's reference, as `radiosity progress` takes it) -> the server
 * until Ctrl-C or the page's stop button.  Only parsing, dispatch and
 * messages live here.  Built without libmicrohttpd (configure says so),
 * the command says that and exits 1.
 */
#include <config.h>

#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "radiosity/base.h"
#include "radiosity/mesh.h"
#include "radiosity/pipeline.h"
#include "radiosity/solve.h"
#include "radiosity/scene.h"
#include "radiosity/changes.h"
#ifdef CLI_VIEW
#include "view/view.h"
#endif

enum {
    OPT_LISTEN = 1300,
    OPT_OPEN,
    OPT_RECORD,
    OPT_ASSETS,
    OPT_METHOD,
    OPT_PAUSED,
    OPT_RATE,
    OPT_CONNECTIONS
};

static void help(void)
{
    printf("Usage: radiosity view [OPTIONS] SCENE [CHANGES]\n"
           "Watch progressive refinement (Cohen, Chen, Wallace & Greenberg 1988)\n"
           "converge in a web browser: the program solves the scene once (the\n"
           "converged solution the error is measured against), then serves a page\n"
           "that draws the scene in WebGL as each shot lands, with the solver's\n"
           "controls, the current shooter, the unshot energy left and the RMS error\n"
           "(eq. 14) against step.  It prints the URL to open and serves until\n"
           "Ctrl-C (SIGINT, SIGTERM or SIGHUP; exit 0) or the page's stop button.\n"
           "From the page, objects are moved, turned, taken out and put back and\n"
           "materials changed, and undone: each change is a frame that the\n"
           "redistribution engine of `radiosity animate' (George, Sillion &\n"
           "Greenberg 1990) runs while the picture follows.  The frames of CHANGES\n"
           "(a change file, radiosity-scene(5)) run first.\n"
           "Nothing is fetched from the internet, and no file is written but the\n"
           "one --record names.\n"
           "\n"
           "Options:\n"
           "      --listen ADDR:PORT  the IPv4 address and port to serve on (default\n"
           "                          127.0.0.1:0, a free port on the loopback; an\n"
           "                          address other than the loopback's lets other\n"
           "                          machines watch and steer the session)\n"
           "      --method M          the method shown first: shooting (file order),\n"
           "                          sorted (largest unshot power first),\n"
           "                          sorted_ambient (sorted, shown with the ambient\n"
           "                          term; the default), gathering (Gauss-Seidel,\n"
           "                          one element a step), jacobi (one sweep a step),\n"
           "                          race (the first four side by side, as in\n"
           "                          figure 7 of the paper) or adaptive (sorted\n"
           "                          shooting with adaptive subdivision, section 4:\n"
           "                          the mesh splits as the light lands; no error\n"
           "                          curve, its converged mesh being unknown)\n"
           "      --subdivide-threshold T  adaptive: split an element where |B -\n"
           "                          B_neighbour| > T times the largest reflected\n"
           "                          radiosity, in some band (default 0.1)\n"
           "      --max-depth D       adaptive: at most D splits below a starting\n"
           "                          element, 0 to 8 (default 3); refused when\n"
           "                          every level's elements together could pass\n"
           "                          4,000,000\n"
           "      --subdivide-test difference|error  adaptive: T bounds the\n"
           "                          difference (default) or the difference times\n"
           "                          the element's side over the largest patch's\n"
           "      --paused            start paused at step 0\n"
           "      --open              start the desktop's browser on the URL (xdg-open)\n"
           "      --record FILE       at the end, write the session's changes (every\n"
           "                          frame that ran, undo frames included) as a\n"
           "                          change file that `radiosity animate SCENE FILE'\n"
           "                          replays\n"
           "      --rate R            steps a second at most while running (default\n"
           "                          30; 0: as fast as the machine goes)\n"
           "      --max-connections N connections served at once (1-1000, default 16)\n"
           "      --max-iterations N  give up on a frame of changes that has not\n"
           "                          converged after N shots: the frame is dropped,\n"
           "                          with those queued after it, and the scene stays\n"
           "                          as before it (default 1000 n + 100000, n the\n"
           "                          elements); frame 0, the scene as loaded, is held\n"
           "                          to it too, and when it fails the session takes\n"
           "                          no changes\n"
           "      --assets DIR        the folder of the page (index.html, view.js;\n"
           "                          default: the installed one)\n" CLI_COMMON_HELP
           "\n"
           "The page's requests are described in radiosity(1), THE LIVE VIEW.\n");
}

typedef struct view_args {
    cli_common common;
    rad_solve_options adaptive; /* the adaptive method's options */
    int given_adaptive;
    const char *listen, *assets, *method, *record;
    int paused, connections, open;
    long max_shots;             /* --max-iterations; 0: the engine's default */
    double rate;
    char addr[64];              /* --listen's address, for the options */
} view_args;

static int parse_option(view_args *a, int opt, const char *arg)
{
    switch (opt) {
    case OPT_LISTEN:
        a->listen = arg;
        return 0;
    case OPT_ASSETS:
        a->assets = arg;
        return 0;
    case OPT_METHOD:
        a->method = arg;
        return 0;
    case OPT_PAUSED:
        a->paused = 1;
        return 0;
    case OPT_OPEN:
        a->open = 1;
        return 0;
    case OPT_RECORD:
        a->record = arg;
        return 0;
    case OPT_RATE:
        if (cli_parse_double(arg, &a->rate) || !(a->rate >= 0 && a->rate <= 100000)) {
            cli_error("--rate takes a number from 0 to 100000, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_CONNECTIONS:
        if (cli_parse_int(arg, 1, 1000, &a->connections)) {
            cli_error("--max-connections takes a whole number from 1 to 1000, not '%s'", arg);
            return 2;
        }
        return 0;
    case OPT_MAX_ITERATIONS: { /* animate's option: the shots a frame may take */
        int k;
        if (cli_parse_int(arg, 1, 2000000000, &k)) {
            cli_error("--max-iterations needs a whole number from 1, not '%s'", arg);
            return 2;
        }
        a->max_shots = k;
        return 0;
    }
    default: {
        const int r = cli_adaptive_option(&a->adaptive, &a->given_adaptive, opt, arg);
        if (r != 1)
            return r;
        return cli_common_option(&a->common, opt, arg) == 0 ? 0 : 2;
    }
    }
}

#ifdef CLI_VIEW
/* "ADDR:PORT" into the options' address (a copy in addr) and port. */
static int parse_listen(const char *arg, char addr[64], radi_view_options *o)
{
    const char *colon = strrchr(arg, ':');
    int port;
    if (!colon || colon == arg || (size_t)(colon - arg) >= 64 ||
        cli_parse_int(colon + 1, 0, 65535, &port)) {
        cli_error("--listen takes ADDR:PORT (an IPv4 address, a port from 0 to 65535), "
                  "not '%s'",
                  arg);
        return 2;
    }
    memcpy(addr, arg, (size_t)(colon - arg));
    addr[colon - arg] = '\0';
    o->address = addr;
    o->port = port;
    return 0;
}

static int write_text(FILE *out, const void *ctx)
{
    const char *text = ctx;
    return fputs(text, out) < 0 ? -1 : 0;
}

/* The change file's text, once rad_changes_load has checked it (its
 * messages name the file and line); NULL (printed) when it cannot. */
static char *changes_text(const char *path, const rad_scene *scene, size_t *len)
{
    rad_changes ch;
    rad_error err;
    if (rad_changes_load(&ch, scene, path, &err) != RAD_OK) {
        cli_error_rec(&err);
        return NULL;
    }
    rad_changes_free(&ch);
    FILE *f = strcmp(path, "-") ? fopen(path, "rb") : NULL;
    char *text = NULL;
    size_t cap = 0;
    *len = 0;
    if (!f) {
        cli_error("%s: %s", path, strcmp(path, "-") ? strerror(errno)
                                                   : "changes from standard input are "
                                                     "read once; give a file");
        return NULL;
    }
    for (;;) {
        if (*len + 4096 + 1 > cap) {
            char *more = realloc(text, cap = 2 * cap + 8192);
            if (!more)
                break;
            text = more;
        }
        const size_t k = fread(text + *len, 1, cap - *len - 1, f);
        *len += k;
        if (k == 0)
            break;
    }
    const int bad = ferror(f) || !text;
    fclose(f);
    if (bad) {
        cli_error("%s: cannot read it", path);
        free(text);
        return NULL;
    }
    text[*len] = '\0';
    return text;
}

/* The view stops on SIGINT, SIGTERM and SIGHUP (cli_signals_defer). */
static int stop_on_signal(void *user)
{
    (void)user;
    return cli_signal_taken() != 0;
}

static int serve(const rad_scene *scene, const rad_result *res, radi_view_options *o,
                 char **record)
{
    rad_error err;
    o->stop = stop_on_signal;
    cli_signals_defer(1);
    const rad_status st = radi_view_serve(scene, res, o, record, &err);
    cli_signals_defer(0);
    if (st != RAD_OK)
        cli_error_rec(&err);
    return st != RAD_OK;
}

static int run(view_args *a, radi_view_options *o, const char *path, const char *changes)
{
    rad_scene scene;
    rad_result res;
    rad_error err;
    rad_pipeline_options po;
    char *text = NULL, *record = NULL;
    int status = 1;
    const cli_output rec[1] = {{a->record, write_text, NULL}};
    memset(&res, 0, sizeof res);
    if (cli_outputs_check(rec, 1) || cli_load_scene(path, &a->common, &scene))
        return 1;
    if (changes && !(text = changes_text(changes, &scene, &o->changes_len)))
        goto done;
    o->changes = text;
    rad_pipeline_options_init(&po);
    cli_progress_attach(&a->common);
    po.ff = a->common.ff;
    po.keep_form_factors = 1;
    o->ff = a->common.ff;
    o->crease = rad_crease_default(&scene);
    o->vertex_rule = po.vertex_rule;
    if (rad_pipeline_run(&scene, &po, &res, &err) != RAD_OK) {
        if (res.ff_done)
            cli_error("the converged (gauss) solution: %s", err.message);
        else
            cli_error_rec(&err);
    } else if (!a->common.quiet && cli_ff_verdict(&a->common, &res.ff)) {
        /* --strict and an unmet promise: printed */
    } else if (serve(&scene, &res, o, a->record ? &record : NULL)) {
        /* printed */
    } else if (a->record && cli_write_atomic(a->record, write_text, record)) {
        /* printed */
    } else {
        status = 0;
    }
done:
    free(record);
    free(text);
    rad_result_free(&res);
    rad_scene_free(&scene);
    return status;
}
#endif

int cmd_view(int argc, char **argv)
{
    static const struct option longopts[] = {
        {"listen", required_argument, NULL, OPT_LISTEN},
        {"assets", required_argument, NULL, OPT_ASSETS},
        {"method", required_argument, NULL, OPT_METHOD},
        {"paused", no_argument, NULL, OPT_PAUSED},
        {"open", no_argument, NULL, OPT_OPEN},
        {"record", required_argument, NULL, OPT_RECORD},
        {"rate", required_argument, NULL, OPT_RATE},
        {"max-connections", required_argument, NULL, OPT_CONNECTIONS},
        {"max-iterations", required_argument, NULL, OPT_MAX_ITERATIONS},
        {"subdivide-threshold", required_argument, NULL, OPT_SUBDIVIDE_THRESHOLD},
        {"max-depth", required_argument, NULL, OPT_MAX_DEPTH},
        {"subdivide-test", required_argument, NULL, OPT_SUBDIVIDE_TEST},
        CLI_COMMON_LONGOPTS,
        {NULL, 0, NULL, 0}};
    view_args a;
    int opt;
    memset(&a, 0, sizeof a);
    cli_common_init(&a.common);
    rad_solve_options_init(&a.adaptive);
    a.rate = 30;
    a.connections = 16;
    while ((opt = getopt_long(argc, argv, "hq", longopts, NULL)) != -1) {
        if (opt == OPT_HELP || opt == 'h') {
            help();
            return 0;
        }
        if (parse_option(&a, opt, optarg) != 0)
            return cli_usage_hint("view");
    }
    if (cli_common_check(&a.common))
        return cli_usage_hint("view");
    if (optind != argc - 1 && optind != argc - 2) {
        cli_error(optind >= argc ? "view needs a SCENE"
                                 : "view takes one SCENE and at most one CHANGES file");
        return cli_usage_hint("view");
    }
#ifdef CLI_VIEW
    radi_view_options o;
    radi_view_options_init(&o);
    if (a.listen && parse_listen(a.listen, a.addr, &o))
        return cli_usage_hint("view");
    if (a.method && (o.method = radi_view_method(a.method)) < 0) {
        cli_error("--method: unknown method '%s' (shooting, sorted, sorted_ambient, gathering, "
                  "jacobi, race, adaptive)",
                  a.method);
        return cli_usage_hint("view");
    }
    o.adaptive = a.adaptive;
    o.assets = a.assets ? a.assets : CLI_VIEW_ASSETS;
    o.paused = a.paused;
    o.rate = a.rate;
    o.max_connections = a.connections;
    o.max_shots = a.max_shots;
    o.open_browser = a.open;
    return run(&a, &o, argv[optind], optind + 1 < argc ? argv[optind + 1] : NULL);
#else
    cli_error("view: this program was built without the live viewer (configure found no "
              "libmicrohttpd; install libmicrohttpd-dev and build again)");
    return 1;
#endif
}
