/* render.h -- camera, software z-buffer rasteriser and tone mapping.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The renderer draws a neutral model of polygons carrying radiosity, not
 * the mesh itself, so a solution read back from a PLY file draws the same
 * way as one just solved.  Everything is double precision and runs in one
 * thread in a fixed order: the same model and options give the same
 * pixels, bit for bit.
 *
 * Image conventions: pixel (x, y) has x = 0 at the left, y = 0 at the top,
 * and is sampled once, at its centre (x + 0.5, y + 0.5).  The camera looks
 * from eye towards at; up fixes the roll; fov is the vertical field of view
 * in degrees; pixels are square.  Seen through the camera, world "right" is
 * (at - eye) x up.
 */
#ifndef RAD_RENDER_H
#define RAD_RENDER_H

#include <stdio.h>

#include "radiosity/mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A polygon model with radiosity.  Arrays are owned by the model
 * (rad_render_model_free).  Bands are column-major like everywhere else in
 * the library: vrad[v + b*nvertices], frad[f + b*nfaces].
 *
 * Faces are convex planar polygons whose vertices run counter-clockwise
 * about their front (the side drawn).  A 4-vertex face is a quad element:
 * its corners 0 1 2 3 are (u,v) = (0,0) (1,0) (1,1) (0,1) of its bilinear
 * parameterisation, as the mesh cuts a quadrilateral. */
typedef struct rad_render_model {
    int nvertices;
    rad_vec3 *pos;              /* vertex positions */
    double *vrad;               /* nvertices x RAD_BANDS vertex radiosity
                                   (smooth shading), or NULL: flat only */
    int nfaces;
    int *face_first;            /* nfaces + 1 offsets into face_index */
    int *face_index;            /* vertex indices of face f:
                                   face_index[face_first[f] .. face_first[f+1]) */
    double *frad;               /* nfaces x RAD_BANDS element radiosity */
    int *face_surface;          /* scene surface of each face, -1 unknown */
    int *face_gi, *face_gj;     /* grid position in its surface, -1 unknown */
    unsigned char *face_emits;  /* non-zero: the face emits light (E > 0 in
                                   some band); NULL: not known */
} rad_render_model;

typedef enum rad_shading {
    RAD_SHADING_FLAT = 0,       /* each face in its element radiosity */
    RAD_SHADING_SMOOTH          /* vertex radiosity interpolated (Gouraud 1971) */
} rad_shading;

/* What the automatic exposure maps to full scale: the brightest element
 * that does not emit (so that a small bright lamp does not leave the room
 * nearly black), or the brightest of all, lamps included. */
typedef enum rad_exposure_from {
    RAD_EXPOSURE_REFLECTORS = 0,
    RAD_EXPOSURE_ALL
} rad_exposure_from;

#define RAD_RENDER_MAX_SIDE 16384       /* largest width or height */
#define RAD_RENDER_MAX_PIXELS (1 << 24) /* largest width * height (~37 bytes each) */

typedef struct rad_render_options {
    rad_camera camera;          /* camera.defined must be non-zero */
    int width, height;          /* pixels, 1 .. RAD_RENDER_MAX_SIDE */
    rad_shading shading;
    int edges;                  /* non-zero: draw the element edges in black */
    double exposure;            /* > 0: radiosity multiplier before the sRGB
                                   curve; 0: automatic, see exposure_from */
    rad_exposure_from exposure_from; /* automatic exposure: 1 / the largest
                                   radiosity (any band) of the faces that do
                                   not emit (REFLECTORS, the default), or of
                                   all faces (ALL); REFLECTORS falls back to
                                   ALL when no face is known to emit or no
                                   reflector has radiosity above 0 */
    double znear;               /* > 0: the near plane's distance from the
                                   eye; 0: 1e-6 of the scene's size plus the
                                   eye's distance from it (the hemicube, its
                                   eye on a surface, sets its own) */
} rad_render_options;

/* A rendered picture, before and after tone mapping. */
typedef struct rad_image {
    int width, height;
    double *rgb;                /* linear radiosity, row-major from the top:
                                   pixel (x, y) band b at rgb[3*(y*width + x) + b];
                                   0 for the background */
    double *depth;              /* camera-space depth, INFINITY for background */
    int *face;                  /* face drawn at each pixel, -1 for background */
    unsigned char *edge;        /* 1 where an element edge is drawn */
    double exposure;            /* the multiplier used by the tone mapping */
    int edges;                  /* whether edge[] is drawn */
} rad_image;

/* 512 x 512, smooth, no edges, automatic exposure from the reflectors, no
 * camera. */
RAD_API void rad_render_options_init(rad_render_options *opt);

/* The model of a solved mesh: its faces are the elements, its vertices the
 * mesh's shared vertices.  B is nelements x RAD_BANDS and Bv nvertices x
 * RAD_BANDS, both column-major; Bv may be NULL (flat shading only). */
RAD_API rad_status rad_render_model_from_mesh(rad_render_model *model, const rad_mesh *mesh,
                                      const double *B, const double *Bv, rad_error *err);
RAD_API void rad_render_model_free(rad_render_model *model);

/* The largest element radiosity over all faces and bands (0 if none). */
RAD_API double rad_render_max_radiosity(const rad_render_model *model);

/* The automatic exposure of the model (see rad_render_options): 1 / the
 * largest radiosity counted, or 1 when that is 0. */
RAD_API double rad_render_auto_exposure(const rad_render_model *model, rad_exposure_from from);

/* The same from a solved mesh and its element radiosity B (nelements x
 * RAD_BANDS, column-major): an element emits when its E > 0 in a band. */
RAD_API double rad_mesh_auto_exposure(const rad_mesh *mesh, const double *B,
                                      rad_exposure_from from);

/* "reflectors" or "all" to *from: 0, or -1 for another name. */
RAD_API int rad_exposure_from_parse(const char *name, rad_exposure_from *from);

/* Is the camera usable: fov in (0, 180), eye != at, up not parallel to the
 * view direction, all finite? */
RAD_API rad_status rad_camera_check(const rad_camera *camera, rad_error *err);

/* Render the model.  On success the caller owns img (rad_image_free). */
RAD_API rad_status rad_render(const rad_render_model *model, const rad_render_options *opt,
                      rad_image *img, rad_error *err);
RAD_API void rad_image_free(rad_image *img);

/* The linear values of image row y (0 = top): 3 * width doubles, pixel x
 * band b at [3*x + b]; NULL if y is outside the image. */
RAD_API const double *rad_image_row(const rad_image *img, int y);

/* The sRGB transfer curve (IEC 61966-2-1:1999, section 5.2) from linear
 * [0, 1] to encoded [0, 1]; values outside [0, 1] are clamped first. */
RAD_API double rad_srgb_encode(double linear);
/* Its inverse, encoded [0, 1] to linear [0, 1]. */
RAD_API double rad_srgb_decode(double encoded);
/* One 8-bit channel: round(255 * srgb(clamp(exposure * radiosity))). */
RAD_API unsigned char rad_tone_byte(double radiosity, double exposure);

/* The tone-mapped picture as 8-bit R G B triples, row-major from the top
 * (3 * width * height bytes), with the edges in black when img->edges. */
RAD_API void rad_image_to_rgb8(const rad_image *img, unsigned char *rgb);

/* Write the tone-mapped picture to out as a PNG (through cairo). */
RAD_API rad_status rad_image_write_png(const rad_image *img, FILE *out, rad_error *err);

#ifdef __cplusplus
}
#endif

#endif /* RAD_RENDER_H */
