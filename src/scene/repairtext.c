/* repairtext.c -- what a foreign format's reader repaired, said in words.
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The OBJ reader (objread.c, objrepair.c) counts its repairs by kind in
 * rad_scene_repairs; every caller that loads a scene (the program, the
 * Python binding) says them in these same lines, one per kind, each with
 * the input line of the first. */
#include <stdio.h>

#include "radiosity/scene.h"

int rad_scene_repair_text(const rad_scene *scene, int k, char *buf, size_t size)
{
    const rad_scene_repairs *p = &scene->repairs;
    if (k < 0 || k >= RAD_SCENE_REPAIR_KINDS || size == 0)
        return 0;
    char split[96], at[16] = "";
    snprintf(split, sizeof split, "not planar, not convex or running round twice cut into %d "
             "triangles", p->split_triangles);
    const struct {
        int count;
        const char *noun, *what;
    } kind[RAD_SCENE_REPAIR_KINDS] = {
        {p->undefined_materials, "face", "use a material that no mtllib defines: given the "
                                         "default grey (reflectance 0.5)"},
        {p->spaced_names, "name", "with spaces, with bytes beyond ASCII, or empty, taken as "
                                  "written"},
        {p->degenerate_faces, "face", "without area (fewer than 3 distinct corners, or all "
                                      "on a line) left out"},
        {p->split_faces, "face", split},
    };
    if (!kind[k].count)
        return 0;
    if (p->first_line[k])
        snprintf(at, sizeof at, ":%d", p->first_line[k]);
    snprintf(buf, size, "%s%s: repaired: %d %s%s %s", scene->filename ? scene->filename : "-",
             at, kind[k].count, kind[k].noun, kind[k].count == 1 ? "" : "s", kind[k].what);
    return 1;
}
