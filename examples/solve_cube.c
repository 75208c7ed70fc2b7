/* solve_cube.c -- the library in thirty lines: load the 1984 cube, solve
 * it, print the radiosity of the element at the centre of each wall.
 * Build: cc solve_cube.c $(pkg-config --cflags --libs radiosity)
 * Run:   ./a.out [SCENE]   (default: the cube as installed, from any folder)
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING. */
#include <stdio.h>

#include <radiosity.h>
#include <radiosity/pipeline.h> /* the whole run as one call */

int main(int argc, char **argv)
{
    char cube[4096];
    snprintf(cube, sizeof cube, "%s/goral1984-cube.scene", rad_scene_dir());
    const char *path = argc > 1 ? argv[1] : cube;
    rad_scene scene;
    rad_pipeline_options opt;
    rad_result res;
    rad_error err;
    if (rad_scene_load(&scene, path, &err) != RAD_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    rad_pipeline_options_init(&opt); /* default accuracy, LU solve */
    rad_status st = rad_pipeline_run(&scene, &opt, &res, &err);
    if (st == RAD_OK) {
        const int n = res.mesh.nelements;
        printf("surface\telement\tr\tg\tb\n");
        for (int s = 0; s < res.mesh.nsurfaces; s++) {
            int e = (res.mesh.surface_first[s] + res.mesh.surface_first[s + 1]) / 2;
            printf("%d\t%d\t%.6f\t%.6f\t%.6f\n", s, e, res.B[e], res.B[e + n], res.B[e + 2 * n]);
        }
    } else {
        fprintf(stderr, "%s\n", err.message);
    }
    rad_result_free(&res);
    rad_scene_free(&scene);
    return st == RAD_OK ? 0 : 1;
}
