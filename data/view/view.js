/* view.js -- the browser side of `radiosity view`: draws the scene with
 * WebGL as `radiosity render` would, and follows the solver's state.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * The picture copies the rules of src/render/render.c (its camera, culling,
 * z-buffer, smooth shading and tone mapping) so that a still at the scene's
 * camera matches `radiosity render`'s PNG within 8-bit rounding:
 *
 *   - camera: fwd = unit(at - eye), right = unit(fwd x up), up' = right x fwd;
 *     f = (height/2) / tan(fov/2); the image point of camera-space (x, y, z)
 *     is (cx + f x/z, cy - f y/z), y down from the top, pixel centres at
 *     (i + 0.5, j + 0.5) (render.c make_view, face_setup);
 *   - one-sided faces: counter-clockwise seen from the front, back faces
 *     culled; the nearest face wins, ties keep the face drawn first (faces
 *     go in model order, depth test LESS); black background;
 *   - smooth shading, per pixel: the ray through the pixel centre
 *     (gl_FragCoord) meets the face's plane, and the point is located in
 *     the face's plane frame (render.c draw_face, shade).  A quad element
 *     is bilinear in its own (u, v), found by inverting the bilinear map
 *     (render.c inverse_bilinear); other polygons are a fan of triangles
 *     from vertex 0, barycentric (render.c fan_weights).  The GPU's own
 *     interpolation would shift the shading by a fraction of a pixel (its
 *     vertices snap to a sub-pixel grid), and its coverage rule differs
 *     from render.c's (pixel centres on an edge are drawn by both faces);
 *     so each triangle is drawn 1/8 pixel larger, and a pixel is kept when
 *     its centre lies in the face (within PIXEL_TOLERANCE): no cracks at
 *     T-junctions, and the silhouettes of render.c;
 *   - element edges (the outlines): pixels whose centre lies within 0.55
 *     pixel of an edge line of the face drawn there, black (render.c
 *     EDGE_HALF_WIDTH, near_edge);
 *   - emitters are drawn like every face (face_emits only chooses the
 *     automatic exposure, which the server sends);
 *   - tone: byte = floor(255 srgb(exposure B) + 0.5), per pixel, from the
 *     interpolated linear radiosity (render.c rad_tone_byte; the curve of
 *     IEC 61966-2-1:1999 eq. (5.2), rad_srgb_encode).
 *
 * Coordinates go to the GPU relative to the centre C of the scene's
 * bounding box, so that a scene far from its origin keeps its precision.
 *
 * Live: the scene is fetched once (/api/scene) and again whenever the
 * state's `geometry` says it changed; states stream from /api/events
 * (EventSource) and only the colour buffer changes with them; the panel
 * sends POST /api/control (run, pause, step, reset, rate, undo, stop) and
 * POST /api/change (change-file lines, radiosity-scene(5)), and shows a
 * refusal's {"error"} reason.
 *
 * ?still=1: no panel, no event stream; fetch the scene and the state once,
 * draw, then set the title to "ready" and add an element id="ready".
 *
 * Teaching views (live page only; the single picture above is untouched):
 *   - the race (method "race"): the four lanes of state.race drawn side by
 *     side, 2 x 2 viewports of one context on one geometry upload, each
 *     with its own colour buffer, the same camera at half the size, and
 *     labelled; the error plot draws one curve per lane;
 *   - what an element sees ("click an element"): a click casts the pixel's
 *     ray against the faces (render.c pixel_ray, nearest front face), GET
 *     /api/row?element=I gives row I of F, and every element is drawn in
 *     one colour of a log-scale viridis ramp of F_Ij; the flat colours go
 *     through the same face program as the picture (corner "radiosity"
 *     that tone() maps back to the ramp's bytes, exposure 1);
 *   - the hemicube: GET /api/hemicube's item buffers unfolded into a cross
 *     (hemicube.c one_face's cameras), each pixel in its element's colour;
 *   - a material editor: `material NAME reflect R G B emit R G B` lines
 *     through POST /api/change.
 */
'use strict';

(function () {

const STILL = new URLSearchParams(location.search).get('still') === '1';
if (STILL)
    document.documentElement.classList.add('still');

const $ = (id) => document.getElementById(id);
const canvas = $('scene');

/* ---- small vector helpers (arrays [x, y, z]) ---------------------------- */

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                         a[0] * b[1] - a[1] * b[0]];
const norm = (a) => Math.sqrt(dot(a, a));
const unit = (a) => scale(a, 1 / norm(a));
const clamp = (x, lo, hi) => Math.min(hi, Math.max(lo, x));

/* ---- the shaders -------------------------------------------------------- */

/* Faces: every GL vertex carries its triangle's face constants (all
 * relative to C): the unit normal n, the plane axis a1 (a2 = n x a1) and
 * vertex 0's offsets along them; the triangle's corners 1 to 3 in the
 * plane frame (corner 0 is its origin); their radiosity, 4 x (r, g, b)
 * packed in 3 vec4.  A quad element is one bilinear patch over both its
 * triangles (slots 0 1 2 3 = its corners); a fan triangle (0, i, i+1)
 * uses slots 0 1 2.  aPos.w = 8 slot + kind: the slot of this vertex;
 * the kind 4 for a quad, else the fan triangle's boundary edges besides
 * 1-2: +1 for edge 0-1, +2 for edge 2-0. */
const FACE_VS = `
attribute vec4 aPos;   // position - C; w = 8 slot + kind
attribute vec4 aNrm;   // n; w = (P0 - C).n
attribute vec4 aAx1;   // a1; w = (P0 - C).a1
attribute vec4 aQa;    // corners 1 and 2 in the plane frame
attribute vec4 aQb;    // corner 3; z = (P0 - C).a2
attribute vec4 aCa, aCb, aCc;   // linear radiosity of the 4 corners
uniform mat4 uMVP;
uniform vec2 uViewHalf;    // half the viewport, pixels
varying vec4 vNrm, vAx1, vQa, vQb, vCa, vCb, vCc;
varying float vGrown;      // 1: this corner and its neighbours lie before the eye: moved out

/* Pixels each edge moves out: more than the rasteriser's snapping of
 * vertices (1/16 pixel and less); the fragment shader cuts the face. */
const float GROW = 0.125;

vec2 corner(float k) {
    return k < 0.5 ? vec2(0.0) : k < 1.5 ? aQa.xy : k < 2.5 ? aQa.zw : aQb.xy;
}

/* Window position (pixels from the centre, y up) of a plane-frame point. */
vec4 project(vec2 q) {
    vec3 a2 = cross(aNrm.xyz, aAx1.xyz);
    vec3 p0 = aNrm.xyz * aNrm.w + aAx1.xyz * aAx1.w + a2 * aQb.z;
    vec4 c = uMVP * vec4(p0 + aAx1.xyz * q.x + a2 * q.y, 1.0);
    return vec4(c.xy / c.w * uViewHalf, c.w, 0.0);
}

/* The offset that moves both edges at corner s (between p and n) out by
 * GROW, the polygon counter-clockwise on the screen: a mitre, at most
 * GROW sqrt(2/1e-3) = 5.6 pixels long at the sharpest corners of faces
 * seen edge-on (what it adds outside the face is cut anyway). */
vec2 grow(vec2 p, vec2 s, vec2 n) {
    vec2 e1 = s - p, e2 = n - s;
    if (!(dot(e1, e1) > 0.0 && dot(e2, e2) > 0.0))
        return vec2(0.0);
    vec2 n1 = normalize(vec2(e1.y, -e1.x)), n2 = normalize(vec2(e2.y, -e2.x));
    return GROW * (n1 + n2) / max(1.0 + dot(n1, n2), 1e-3);
}

void main() {
    float slot = floor(aPos.w / 8.0), kind = aPos.w - 8.0 * slot;
    float m = kind > 3.5 ? 4.0 : 3.0;
    vec4 s = project(corner(slot));
    vec4 p = project(corner(mod(slot + m - 1.0, m))), n = project(corner(mod(slot + 1.0, m)));
    vec4 pos = uMVP * vec4(aPos.xyz, 1.0);
    vGrown = s.z > 0.0 && p.z > 0.0 && n.z > 0.0 ? 1.0 : 0.0;
    if (vGrown > 0.5)
        pos.xy += grow(p.xy, s.xy, n.xy) / uViewHalf * pos.w;
    gl_Position = pos;
    vNrm = aNrm;
    vAx1 = aAx1;
    vQa = aQa;
    vQb = vec4(aQb.xyz, kind);
    vCa = aCa;
    vCb = aCb;
    vCc = aCc;
}`;

const FACE_FS = `
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
#else
precision mediump float;
#endif
uniform float uExposure;
uniform vec3 uEye, uFwd, uRight, uUp;   // eye - C; render.c's camera frame
uniform vec2 uHalf;                     // the image centre (cx, cy), pixels
uniform float uF;                       // focal length, pixels
uniform float uEdges;                   // 1: draw the element edges
varying vec4 vNrm, vAx1, vQa, vQb, vCa, vCb, vCc;
varying float vGrown;

const float PIXEL_TOLERANCE = 1e-3;     // pixels: coverage, beyond rounding
const float EDGE_HALF_WIDTH = 0.55;     // pixels: render.c's edge lines

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

/* The point of the face's plane under the pixel centre, in the plane
 * frame: the ray fwd + right (x - cx)/f + up (cy - y_top)/f meets the
 * plane at depth t = n.(P0 - eye) / n.ray (render.c pixel_ray, draw_face);
 * gl_FragCoord.y counts from the bottom, so cy - y_top = y - cy.  Also
 * its derivatives along the screen's x and y (J[0], J[1]), which turn
 * plane distances into pixels. */
vec2 planePoint(out mat2 J) {
    vec3 dx = uRight / uF, dy = uUp / uF;
    vec3 r = uFwd + dx * (gl_FragCoord.x - uHalf.x) + dy * (gl_FragCoord.y - uHalf.y);
    vec3 n = vNrm.xyz, a1 = vAx1.xyz, a2 = cross(n, a1);
    float nr = dot(n, r), t = (vNrm.w - dot(uEye, n)) / nr;
    float tx = -t * dot(n, dx) / nr, ty = -t * dot(n, dy) / nr;
    vec2 ra = vec2(dot(r, a1), dot(r, a2));
    J[0] = tx * ra + t * vec2(dot(dx, a1), dot(dx, a2));
    J[1] = ty * ra + t * vec2(dot(dy, a1), dot(dy, a2));
    return vec2(t * ra.x - (vAx1.w - dot(uEye, a1)), t * ra.y - (vQb.z - dot(uEye, a2)));
}

/* Signed distance in pixels from the pixel centre to the screen line of
 * the edge a -> b, positive inside (the face is counter-clockwise in its
 * plane frame); the plane distance over its screen gradient. */
float edgePixels(vec2 p, mat2 J, vec2 a, vec2 b) {
    vec2 d = b - a;
    float len = length(d);
    if (!(len > 0.0))
        return 1e9;
    vec2 m = vec2(-d.y, d.x) / len;
    float g = length(vec2(dot(J[0], m), dot(J[1], m)));
    return g > 0.0 ? dot(p - a, m) / g : 1e9;
}

/* The smallest signed pixel distance to the face's boundary edges that
 * this triangle knows: a quad's four; a fan triangle's edge 1-2 and
 * those of 0-1 and 2-0 that bound the polygon (the kind's flags). */
float boundaryPixels(vec2 p, mat2 J, float kind) {
    vec2 q0 = vec2(0.0), q1 = vQa.xy, q2 = vQa.zw, q3 = vQb.xy;
    float e = edgePixels(p, J, q1, q2);
    if (kind > 3.5)
        return min(min(e, edgePixels(p, J, q0, q1)),
                   min(edgePixels(p, J, q2, q3), edgePixels(p, J, q3, q0)));
    if (mod(kind, 2.0) > 0.5)
        e = min(e, edgePixels(p, J, q0, q1));
    if (kind > 1.5)
        e = min(e, edgePixels(p, J, q2, q0));
    return e;
}

/* how far r lies outside [0, 1] */
float outside01(float r) { return r < 0.0 ? -r : (r > 1.0 ? r - 1.0 : 0.0); }

/* (u, v) of p in the quad P(u,v) = (1-u)(1-v) 0 + u(1-v) q1 + uv q2 + (1-u)v q3:
 * the rule of render.c inverse_bilinear.  p = u e + v f + uv g; crossing
 * with (e + v g) leaves k2 v^2 + k1 v + k0 = 0, solved in the
 * cancellation-free form of Numerical Recipes (2nd ed., sec. 5.6); the root
 * nearer [0, 1] is kept, then u by projection on e + v g. */
vec2 inverseBilinear(vec2 p, vec2 q1, vec2 q2, vec2 q3) {
    vec2 e = q1, f = q3, g = q2 - q1 - q3;
    float k2 = cross2(g, f);
    float k1 = cross2(e, f) + cross2(p, g);
    float k0 = cross2(p, e);
    float v;
    if (k2 == 0.0) {
        v = k1 != 0.0 ? -k0 / k1 : 0.0;
    } else {
        float s = sqrt(max(k1 * k1 - 4.0 * k0 * k2, 0.0));
        float q = -0.5 * (k1 + (k1 >= 0.0 ? s : -s));
        float r1 = q / k2;
        float r2 = q != 0.0 ? k0 / q : r1;
        v = outside01(r2) <= outside01(r1) ? r2 : r1;
    }
    v = clamp(v, 0.0, 1.0);
    vec2 d = e + v * g, n = p - v * f;
    float dd = dot(d, d);
    float u = clamp(dd > 0.0 ? dot(n, d) / dd : 0.0, 0.0, 1.0);
    return vec2(u, v);
}

/* Barycentric weights of p in the triangle (0, a, b), negative ones
 * clamped to 0 and the rest renormalised (render.c fan_weights). */
vec3 fanWeights(vec2 p, vec2 a, vec2 b) {
    float d = cross2(a, b);
    float wi = d != 0.0 ? cross2(p, b) / d : 0.0;
    float wj = d != 0.0 ? cross2(a, p) / d : 0.0;
    vec3 w = max(vec3(1.0 - wi - wj, wi, wj), 0.0);
    float s = w.x + w.y + w.z;
    return s > 0.0 ? w / s : vec3(1.0, 0.0, 0.0);
}

/* IEC 61966-2-1:1999 eq. (5.2), as render.c rad_srgb_encode */
float srgbEncode(float c) {
    if (!(c > 0.0)) return 0.0;
    if (c >= 1.0) return 1.0;
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

/* render.c rad_tone_byte: floor(255 s + 0.5), as a fraction of 255 */
float tone(float b) {
    return floor(255.0 * srgbEncode(b * uExposure) + 0.5) / 255.0;
}

void main() {
    vec3 c0 = vCa.xyz, c1 = vec3(vCa.w, vCb.xy), c2 = vec3(vCb.zw, vCc.x), c3 = vCc.yzw;
    mat2 J;
    vec2 p = planePoint(J);
    float kind = vQb.w, inside = boundaryPixels(p, J, kind);
    /* outside the face: render.c's coverage; a triangle crossing the
     * near plane is not grown, and keeps the GPU's coverage */
    if (inside < -PIXEL_TOLERANCE && vGrown > 0.9999)
        discard;
    if (uEdges > 0.5 && abs(inside) < EDGE_HALF_WIDTH) {
        gl_FragColor = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec3 b;
    if (kind > 3.5) {
        vec2 uv = inverseBilinear(p, vQa.xy, vQa.zw, vQb.xy);
        float u = uv.x, v = uv.y;
        b = (1.0 - u) * (1.0 - v) * c0 + u * (1.0 - v) * c1 + u * v * c2 + (1.0 - u) * v * c3;
    } else {
        vec3 w = fanWeights(p, vQa.xy, vQa.zw);
        b = w.x * c0 + w.y * c1 + w.z * c2;
    }
    gl_FragColor = vec4(tone(b.r), tone(b.g), tone(b.b), 1.0);
}`;

/* Lines: the shooter's outline; uShift moves the line
 * by a fraction of the viewport (NDC) to draw it thicker. */
const LINE_VS = `
attribute vec3 aPos;
uniform mat4 uMVP;
uniform vec2 uShift;
void main() {
    vec4 p = uMVP * vec4(aPos, 1.0);
    p.xy += uShift * p.w;
    gl_Position = p;
}`;

const LINE_FS = `
precision mediump float;
uniform vec4 uColour;
void main() { gl_FragColor = uColour; }`;

/* 8 attributes: the least WebGL 1 promises */
const FACE_ATTRIBS = ['aPos', 'aNrm', 'aAx1', 'aQa', 'aQb', 'aCa', 'aCb', 'aCc'];
const GEOM_FLOATS = 20;       // floats per GL vertex: aPos .. aQb
const COLOUR_FLOATS = 12;     // 4 corners x (r, g, b)
const RACE_LANES = 4;         // the race's methods (radiosity(1), THE LIVE VIEW)
const RACE_METHODS = ['gathering', 'shooting', 'sorted', 'sorted_ambient'];
const LANE_COLOURS = ['#f7a35c', '#6cf', '#c9a0ff', '#8e8'];   // plot, labels

/* ---- what the page holds ------------------------------------------------ */

const app = {
    scene: null,          // /api/scene
    geom: null,           // buildGeometry(scene)
    state: null,          // the last state drawn
    version: -Infinity,   // its version
    pending: null,        // a newer state waiting for the next frame
    gl: null, glp: null,  // the context and its programs and buffers
    orbit: { yaw: 0, pitch: 0, zoom: 1 },
    outlines: false,
    wasAdaptive: false,   // the last state drawn was the adaptive method's
    /* when the page had its script, its scene, its WebGL context and
     * programs, its first state and its first picture, in ms
     * since the navigation began (performance.now()): `make bench` reads
     * them as window.radiosityTiming */
    timing: { script: performance.now(), scene: null, gl: null, state: null, picture: null },
    showShooter: false,
    frameQueued: false,
    busy: false,          // a request is on its way
    geometry: undefined,  // the state's count of scene changes the scene answers
    reloading: false,     // the scene is being fetched again
    misfit: undefined,    // a geometry whose states did not fit the scene fetched
    events: null,         // the EventSource
    race: null,           // the race's lanes drawn side by side (state.race), or null
    pick: false,          // "click an element": a click picks, the heat map shows
    heat: null,           // the heat map: { element, row, sum, lo, hi, rgb }
    refusal: '',          // the reason of the last refusal
};
window.radiosityTiming = app.timing;

/* ---- the camera (render.c make_view) ------------------------------------ */

/* The camera of the picture: the scene's own, or orbited around `at`
 * (yaw about the scene's up, pitch towards it, zoom along the view line).
 * At the default view the scene's camera is returned untouched. */
function currentCamera() {
    const c = app.scene.camera, o = app.orbit;
    if (o.yaw === 0 && o.pitch === 0 && o.zoom === 1)
        return c;
    const up = unit(c.up), off = sub(c.eye, c.at), dist = norm(off);
    const h0 = unit(sub(off, scale(up, dot(off, up))));
    const side = cross(up, h0);
    const h = add(scale(h0, Math.cos(o.yaw)), scale(side, Math.sin(o.yaw)));
    const el = elevation(c) + o.pitch;
    const dir = add(scale(h, Math.cos(el)), scale(up, Math.sin(el)));
    return { eye: add(c.at, scale(dir, dist * o.zoom)), at: c.at, up: c.up, fov: c.fov };
}

/* The angle of the scene camera's eye above the plane normal to up, at `at`. */
function elevation(c) {
    const off = sub(c.eye, c.at);
    return Math.asin(clamp(dot(off, unit(c.up)) / norm(off), -1, 1));
}

/* The camera frame of render.c make_view: fwd, right = fwd x up, up' =
 * right x fwd; f = (height/2) / tan(fov/2) in pixels; the eye relative
 * to the scene's centre C. */
function cameraFrame(c, width, height) {
    const fwd = unit(sub(c.at, c.eye));
    const right = unit(cross(fwd, c.up));
    const up = cross(right, fwd);
    const f = 0.5 * height / Math.tan(0.5 * c.fov * Math.PI / 180);
    return { eye: sub(c.eye, app.geom.centre), fwd, right, up, f, width, height };
}

/* Near and far planes for the depth buffer: the scene's bounding box seen
 * from the eye.  render.c clips at 1e-6 of the scene's size and keeps
 * exact depths; a 24-bit z-buffer needs the near plane as far out as
 * nothing visible is cut: half the box's distance times the cosine of
 * the widest ray of the picture, and never below 1e-3 of the far plane. */
function depthRange(v) {
    const lo = sub(app.geom.lo, app.geom.centre), hi = sub(app.geom.hi, app.geom.centre);
    let far = 0;
    for (let k = 0; k < 8; k++) {
        const p = [k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]];
        far = Math.max(far, dot(sub(p, v.eye), v.fwd));
    }
    const out = [0, 1, 2].map((i) => Math.max(lo[i] - v.eye[i], 0, v.eye[i] - hi[i]));
    const cosWidest = v.f / Math.hypot(v.f, v.width / 2, v.height / 2);
    far = far > 0 ? far * 1.01 : 1;
    const near = Math.max(0.5 * norm(out) * cosWidest, 1e-3 * far);
    return { near, far: Math.max(far, 2 * near) };
}

/* Column-major clip matrix: clip x = (2f/W) x_c, clip y = (2f/H) y_c,
 * clip w = z_c (camera space x right, y up, z forward as render.c
 * to_camera), so x_s = W/2 + f x/z and y_s (from the top) = H/2 - f y/z. */
function clipMatrix(v) {
    const { near, far } = depthRange(v);
    const a = (far + near) / (far - near), b = -2 * far * near / (far - near);
    const row = (d, s) => [d[0] * s, d[1] * s, d[2] * s, -dot(d, v.eye) * s];
    const r0 = row(v.right, 2 * v.f / v.width), r1 = row(v.up, 2 * v.f / v.height);
    const r3 = row(v.fwd, 1), r2 = r3.map((x) => a * x);
    r2[3] += b;
    const m = new Float32Array(16);
    [r0, r1, r2, r3].forEach((r, i) => r.forEach((x, j) => { m[4 * j + i] = x; }));
    return m;
}

/* ---- geometry, uploaded once -------------------------------------------- */

/* The vertex positions of a face, relative to the centre C. */
function facePoints(face) {
    const V = app.scene.vertices, C = app.geom.centre;
    return face.map((i) => [V[3 * i] - C[0], V[3 * i + 1] - C[1], V[3 * i + 2] - C[2]]);
}

/* render.c's plane frame of a face: origin at vertex 0, a1 along edge 0-1,
 * a2 = n x a1 with n the unit Newell normal (the sum of the fan's cross
 * products, util/vec.h v3_newell); q: the vertices in that frame.  Null
 * for a face with no area (render.c does not draw it). */
function planeFrame(P) {
    let n = [0, 0, 0];
    for (let k = 1; k + 1 < P.length; k++)
        n = add(n, cross(sub(P[k], P[0]), sub(P[k + 1], P[0])));
    const nn = norm(n), e = sub(P[1], P[0]);
    if (!(nn > 0) || !(norm(e) > 0))
        return null;
    n = scale(n, 1 / nn);
    const a1 = unit(e), a2 = cross(n, a1);
    const q = P.map((p) => [dot(sub(p, P[0]), a1), dot(sub(p, P[0]), a2)]);
    return { n, a1, a2, q, o: [dot(P[0], n), dot(P[0], a1), dot(P[0], a2)] };
}

/* Is element e in the scene (an absent object's elements are not drawn)? */
function present(scene, e) {
    return !Array.isArray(scene.present) || scene.present[e] !== 0;
}

/* Every face as a fan of triangles from vertex 0, in model order (the
 * z-buffer's tie rule).  corner[4 j + k] is the mesh vertex whose
 * radiosity goes into colour slot k of GL vertex j (-1: none). */
function buildGeometry(scene) {
    let count = 0;
    scene.faces.forEach((f, e) => {
        count += f.length >= 3 && present(scene, e) ? 3 * (f.length - 2) : 0;
    });
    const g = {
        data: new Float32Array(GEOM_FLOATS * count),
        corner: new Int32Array(4 * count).fill(-1),
        element: new Int32Array(count),    // the element of each GL vertex
        frames: null,                      // pickFrames(): the faces' plane frames
        count: 0,
    };
    app.geom = g;
    boundingBox(g, scene.vertices);
    scene.faces.forEach((face, e) => {
        if (present(scene, e))
            addFace(g, face, e);
    });
    g.colours = new Float32Array(COLOUR_FLOATS * g.count);
    return g;
}

/* The triangles of one face, each vertex with its face constants. */
function addFace(g, face, e) {
    const n = face.length, P = n >= 3 ? facePoints(face) : null, fr = P && planeFrame(P);
    if (!fr)
        return;
    const quad = n === 4, q = fr.q;
    for (let i = 1; i + 1 < n; i++) {
        const slots = quad ? [0, 1, 2, 3] : [0, i, i + 1];
        const qa = [...q[slots[1]], ...q[slots[2]]], qb = quad ? q[3] : [0, 0];
        const kind = quad ? 4 : (i === 1 ? 1 : 0) + (i + 2 === n ? 2 : 0);
        for (const k of [0, i, i + 1]) {
            const j = g.count++, slot = quad ? k : k === 0 ? 0 : k - i + 1;
            g.element[j] = e;
            g.data.set([...P[k], 8 * slot + kind, ...fr.n, fr.o[0], ...fr.a1, fr.o[1],
                        ...qa, ...qb, fr.o[2], 0], GEOM_FLOATS * j);
            slots.forEach((s, m) => { g.corner[4 * j + m] = face[s]; });
        }
    }
}

/* The bounding box of the vertices and its centre C. */
function boundingBox(g, V) {
    g.lo = [Infinity, Infinity, Infinity];
    g.hi = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < V.length; i++) {
        g.lo[i % 3] = Math.min(g.lo[i % 3], V[i]);
        g.hi[i % 3] = Math.max(g.hi[i % 3], V[i]);
    }
    if (!(V.length > 0)) {
        g.lo = [-1, -1, -1];
        g.hi = [1, 1, 1];
    }
    g.centre = scale(add(g.lo, g.hi), 0.5);
}

/* The colour slots of every GL vertex from the vertex radiosity (r, g, b
 * interleaved); a missing or null value counts as 0. */
function fillColours(g, vb) {
    const c = g.colours, corner = g.corner;
    for (let s = 0; s < 4 * g.count; s++) {
        const i = corner[s], o = 3 * s;
        if (i >= 0 && 3 * i + 2 < vb.length) {
            c[o] = vb[3 * i];
            c[o + 1] = vb[3 * i + 1];
            c[o + 2] = vb[3 * i + 2];
        } else {
            c[o] = c[o + 1] = c[o + 2] = 0;
        }
    }
}

/* ---- WebGL -------------------------------------------------------------- */

function compile(gl, vs, fs, attribs) {
    const prog = gl.createProgram();
    for (const [type, src] of [[gl.VERTEX_SHADER, vs], [gl.FRAGMENT_SHADER, fs]]) {
        const sh = gl.createShader(type);
        gl.shaderSource(sh, src);
        gl.compileShader(sh);
        if (!gl.getShaderParameter(sh, gl.COMPILE_STATUS) && !gl.isContextLost())
            throw new Error('shader: ' + gl.getShaderInfoLog(sh));
        gl.attachShader(prog, sh);
    }
    attribs.forEach((name, i) => gl.bindAttribLocation(prog, i, name));
    gl.linkProgram(prog);
    if (!gl.getProgramParameter(prog, gl.LINK_STATUS) && !gl.isContextLost())
        throw new Error('program: ' + gl.getProgramInfoLog(prog));
    const u = (name) => gl.getUniformLocation(prog, name);
    return { prog, u };
}

/* Programs and buffers; the geometry goes up once, the colours on every
 * state: a colour buffer and a shooter outline for each lane of the race
 * (lane 0: the single picture's), one for the heat map's flat colours and
 * the clicked element's outline.  Returns false when the browser has no
 * WebGL. */
function initGL() {
    const opts = { antialias: false, alpha: false, depth: true,
                   preserveDrawingBuffer: true, premultipliedAlpha: false };
    const gl = canvas.getContext('webgl', opts) || canvas.getContext('experimental-webgl', opts);
    if (!gl)
        return false;
    if (gl.getParameter(gl.MAX_VERTEX_ATTRIBS) < FACE_ATTRIBS.length)
        throw new Error('too few vertex attributes');
    app.gl = gl;
    const slot = () => ({ colours: gl.createBuffer(), size: 0, lines: gl.createBuffer(), count: 0 });
    app.glp = {
        face: compile(gl, FACE_VS, FACE_FS, FACE_ATTRIBS),
        line: compile(gl, LINE_VS, LINE_FS, ['aPos']),
        geom: gl.createBuffer(),
        lanes: Array.from({ length: RACE_LANES }, slot),
        heat: slot(),
    };
    uploadGeometry();
    return true;
}

/* The geometry of app.geom, and room for lane 0's colours (the other
 * buffers get theirs when first filled). */
function uploadGeometry() {
    const gl = app.gl, p = app.glp, g = app.geom;
    if (!gl || gl.isContextLost())
        return;
    gl.bindBuffer(gl.ARRAY_BUFFER, p.geom);
    gl.bufferData(gl.ARRAY_BUFFER, g.data, gl.STATIC_DRAW);
    for (const b of [...p.lanes, p.heat]) {
        b.size = 0;
        b.count = 0;
    }
    putColours(p.lanes[0], g.colours);
}

/* Colours into a slot's buffer: resized when the geometry changed. */
function putColours(slot, data) {
    const gl = app.gl;
    gl.bindBuffer(gl.ARRAY_BUFFER, slot.colours);
    if (slot.size !== data.length) {
        gl.bufferData(gl.ARRAY_BUFFER, data, gl.DYNAMIC_DRAW);
        slot.size = data.length;
    } else {
        gl.bufferSubData(gl.ARRAY_BUFFER, 0, data);
    }
}

/* The outline of element e (or none for -1) into a slot's line buffer. */
function putOutline(slot, e) {
    const gl = app.gl, f = elementFace(e);
    const pts = f ? facePoints(f) : [];
    const seg = new Float32Array(6 * pts.length);
    pts.forEach((q, k) => {
        seg.set(q, 6 * k);
        seg.set(pts[(k + 1) % pts.length], 6 * k + 3);
    });
    gl.bindBuffer(gl.ARRAY_BUFFER, slot.lines);
    gl.bufferData(gl.ARRAY_BUFFER, seg, gl.DYNAMIC_DRAW);
    slot.count = 2 * pts.length;
}

function attrib(gl, loc, buf, size, stride, offset) {
    gl.bindBuffer(gl.ARRAY_BUFFER, buf);
    gl.enableVertexAttribArray(loc);
    gl.vertexAttribPointer(loc, size, gl.FLOAT, false, stride, offset);
}

/* The viewports of the picture, in device pixels, y up as GL counts: the
 * whole canvas, or in the race (outside the heat map) the 2 x 2 grid,
 * lane k at column k % 2 and row k / 2 from the top. */
function views() {
    const W = canvas.width, H = canvas.height;
    if (!app.race || heatShown())
        return [{ x: 0, y: 0, w: W, h: H, lane: 0 }];
    const w = Math.floor(W / 2), h = Math.floor(H / 2);
    return app.race.map((l, k) => ({ x: k % 2 ? W - w : 0, y: k < 2 ? H - h : 0, w, h, lane: k }));
}

/* Draw the picture with the current camera, state and overlays. */
function draw() {
    const gl = app.gl, p = app.glp;
    if (!gl || gl.isContextLost() || !app.state)
        return;
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(0, 0, 0, 1);         // render.c: background radiosity 0
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.depthFunc(gl.LESS);             // strictly nearer wins, ties keep the first
    gl.enable(gl.CULL_FACE);           // one-sided faces, CCW = front
    gl.frontFace(gl.CCW);
    gl.cullFace(gl.BACK);
    const list = views();
    for (const vw of list) {
        if (list.length > 1) {         // the race: nothing spills into a neighbour
            gl.enable(gl.SCISSOR_TEST);
            gl.scissor(vw.x, vw.y, vw.w, vw.h);
        }
        drawView(gl, p, vw);
    }
    gl.disable(gl.SCISSOR_TEST);
    if (app.timing.picture === null)
        app.timing.picture = performance.now();
}

/* One viewport: the camera of the picture at the viewport's size (f
 * scales with its height), its lane's colours or the heat map's. */
function drawView(gl, p, vw) {
    const v = cameraFrame(currentCamera(), vw.w, vw.h);
    v.ox = vw.x;
    v.oy = vw.y;
    const mvp = clipMatrix(v), heat = heatShown(), lane = p.lanes[vw.lane];
    gl.viewport(vw.x, vw.y, vw.w, vw.h);
    gl.enable(gl.DEPTH_TEST);
    if (heat)
        drawFaces(gl, p, v, mvp, p.heat.colours, 1);
    else
        drawFaces(gl, p, v, mvp, lane.colours, app.scene.exposure);
    for (let i = 1; i < FACE_ATTRIBS.length; i++) /* the lines use aPos alone */
        gl.disableVertexAttribArray(i);
    if (app.showShooter && lane.count > 0)
        drawLines(gl, p, mvp, v, lane.lines, lane.count, [1, 0.1, 1, 1]);
    if (heat && p.heat.count > 0)
        drawLines(gl, p, mvp, v, p.heat.lines, p.heat.count, [1, 1, 1, 1]);
}

/* The faces in one viewport; uHalf, the image centre, is in window
 * pixels (gl_FragCoord's), the viewport's offset added. */
function drawFaces(gl, p, v, mvp, colours, exposure) {
    const u = p.face.u;
    gl.useProgram(p.face.prog);
    gl.uniformMatrix4fv(u('uMVP'), false, mvp);
    gl.uniform1f(u('uExposure'), exposure);
    gl.uniform3fv(u('uEye'), v.eye);
    gl.uniform3fv(u('uFwd'), v.fwd);
    gl.uniform3fv(u('uRight'), v.right);
    gl.uniform3fv(u('uUp'), v.up);
    gl.uniform2f(u('uHalf'), v.ox + 0.5 * v.width, v.oy + 0.5 * v.height);
    gl.uniform2f(u('uViewHalf'), 0.5 * v.width, 0.5 * v.height);
    gl.uniform1f(u('uF'), v.f);
    gl.uniform1f(u('uEdges'), app.outlines ? 1 : 0);
    for (let k = 0; k < 5; k++)
        attrib(gl, k, p.geom, 4, 4 * GEOM_FLOATS, 16 * k);
    for (let k = 0; k < 3; k++)
        attrib(gl, 5 + k, colours, 4, 4 * COLOUR_FLOATS, 16 * k);
    gl.drawArrays(gl.TRIANGLES, 0, app.geom.count);
}

/* An element's outline: segments in a colour, on top of everything (seen
 * through what hides it), three pixels wide (shifted copies). */
function drawLines(gl, p, mvp, v, buf, count, colour) {
    gl.useProgram(p.line.prog);
    gl.uniformMatrix4fv(p.line.u('uMVP'), false, mvp);
    gl.uniform4fv(p.line.u('uColour'), colour);
    attrib(gl, 0, buf, 3, 0, 0);
    gl.disable(gl.DEPTH_TEST);
    for (const [sx, sy] of [[0, 0], [-1, 0], [1, 0], [0, -1], [0, 1]]) {
        gl.uniform2f(p.line.u('uShift'), 2 * sx / v.width, 2 * sy / v.height);
        gl.drawArrays(gl.LINES, 0, count);
    }
}

/* The new state's radiosity into the colour buffers (lane 0's, and in
 * the race each lane's), the shooters' outlines into theirs. */
function uploadState(s) {
    const gl = app.gl, p = app.glp, g = app.geom;
    if (!gl || gl.isContextLost())
        return;
    const lanes = app.race || [{ vertex_b: s.vertex_b, shooter: s.shooter }];
    lanes.forEach((l, k) => {
        fillColours(g, Array.isArray(l.vertex_b) ? l.vertex_b : []);
        putColours(p.lanes[k], g.colours);
        putOutline(p.lanes[k], l.shooter);
    });
}

/* The vertex indices of element i, present in the scene, or null. */
function elementFace(i) {
    const faces = app.scene.faces;
    return Number.isInteger(i) && i >= 0 && i < faces.length && present(app.scene, i)
        ? faces[i] : null;
}

/* ---- the picture's canvas and its mouse ---------------------------------- */

/* width x height CSS pixels; the backing store follows devicePixelRatio
 * outside still mode (the view is the same: f scales with the height). */
function sizeCanvas() {
    const w = app.scene.width, h = app.scene.height;
    const dpr = STILL ? 1 : (window.devicePixelRatio || 1);
    canvas.style.width = w + 'px';
    canvas.style.height = h + 'px';
    canvas.width = Math.round(w * dpr);
    canvas.height = Math.round(h * dpr);
}

function requestDraw() {
    if (app.frameQueued)
        return;
    app.frameQueued = true;
    requestAnimationFrame(() => {
        app.frameQueued = false;
        if (app.pending && !app.reloading) {
            const s = app.pending;
            app.pending = null;
            applyState(s);
        }
        draw();
    });
}

/* Drag to orbit around `at`, wheel to zoom.  In "click an element" a
 * drag starts past 4 pixels, and a click picks the element there. */
function attachMouse() {
    let drag = null;
    canvas.addEventListener('pointerdown', (e) => {
        drag = { x: e.clientX, y: e.clientY, x0: e.clientX, y0: e.clientY, moved: !app.pick };
        canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener('pointermove', (e) => {
        if (!drag) {
            if (app.pick)
                hoverPicture(e);
            return;
        }
        if (!drag.moved && Math.hypot(e.clientX - drag.x0, e.clientY - drag.y0) < 4)
            return;
        drag.moved = true;
        const o = app.orbit, el0 = elevation(app.scene.camera), lim = 89 * Math.PI / 180;
        o.yaw -= 0.01 * (e.clientX - drag.x);
        o.pitch = clamp(el0 + o.pitch + 0.01 * (e.clientY - drag.y), -lim, lim) - el0;
        drag = { x: e.clientX, y: e.clientY };
        requestDraw();
    });
    canvas.addEventListener('pointerup', (e) => {
        if (drag && !drag.moved && app.pick)
            pickElement(elementAt(e.clientX, e.clientY));
        drag = null;
    });
    canvas.addEventListener('pointercancel', () => { drag = null; });
    canvas.addEventListener('wheel', (e) => {
        e.preventDefault();
        const dy = e.deltaY * (e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? 400 : 1);
        app.orbit.zoom = clamp(app.orbit.zoom * Math.exp(0.001 * dy), 0.02, 50);
        requestDraw();
    }, { passive: false });
}

function resetView() {
    app.orbit = { yaw: 0, pitch: 0, zoom: 1 };
    requestDraw();
}

/* ---- the scene and the state ------------------------------------------------ */

/* Does the state's vertex radiosity belong to this scene's mesh? */
function fits(scene, s) {
    return Array.isArray(s.vertex_b) && s.vertex_b.length === scene.vertices.length;
}

/* A scene to draw from now on; `geometry` is the state's count of scene
 * changes it answers (the scene may say so itself). */
function setScene(scene, geometry) {
    app.scene = scene;
    app.geometry = scene.geometry !== undefined ? scene.geometry : geometry;
    app.geom = buildGeometry(scene);
    app.race = null;              /* until a state of this mesh comes */
    uploadGeometry();
    if (app.heat && app.heat.row.length !== scene.elements)
        app.heat = null;
    uploadHeat();
}

/* A state from the stream or a fetch: only a newer one is drawn, at the
 * next animation frame (a burst of messages draws once). */
function receiveState(s) {
    if (!s || typeof s !== 'object' || !(s.version >= app.version))
        return;
    app.version = s.version;
    app.pending = s;
    if (app.timing.state === null)
        app.timing.state = performance.now();
    if (needsScene(s))
        reloadScene(s.geometry);
    else
        requestDraw();
}

/* Has the scene moved since it was fetched?  The state's `geometry`
 * counts the scene's changes; a mesh of another size says so too (one
 * fetch per geometry, then the picture waits for a state that fits). */
function needsScene(s) {
    if (app.reloading)
        return false;
    if (app.geometry === undefined)
        app.geometry = s.geometry;
    if (s.geometry !== undefined && s.geometry !== app.geometry)
        return true;
    return !fits(app.scene, s) && app.misfit !== s.geometry;
}

async function reloadScene(geometry) {
    app.reloading = true;
    try {
        setScene(await getJSON('api/scene'), geometry);
        showObjects();
        showMaterials();
    } catch (e) {
        app.geometry = geometry;     /* no retry loop: wait for the next change */
        showMessage('cannot load the changed scene: ' + e.message, true);
    } finally {
        app.reloading = false;
    }
    const s = app.pending;
    if (s && !fits(app.scene, s))
        app.misfit = s.geometry;
    if (s && needsScene(s))
        reloadScene(s.geometry);
    else
        requestDraw();
}

function applyState(s) {
    app.state = s;
    app.race = fits(app.scene, s) ? raceLanes(s) : null;
    if (fits(app.scene, s))
        uploadState(s);
    if (!STILL) {
        showReadouts(s);
        showRace(s);
        drawPlot(s.rms_history || [], app.race ? app.race.map((l) => l.method) : RACE_METHODS);
        updateHemicube();
    }
}

/* The race's lanes when the state is the race's and every lane's vertex
 * radiosity fits the mesh (not in still mode, not once the scene moved). */
function raceLanes(s) {
    if (STILL || s.method !== 'race' || s.mode === 'animate' || !Array.isArray(s.race))
        return null;
    const lanes = s.race.slice(0, RACE_LANES);
    const ok = lanes.length > 1 && lanes.every((l) => l && fits(app.scene, l));
    return ok ? lanes : null;
}

/* ---- the panel ------------------------------------------------------------ */

const fmt = (x, digits) => (typeof x === 'number' && isFinite(x) ? x.toPrecision(digits || 3)
                                                                   : '\u2013');
const fmtRate = (x) => (typeof x === 'number' && x >= 100 ? String(Math.round(x)) : fmt(x));

function setText(id, text) {
    const el = $(id);
    if (el.textContent !== text)
        el.textContent = text;
}

/* An input shows the server's value unless the user is editing it. */
function syncInput(el, value) {
    if (document.activeElement !== el && !app.busy && value !== undefined && value !== null)
        el.value = String(value);
}

function showReadouts(s) {
    const adaptive = s.method === 'adaptive' && s.mode !== 'animate';
    setText('state-method', (s.method || '?') + (adaptive && app.scene
        ? ' \u00b7 ' + app.scene.elements + ' elements' : ''));
    if (adaptive && !app.wasAdaptive) {   /* the mesh splitting is the point: outlines on */
        $('outlines').checked = app.outlines = true;
        requestDraw();
    }
    app.wasAdaptive = adaptive;
    setText('state-running', s.busy ? 'busy' : s.running ? 'running' : 'paused');
    setText('state-step', Number.isInteger(s.step) ? String(s.step) : '\u2013');
    setText('state-sps', fmtRate(s.shots_per_second));
    setText('state-unshot', typeof s.unshot === 'number' ? fmt(100 * s.unshot) + ' %'
                                                         : 'n/a (' + (s.method || '') + ')');
    setText('state-rms', adaptive ? '\u2013 (its converged mesh is not known yet)'
                                  : fmt(s.rms, 4));
    setText('state-shooter', describeShooter(s.shooter));
    /* once the scene has changed the race is over: the server answers 409 */
    const race = s.mode !== 'animate';
    $('run').disabled = !race || !!s.running;
    $('pause').disabled = !race || !s.running;
    for (const id of ['step', 'reset', 'method', 'steps'])
        $(id).disabled = !race;
    $('race-over').hidden = race;
    syncInput($('method'), s.method);
    syncInput($('rate'), s.rate);
    const failure = $('failure');
    failure.hidden = !s.failure;
    setText('failure', s.failure ? 'the solver stopped: ' + s.failure : '');
    showChanges(s);
}

/* "element 12 (surface 3, object tallbox)" */
function describeShooter(i) {
    const sc = app.scene;
    if (!Number.isInteger(i) || i < 0)
        return 'none';
    if (i >= sc.elements)
        return 'patch ' + i;
    const surf = sc.surface ? sc.surface[i] : undefined;
    let text = 'element ' + i + (surf !== undefined ? ' (surface ' + surf : '');
    const obj = (sc.objects || []).find((o) => (o.surfaces || []).includes(surf));
    if (obj)
        text += ', object ' + obj.name;
    return text + (surf !== undefined ? ')' : '');
}

function showMessage(text, isError) {
    const m = $('message');
    m.textContent = text || '';
    m.className = isError ? 'error' : '';
}

function setConnection(text) {
    $('connection').textContent = text;
}

/* POST a request; a refusal's reason ({"error": ...}) goes to the panel.
 * Resolves to whether the server took it. */
async function post(url, init, what) {
    app.busy = true;
    try {
        const r = await fetch(url, Object.assign({ method: 'POST' }, init));
        let body = null;
        try {
            body = await r.json();
        } catch (e) {
            body = null;
        }
        app.refusal = r.ok ? '' : (body && body.error) || 'HTTP ' + r.status;
        if (r.ok)
            showMessage('');
        else
            showMessage('the server refused ' + what + ': ' + app.refusal, true);
        return r.ok;
    } catch (e) {
        app.refusal = 'the server did not answer: ' + e.message;
        showMessage(app.refusal, true);
        return false;
    } finally {
        app.busy = false;
    }
}

/* POST /api/control with the given query parameters. */
function control(params) {
    return post('api/control?' + new URLSearchParams(params), {}, params.action);
}

function stepCount() {
    const k = parseInt($('steps').value, 10);
    return Number.isInteger(k) && k >= 1 ? k : 1;
}

function attachPanel() {
    const sel = $('method');
    for (const m of app.scene.methods || []) {
        const o = document.createElement('option');
        o.value = o.textContent = m;
        sel.appendChild(o);
    }
    sel.addEventListener('change', () => control({ action: 'reset', method: sel.value }));
    $('run').addEventListener('click', () => control({ action: 'run' }));
    $('pause').addEventListener('click', () => control({ action: 'pause' }));
    $('step').addEventListener('click', () => control({ action: 'step', steps: stepCount() }));
    $('reset').addEventListener('click', () => control({ action: 'reset', method: sel.value }));
    $('rate').addEventListener('change', setRate);
    $('outlines').addEventListener('change', (e) => { app.outlines = e.target.checked; requestDraw(); });
    $('highlight').addEventListener('change', (e) => { app.showShooter = e.target.checked; requestDraw(); });
    $('reset-view').addEventListener('click', resetView);
    $('stop').addEventListener('click', stopServer);
    app.outlines = $('outlines').checked;
    app.showShooter = $('highlight').checked;
    attachChanges();
    attachTeaching();
    const sc = app.scene;
    $('scene-info').textContent = sc.elements + ' elements, ' + sc.vertices.length / 3 +
        ' vertices, exposure ' + fmt(sc.exposure, 4);
}

/* The pace while running (0: as fast as the machine goes). */
function setRate() {
    const r = parseFloat($('rate').value);
    if (!(r >= 0)) {
        showMessage('the rate is a number of steps a second, 0 or more', true);
        return;
    }
    const running = app.state && app.state.running;
    control({ action: running ? 'run' : 'pause', rate: r });
}

async function stopServer() {
    if (!window.confirm('Stop the server?  The page will stop updating.'))
        return;
    if (await control({ action: 'stop' })) {
        if (app.events)
            app.events.close();
        setConnection('the server has stopped');
    }
}

/* ---- changes to the scene: POST /api/change (change-file lines) ------------ */

const MOVES = { 'move-xm': [-1, 0, 0], 'move-xp': [1, 0, 0], 'move-ym': [0, -1, 0],
                'move-yp': [0, 1, 0], 'move-zm': [0, 0, -1], 'move-zp': [0, 0, 1] };

function attachChanges() {
    for (const [id, d] of Object.entries(MOVES))
        $(id).addEventListener('click', () => moveObject(d));
    $('turn-l').addEventListener('click', () => turnObject(15));
    $('turn-r').addEventListener('click', () => turnObject(-15));
    $('presence').addEventListener('click', togglePresence);
    $('object').addEventListener('change', showPresence);
    $('change-apply').addEventListener('click', () => postChange($('change-text').value));
    $('undo').addEventListener('click', () => control({ action: 'undo' }));
    const g = app.geom, size = norm(sub(g.hi, g.lo));
    $('move-step').value = String(niceStep(size / 20));
    showObjects();
}

/* 1, 2 or 5 times a power of ten, near x. */
function niceStep(x) {
    if (!(x > 0) || !isFinite(x))
        return 1;
    const p = Math.pow(10, Math.floor(Math.log10(x))), m = x / p;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
}

/* A select's options: the names of `items`, the choice kept when it is
 * still one of them. */
function fillNames(sel, items) {
    const keep = sel.value;
    sel.textContent = '';
    for (const it of items) {
        const opt = document.createElement('option');
        opt.value = opt.textContent = it.name;
        sel.appendChild(opt);
    }
    if (items.some((it) => it.name === keep))
        sel.value = keep;
}

function showObjects() {
    if (STILL)
        return;
    const objs = app.scene.objects || [];
    fillNames($('object'), objs);
    $('object-tools').disabled = !objs.length;
    showPresence();
}

/* Is any element of the object's surfaces in the scene? */
function objectPresent(name) {
    const sc = app.scene, o = (sc.objects || []).find((x) => x.name === name);
    const surfs = new Set(o ? o.surfaces : []);
    return sc.faces.some((f, e) => surfs.has(sc.surface[e]) && present(sc, e));
}

function showPresence() {
    const name = $('object').value;
    $('presence').textContent = name && !objectPresent(name) ? 'Put back' : 'Take out';
}

function moveStep() {
    const d = parseFloat($('move-step').value);
    return d > 0 && isFinite(d) ? d : null;
}

function moveObject(dir) {
    const d = moveStep(), name = $('object').value;
    if (d === null)
        return showMessage('the step must be a length above 0', true);
    if (name)
        postChange(`move ${name} ${dir[0] * d} ${dir[1] * d} ${dir[2] * d}`);
}

/* Turn about the scene camera's up, through the object's centroid. */
function turnObject(degrees) {
    const up = app.scene.camera.up, name = $('object').value;
    if (name)
        postChange(`rotate ${name} ${up[0]} ${up[1]} ${up[2]} ${degrees}`);
}

function togglePresence() {
    const name = $('object').value;
    if (name)
        postChange((objectPresent(name) ? 'remove ' : 'add ') + name);
}

function postChange(text) {
    if (!text.trim())
        return Promise.resolve(false);
    return post('api/change', { headers: { 'Content-Type': 'text/plain' }, body: text },
                'the change');
}

/* The animation's progress, and whether the server takes changes at all. */
function showChanges(s) {
    const box = $('changes');
    box.hidden = typeof s.changes !== 'string';
    if (box.hidden)
        return;
    let text = 'engine ' + s.changes;
    const stage = {
        direct: ', frame ' + (s.frame + 1) + ': shooting the direct light\u2019s change',
        form_factors: ', frame ' + (s.frame + 1) + ': direct light shown, computing the '
            + 'other form factors',
        shooting: ', frame ' + (s.frame + 1) + ': redistributing and propagating'
    };
    if (s.mode === 'animate')
        text += ' \u00b7 frame ' + s.frame + ' of ' + s.frames + (s.converged ? ', converged'
            : ', ' + (s.frame_shots || 0) + ' shots') + (stage[s.frame_stage] || '');
    setText('changes-state', text);
    $('undo').disabled = !(s.undo > 0);
    const f = $('changes-failure');
    f.hidden = !s.changes_failure;
    setText('changes-failure', s.changes_failure || '');
}

/* ---- the error plot: rms against step, log axis ----------------------------- */

/* rms against step on a log axis: rms_history rows [step, rms] or, in the
 * race, [step, rms of each lane] (one curve each, named by `names`). */
function drawPlot(hist, names) {
    const c = $('plot'), ctx = c.getContext('2d');
    const dpr = window.devicePixelRatio || 1, W = c.clientWidth || 300, H = c.clientHeight || 180;
    if (c.width !== Math.round(W * dpr) || c.height !== Math.round(H * dpr)) {
        c.width = Math.round(W * dpr);
        c.height = Math.round(H * dpr);
    }
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, W, H);
    ctx.font = '11px sans-serif';
    ctx.fillStyle = '#ccc';
    const rows = hist.filter((p) => Array.isArray(p) && isFinite(p[0]));
    const curves = plotCurves(rows);
    showPlotLegend(curves, names);
    const all = [].concat(...curves);
    if (!all.length) {
        ctx.fillText('no error to plot yet', 50, H / 2);
        return;
    }
    const box = { l: 44, r: W - 8, t: 8, b: H - 22 };
    const s0 = Math.min(...all.map((p) => p[0]));
    const s1 = Math.max(Math.max(...all.map((p) => p[0])), s0 + 1);
    const logs = all.map((p) => Math.log10(p[1]));
    let d0 = Math.floor(Math.min(...logs)), d1 = Math.ceil(Math.max(...logs));
    if (d1 <= d0)
        d1 = d0 + 1;
    const X = (s) => box.l + (box.r - box.l) * (s - s0) / (s1 - s0);
    const Y = (l) => box.b - (box.b - box.t) * (l - d0) / (d1 - d0);
    plotAxes(ctx, box, d0, d1, s0, s1, Y);
    ctx.lineWidth = 1.5;
    curves.forEach((pts, k) => {
        ctx.strokeStyle = curves.length > 1 ? LANE_COLOURS[k % LANE_COLOURS.length] : '#6cf';
        ctx.beginPath();
        pts.forEach((p, i) => (i ? ctx.lineTo : ctx.moveTo).call(ctx, X(p[0]), Y(Math.log10(p[1]))));
        ctx.stroke();
    });
}

/* The points [step, rms] of each column of the rows that can go on a log
 * axis (rms > 0 and finite). */
function plotCurves(rows) {
    const columns = Math.max(2, ...rows.map((p) => p.length)) - 1;
    const curves = [];
    for (let k = 1; k <= columns; k++)
        curves.push(rows.filter((p) => p[k] > 0 && isFinite(p[k])).map((p) => [p[0], p[k]]));
    return curves;
}

/* Under the plot, in the race: each lane's colour, name and last rms. */
function showPlotLegend(curves, names) {
    const box = $('plot-legend');
    box.hidden = curves.length < 2;
    if (box.hidden)
        return;
    const text = curves.map((pts, k) => (names[k] || 'lane ' + k) + ' ' +
                            (pts.length ? fmt(pts[pts.length - 1][1]) : '\u2013')).join('|');
    if (box.dataset.text === text)
        return;
    box.dataset.text = text;
    box.textContent = '';
    text.split('|').forEach((t, k) => {
        const item = document.createElement('span');
        item.className = 'key';
        item.style.borderColor = LANE_COLOURS[k % LANE_COLOURS.length];
        item.textContent = t;
        box.appendChild(item);
    });
}

/* Decade grid lines labelled 1e-k, the step range under the axis. */
function plotAxes(ctx, box, d0, d1, s0, s1, Y) {
    const every = Math.max(1, Math.ceil((d1 - d0) / 6));
    ctx.strokeStyle = '#444';
    ctx.lineWidth = 1;
    ctx.textAlign = 'right';
    for (let d = d0; d <= d1; d += every) {
        ctx.beginPath();
        ctx.moveTo(box.l, Y(d));
        ctx.lineTo(box.r, Y(d));
        ctx.stroke();
        ctx.fillText('1e' + d, box.l - 4, Y(d) + 4);
    }
    ctx.strokeRect(box.l, box.t, box.r - box.l, box.b - box.t);
    ctx.textAlign = 'left';
    ctx.fillText('step ' + s0, box.l, box.b + 15);
    ctx.textAlign = 'right';
    ctx.fillText(String(s1), box.r, box.b + 15);
    ctx.textAlign = 'center';
    ctx.fillText('rms (log)', (box.l + box.r) / 2, box.b + 15);
}

/* ---- teaching views: common helpers ------------------------------------------ */

/* fn at most once every `ms` milliseconds, the last request never lost;
 * an async fn is not started again before it has ended. */
function throttled(fn, ms) {
    let running = false, again = false, timer = 0, last = -Infinity;
    const kick = () => {
        if (running) {
            again = true;
            return;
        }
        if (!timer)
            timer = setTimeout(run, Math.max(0, last + ms - performance.now()));
    };
    const run = async () => {
        timer = 0;
        running = true;
        again = false;
        last = performance.now();
        try {
            await fn();
        } finally {
            running = false;
            if (again)
                kick();
        }
    };
    return kick;
}

/* IEC 61966-2-1:1999 eq. (5.2), as render.c rad_srgb_encode (the shader's) */
function srgbEncode(c) {
    if (!(c > 0))
        return 0;
    if (c >= 1)
        return 1;
    return c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
}

/* its inverse, IEC 61966-2-1:1999 eq. (5.1): an sRGB byte to linear */
const SRGB_LINEAR = Float32Array.from({ length: 256 }, (_, n) => {
    const c = n / 255;
    return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
});

/* render.c rad_tone_byte: floor(255 srgb(exposure B) + 0.5) */
const toneByte = (b, exposure) => Math.floor(255 * srgbEncode(b * exposure) + 0.5);

const cssRGB = (c) => `rgb(${c[0]},${c[1]},${c[2]})`;

/* ---- the race: the four lanes side by side ------------------------------------ */

/* The labels over the 2 x 2 grid: each lane's method, step, rms (eq. 14)
 * and unshot power; hidden outside the race and under the heat map. */
function showRace(s) {
    const box = $('race-labels');
    box.hidden = !app.race || heatShown();
    if (box.hidden)
        return;
    app.race.forEach((l, k) => {
        const unshot = typeof l.unshot === 'number' ? ' \u00b7 unshot ' + fmt(100 * l.unshot) + ' %' : '';
        setText('lane-' + k, l.method + '\nstep ' + s.step + ' \u00b7 rms ' + fmt(l.rms, 3) + unshot);
    });
}

/* ---- picking: the element under a point of the picture ------------------------ */

/* Each present face's plane frame (planeFrame, relative to C) or null,
 * made at the first pick of a geometry. */
function pickFrames() {
    const g = app.geom, sc = app.scene;
    if (!g.frames)
        g.frames = sc.faces.map((f, e) => (f.length >= 3 && present(sc, e)
                                           ? planeFrame(facePoints(f)) : null));
    return g.frames;
}

/* The element drawn at a point (client coordinates) of the canvas, or -1:
 * the ray of render.c pixel_ray in the viewport there, fwd + right (x -
 * cx)/f + up (cy - y)/f, x and y from the viewport's top-left. */
function elementAt(clientX, clientY) {
    const rect = canvas.getBoundingClientRect();
    const px = (clientX - rect.left) * canvas.width / rect.width;
    const gy = canvas.height - (clientY - rect.top) * canvas.height / rect.height;
    const vw = views().find((w) => px >= w.x && px < w.x + w.w && gy >= w.y && gy < w.y + w.h);
    if (!vw)
        return -1;
    const v = cameraFrame(currentCamera(), vw.w, vw.h);
    const x = px - vw.x, y = vw.y + vw.h - gy;
    const r = add(v.fwd, add(scale(v.right, (x - vw.w / 2) / v.f),
                             scale(v.up, (vw.h / 2 - y) / v.f)));
    return castRay(v.eye, r);
}

/* The nearest front face the ray eye + t r (t > 0) meets, or -1.  The
 * plane point as the face shader finds it (planePoint: t = n.(P0 - eye) /
 * n.r), kept when inside the face's polygon in its plane frame; ties keep
 * the first face, as the picture's depth test does. */
function castRay(eye, r) {
    let best = Infinity, hit = -1;
    pickFrames().forEach((fr, e) => {
        const nr = fr ? dot(fr.n, r) : 0;
        if (!(nr < 0))                 /* none, or seen from behind: culled */
            return;
        const t = (fr.o[0] - dot(eye, fr.n)) / nr;
        if (!(t > 0 && t < best))
            return;
        const q = [t * dot(r, fr.a1) - (fr.o[1] - dot(eye, fr.a1)),
                   t * dot(r, fr.a2) - (fr.o[2] - dot(eye, fr.a2))];
        if (insidePolygon(q, fr.q)) {
            best = t;
            hit = e;
        }
    });
    return hit;
}

/* The even-odd rule: a ray from q along +x crosses the polygon's edges an
 * odd number of times (any simple polygon, either orientation). */
function insidePolygon(q, poly) {
    let inside = false;
    for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
        const [xi, yi] = poly[i], [xj, yj] = poly[j];
        if ((yi > q[1]) !== (yj > q[1]) && q[0] < xj + (q[1] - yj) * (xi - xj) / (yi - yj))
            inside = !inside;
    }
    return inside;
}

/* ---- what an element sees: row I of F as a heat map --------------------------- */

/* viridis (van der Walt & Smith, matplotlib _cm_listed.py, CC0): 17 of its
 * 256 entries, every 16th, as sRGB bytes; linear between them. */
const VIRIDIS = [0x440154, 0x48186a, 0x472d7b, 0x424086, 0x3b528b, 0x33638d, 0x2c728e,
                 0x26828e, 0x21918c, 0x1f9f88, 0x27ad81, 0x3dbc74, 0x5cc863, 0x81d34d,
                 0xaadc32, 0xd5e21a, 0xfde725];
const UNSEEN = [72, 72, 72];   // F_Ij = 0: j is not seen from I
const HEAT_DECADES = 4;        // the log scale's depth below the largest F_Ij

function viridis(t) {
    const x = clamp(t, 0, 1) * (VIRIDIS.length - 1), k = Math.min(Math.floor(x), VIRIDIS.length - 2);
    const a = VIRIDIS[k], b = VIRIDIS[k + 1], w = x - k;
    return [16, 8, 0].map((s) => Math.round(((a >> s) & 255) * (1 - w) + ((b >> s) & 255) * w));
}

function heatShown() {
    return app.pick && !!app.heat;
}

/* The scale of a row: hi = max_j F_Ij, lo = the least F_Ij > 0 but not
 * below hi 10^-HEAT_DECADES; sum = sum_j F_Ij (1 for a closed scene: the
 * form factors of a closed enclosure sum to one, Goral et al. 1984). */
function heatScale(row) {
    let hi = 0, lo = Infinity, sum = 0, seen = 0;
    for (const F of row) {
        sum += F;
        if (F > 0) {
            hi = Math.max(hi, F);
            lo = Math.min(lo, F);
            seen++;
        }
    }
    return { hi, lo: Math.max(lo, hi * Math.pow(10, -HEAT_DECADES)), sum, seen };
}

/* The ramp's colour of F: t = log(F / lo) / log(hi / lo), clamped. */
function heatRGB(F, h) {
    if (!(F > 0))
        return UNSEEN;
    return viridis(h.hi > h.lo ? Math.log(F / h.lo) / Math.log(h.hi / h.lo) : 1);
}

/* Fetch row e of F and show it; -1 (the background) leaves the map. */
async function pickElement(e) {
    if (e < 0) {
        setText('heat-note', 'nothing there: click an element of the picture');
        return;
    }
    const seq = app.pickSeq = (app.pickSeq || 0) + 1;
    setText('heat-note', 'reading row ' + e + ' of F\u2026');
    try {
        const r = await getJSON('api/row?element=' + e);
        if (seq !== app.pickSeq || !app.pick)
            return;                    /* a newer click, or the mode was left */
        if (!Array.isArray(r.row) || r.row.length !== app.scene.elements)
            throw new Error('the row does not fit the scene');
        setHeat(e, r.row);
    } catch (err) {
        setText('heat-note', 'cannot read row ' + e + ' of F: ' + err.message);
    }
}

function setHeat(e, row) {
    const h = heatScale(row);
    h.element = e;
    h.row = row;
    h.rgb = new Uint8Array(3 * row.length);
    row.forEach((F, j) => h.rgb.set(heatRGB(F, h), 3 * j));
    app.heat = h;
    uploadHeat();
    showHeat();
    if (app.state)
        showRace(app.state);
    requestDraw();
    updateHemicube();
}

/* The mode on or off; off, the picture is the radiosity's again. */
function setPickMode(on) {
    app.pick = on;
    canvas.classList.toggle('picking', on);
    if (!on)
        app.heat = null;
    uploadHeat();
    showHeat();
    if (app.state)
        showRace(app.state);
    requestDraw();
    updateHemicube();
}

/* The heat map's colours, flat over each element: every corner gets the
 * linear value whose tone (exposure 1) is the ramp's byte, so the face
 * program draws it unchanged; and the clicked element's outline. */
function uploadHeat() {
    const gl = app.gl, p = app.glp, h = app.heat, g = app.geom;
    if (!gl || gl.isContextLost() || !g)
        return;
    if (!h) {
        p.heat.count = 0;
        return;
    }
    if (!g.heat || g.heat.length !== g.colours.length)
        g.heat = new Float32Array(g.colours.length);
    for (let j = 0; j < g.count; j++) {
        const o = 3 * g.element[j];
        for (let k = 0; k < 12; k++)
            g.heat[12 * j + k] = SRGB_LINEAR[h.rgb[o + k % 3]];
    }
    putColours(p.heat, g.heat);
    putOutline(p.heat, h.element);
}

/* The panel's side of the heat map: the element, the row sum, the range
 * and its legend. */
function showHeat() {
    const h = app.heat;
    $('heat-details').hidden = !h;
    setText('heat-note', !app.pick ? '' : h ? '' : 'click an element of the picture');
    if (!h)
        return;
    setText('heat-element', describeShooter(h.element));
    setText('heat-sum', fmt(h.sum, 6));
    setText('heat-seen', h.seen + ' of ' + h.row.length);
    setText('heat-hover', '\u2013');
    $('heat-loaded').hidden = !(app.state && app.state.mode === 'animate');
    drawHeatLegend(h);
}

/* The ramp from lo to hi with its decades, and the swatch of F = 0. */
function drawHeatLegend(h) {
    const c = $('heat-legend'), ctx = c.getContext('2d');
    const dpr = window.devicePixelRatio || 1, W = c.clientWidth || 300, H = c.clientHeight || 40;
    c.width = Math.round(W * dpr);
    c.height = Math.round(H * dpr);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    const x0 = 44, x1 = W - 8, bar = { t: 4, h: 14 };
    ctx.fillStyle = cssRGB(UNSEEN);
    ctx.fillRect(0, bar.t, 30, bar.h);
    for (let x = x0; x < x1; x++) {
        ctx.fillStyle = cssRGB(viridis((x - x0 + 0.5) / (x1 - x0)));
        ctx.fillRect(x, bar.t, 1, bar.h);
    }
    ctx.font = '11px sans-serif';
    ctx.fillStyle = '#ccc';
    ctx.textAlign = 'center';
    ctx.fillText('0', 15, bar.t + bar.h + 13);
    const l0 = Math.log10(h.lo), l1 = Math.log10(h.hi), X = (l) => x0 + (x1 - x0) * (l - l0) / (l1 - l0);
    for (let d = Math.ceil(l0); l1 > l0 && d <= l1; d++) {
        ctx.fillRect(X(d) - 0.5, bar.t + bar.h, 1, 4);
        if (X(d) - x0 > 40 && x1 - X(d) > 40)
            ctx.fillText('1e' + d, X(d), bar.t + bar.h + 13);
    }
    ctx.textAlign = 'left';
    ctx.fillText('\u2264' + fmt(h.lo, 2), x0, bar.t + bar.h + 13);
    ctx.textAlign = 'right';
    ctx.fillText(fmt(h.hi, 3), x1, bar.t + bar.h + 13);
}

/* F_Ij of the element under the pointer, once a frame at most. */
function hoverPicture(ev) {
    if (!app.heat)
        return;
    const queued = app.hoverAt;
    app.hoverAt = [ev.clientX, ev.clientY];
    if (queued)
        return;
    requestAnimationFrame(() => {
        const [x, y] = app.hoverAt, h = app.heat;
        app.hoverAt = null;
        if (!h)
            return;
        const e = elementAt(x, y);
        setText('heat-hover', e < 0 ? '\u2013' : e === h.element ? 'element ' + e + ' itself'
            : 'element ' + e + ': F = ' + fmt(h.row[e], 6));
    });
}

/* ---- the hemicube: what the shooter's item buffers show ----------------------- */

const hemi = { cache: new Map(), data: null, cells: null };
const HEMI_FACES = ['top (n)', 't1', '\u2212t1', 'n\u00d7t1', '\u2212n\u00d7t1'];

/* Whose hemicube: the clicked element under the heat map, else the
 * shooter of the method or of the race's lane chosen. */
function hemiTarget() {
    const s = app.state, lanes = app.race;
    if (heatShown())
        return { element: app.heat.element, why: 'the clicked element', lane: -1, rgb: app.heat.rgb };
    if (!s)
        return null;
    const lane = lanes ? clamp(parseInt($('hemi-lane').value, 10) || 0, 0, lanes.length - 1) : 0;
    const e = lanes ? lanes[lane].shooter : s.shooter;
    const method = lanes ? lanes[lane].method : s.method;
    if (!Number.isInteger(e) || e < 0 || e >= app.scene.elements)
        return null;
    const role = method === 'gathering' || method === 'jacobi' ? 'the element that gathered last'
                                                              : 'the shooter';
    return { element: e, why: role + (lanes ? ' of ' + method : ''), lane,
             vb: lanes ? lanes[lane].vertex_b : s.vertex_b };
}

/* /api/hemicube for element e at resolution R, kept (the scene as loaded
 * does not change): items, row and the row's sum. */
async function hemicubeItems(e, R) {
    const key = e + '/' + R;
    let d = hemi.cache.get(key);
    if (!d) {
        d = await getJSON('api/hemicube?element=' + e + '&resolution=' + R);
        if (!Array.isArray(d.items) || d.items.length !== 3 * R * R || !Array.isArray(d.row))
            throw new Error('the hemicube has another shape');
        d.sum = d.row.reduce((a, b) => a + b, 0);
        hemi.cache.set(key, d);
        if (hemi.cache.size > 32)
            hemi.cache.delete(hemi.cache.keys().next().value);
    }
    return d;
}

/* Each element's colour: the heat map's F_Ij, or its radiosity toned as
 * the picture (render.c rad_tone_byte, the scene's exposure): the element
 * radiosity of /api/elements where that is the lane's (the first lane,
 * before any change), else the mean of its vertices' smoothed radiosity. */
async function elementColours(t) {
    if (t.lane < 0)
        return { rgb: t.rgb, what: 'F_Ij, as the heat map' };
    const n = app.scene.elements, ex = app.scene.exposure;
    let b = null, what = 'radiosity';
    if (t.lane === 0 && app.state.mode !== 'animate') {
        const st = await getJSON('api/elements');
        if (Array.isArray(st.element_b) && st.element_b.length === 3 * n)
            b = st.element_b;
    }
    if (!b) {
        b = vertexMean(t.vb || []);
        what = 'radiosity (the mean of its vertices)';
    }
    const rgb = new Uint8Array(3 * n);
    for (let k = 0; k < 3 * n; k++)
        rgb[k] = toneByte(b[k], ex);
    return { rgb, what };
}

/* Per element, the mean of its vertices' radiosity (r, g, b). */
function vertexMean(vb) {
    const faces = app.scene.faces, b = new Float64Array(3 * faces.length);
    faces.forEach((f, e) => {
        for (const v of f)
            for (let c = 0; c < 3; c++)
                b[3 * e + c] += (vb[3 * v + c] || 0) / f.length;
    });
    return b;
}

/* Fetch what is missing and paint: at most every 300 ms (throttled). */
async function refreshHemicube() {
    if (STILL || !$('hemi-show').checked)
        return;
    $('hemi-lane-row').hidden = !app.race || heatShown();
    const t = hemiTarget(), R = parseInt($('hemi-res').value, 10) || 32;
    const changed = app.state && app.state.mode === 'animate';
    if (!t)
        return clearHemicube(changed ? 'no shooter while the scene changes: click an element'
                                     : 'no shooter yet: take a step, or click an element');
    try {
        const d = await hemicubeItems(t.element, R);
        const c = await elementColours(t);
        paintHemicube(d, c.rgb);
        hemi.data = d;
        setText('hemi-caption', 'element ' + t.element + ', ' + t.why + '; R = ' + R +
                '; coloured by ' + c.what + (changed ? '; the scene as loaded' : ''));
        setText('hemi-sum', fmt(d.sum, 6));
    } catch (e) {
        clearHemicube('cannot draw the hemicube: ' + e.message);
    }
}
const updateHemicube = throttled(refreshHemicube, 300);

function clearHemicube(why) {
    const c = $('hemi');
    c.getContext('2d').clearRect(0, 0, c.width, c.height);
    hemi.data = hemi.cells = null;
    setText('hemi-caption', why);
    setText('hemi-sum', '\u2013');
}

/* Where pixel (x, y) of face f lands in the unfolded cross of 2R x 2R
 * cells, seen from the element looking up the normal n: the top face's
 * camera (hemicube.c one_face, render.c make_view) has right = n x t1 and
 * up = t1, so t1 is up the cross and n x t1 to the right; a side along d
 * has up = n (its row 0 at the top face's edge) and right = d x n.  Each
 * side is folded out about the edge it shares with the top face. */
function crossCell(R, f, x, y) {
    const h = R / 2;
    switch (f) {
    case 0: return [h + x, h + y];                 /* top */
    case 1: return [h + R - 1 - x, h - 1 - y];     /* t1 above: right = -(n x t1) */
    case 2: return [h + x, h + R + y];             /* -t1 below: right = n x t1 */
    case 3: return [h + R + y, h + R - 1 - x];     /* n x t1 right: right = t1 */
    default: return [h - 1 - y, h + x];            /* -(n x t1) left: right = -t1 */
    }
}

/* The unfolded hemicube: one cell per pixel of the item buffers (the top
 * face's R x R first, then the sides' R/2 x R, radi_hemicube_row_items'
 * order) in its element's colour, black where nothing is seen (render.c's
 * background); the cross's corners blank, thin lines between the faces. */
function paintHemicube(d, rgb) {
    const R = d.resolution, N = 2 * R, img = new ImageData(N, N);
    const cells = new Int32Array(N * N).fill(-1);
    for (let f = 0; f < 5; f++) {
        const rows = f ? R / 2 : R, base = f ? R * R + (f - 1) * (R / 2) * R : 0;
        for (let y = 0; y < rows; y++)
            for (let x = 0; x < R; x++) {
                const [X, Y] = crossCell(R, f, x, y), c = Y * N + X, p = base + y * R + x;
                const id = d.items[p], o = 4 * c;
                cells[c] = p;
                for (let k = 0; k < 3; k++)
                    img.data[o + k] = id >= 0 ? rgb[3 * id + k] : 0;
                img.data[o + 3] = 255;
            }
    }
    hemi.cells = cells;
    drawCross(img, R);
}

function drawCross(img, R) {
    const c = $('hemi'), ctx = c.getContext('2d'), N = 2 * R;
    const dpr = window.devicePixelRatio || 1, W = c.clientWidth || 256, H = c.clientHeight || 256;
    c.width = Math.round(W * dpr);
    c.height = Math.round(H * dpr);
    const off = document.createElement('canvas');
    off.width = off.height = N;
    off.getContext('2d').putImageData(img, 0, 0);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(off, 0, 0, W, H);
    const s = W / N, h = R / 2;
    ctx.strokeStyle = 'rgba(200, 200, 200, 0.6)';
    ctx.lineWidth = 1;
    for (const [x, y, w, hh] of [[h, h, R, R], [h, 0, R, h], [h, h + R, R, h], [h + R, h, h, R],
                                 [0, h, h, R]])
        ctx.strokeRect(x * s, y * s, w * s, hh * s);
    ctx.fillStyle = '#aaa';
    ctx.font = '11px sans-serif';
    ctx.textAlign = 'right';
    ctx.fillText('t1 \u2191', h * s - 4, h * s - 6);
    ctx.textAlign = 'left';
    ctx.fillText('n\u00d7t1 \u2192', (h + R) * s + 4, h * s - 6);
}

/* The pixel under the pointer: its face, the element it shows, its F. */
function hoverHemicube(ev) {
    const d = hemi.data, c = $('hemi');
    if (!d || !hemi.cells)
        return;
    const R = d.resolution, N = 2 * R;
    const X = Math.floor(ev.offsetX * N / c.clientWidth), Y = Math.floor(ev.offsetY * N / c.clientHeight);
    const p = X >= 0 && X < N && Y >= 0 && Y < N ? hemi.cells[Y * N + X] : -1;
    if (p < 0)
        return setText('hemi-hover', '\u2013');
    const f = p < R * R ? 0 : 1 + Math.floor((p - R * R) / (R * R / 2));
    const q = f ? (p - R * R) % (R * R / 2) : p, id = d.items[p];
    let text = HEMI_FACES[f] + ' (' + q % R + ', ' + Math.floor(q / R) + '): ';
    text += id < 0 ? 'nothing' : 'element ' + id + ', F by the hemicube ' + fmt(d.row[id], 4);
    if (id >= 0 && heatShown() && app.heat.element === d.element)
        text += ', F ' + fmt(app.heat.row[id], 4);
    setText('hemi-hover', text);
}

/* ---- the material editor: `material NAME reflect R G B emit R G B` ------------- */

const MATERIAL_INPUTS = ['refl-r', 'refl-g', 'refl-b', 'emit-r', 'emit-g', 'emit-b'];

function currentMaterial() {
    const name = $('material').value;
    return (app.scene.materials || []).find((m) => m.name === name) || null;
}

/* The scene's materials into the list (again after each scene change). */
function showMaterials() {
    if (STILL)
        return;
    const mats = app.scene.materials || [];
    fillNames($('material'), mats);
    $('material-tools').hidden = !mats.length;
    fillMaterial(false);
}

/* The chosen material's values into the inputs; not while one of them is
 * being edited, unless `force`. */
function fillMaterial(force) {
    const m = currentMaterial();
    if (!m || (!force && MATERIAL_INPUTS.some((id) => document.activeElement === $(id))))
        return;
    m.reflect.concat(m.emit).forEach((x, k) => { $(MATERIAL_INPUTS[k]).value = String(x); });
    setText('material-error', '');
    showSwatch();
}

/* The reflectance as an sRGB colour (eq. 5.2), a preview of the surface. */
function showSwatch() {
    const v = MATERIAL_INPUTS.slice(0, 3).map((id) => Number($(id).value));
    $('material-swatch').style.background = v.every((x) => isFinite(x))
        ? cssRGB(v.map((x) => Math.round(255 * srgbEncode(x)))) : 'transparent';
}

/* Send the line; the server checks the ranges (reflect 0 to 1, emit 0 or
 * more) and its reason for a refusal shows under the editor. */
async function applyMaterial() {
    const m = currentMaterial();
    if (!m)
        return;
    const v = MATERIAL_INPUTS.map((id) => $(id).value.trim());
    if (v.some((x) => x === '' || !isFinite(Number(x))))
        return setText('material-error', 'each value must be a number');
    setText('material-error', '');
    const ok = await postChange('material ' + m.name + ' reflect ' + v.slice(0, 3).join(' ') +
                                ' emit ' + v.slice(3).join(' '));
    setText('material-error', ok ? '' : app.refusal);
}

/* ---- the teaching views' controls ---------------------------------------------- */

function attachTeaching() {
    $('pick').addEventListener('change', (e) => setPickMode(e.target.checked));
    const lane = $('hemi-lane');
    RACE_METHODS.forEach((m, k) => {
        const o = document.createElement('option');
        o.value = String(k);
        o.textContent = m;
        lane.appendChild(o);
        $('lane-' + k).style.borderColor = LANE_COLOURS[k];
    });
    lane.value = String(RACE_METHODS.indexOf('sorted_ambient'));
    const showHemi = () => {
        $('hemi-body').hidden = !$('hemi-show').checked;
        updateHemicube();
    };
    $('hemi-show').addEventListener('change', showHemi);
    $('hemi-res').addEventListener('change', updateHemicube);
    lane.addEventListener('change', updateHemicube);
    $('hemi').addEventListener('mousemove', hoverHemicube);
    $('material').addEventListener('change', () => fillMaterial(true));
    $('material-apply').addEventListener('click', applyMaterial);
    MATERIAL_INPUTS.forEach((id) => $(id).addEventListener('input', showSwatch));
    showHemi();
    setPickMode($('pick').checked);
    showMaterials();
}

/* ---- talking to the server -------------------------------------------------- */

async function getJSON(path) {
    const r = await fetch(path, { cache: 'no-store' });
    if (!r.ok) {
        let reason = 'HTTP ' + r.status;
        try {
            reason = (await r.json()).error || reason;
        } catch (e) { /* not JSON: keep the status */ }
        throw new Error(path + ': ' + reason);
    }
    return r.json();
}

/* The stream of states; EventSource reconnects by itself.  After a
 * reconnection any version is accepted (the server may have restarted). */
function listen() {
    const es = new EventSource('api/events');
    app.events = es;
    es.addEventListener('state', (ev) => {
        let s;
        try {
            s = JSON.parse(ev.data);
        } catch (e) {
            showMessage('a state from the server was not JSON', true);
            return;
        }
        receiveState(s);
    });
    es.onopen = () => {
        app.version = -Infinity;
        setConnection('live');
    };
    es.onerror = () => setConnection(es.readyState === EventSource.CLOSED
        ? 'disconnected (reload to retry)' : 'connection lost, retrying\u2026');
}

/* ---- start ------------------------------------------------------------------- */

function noWebGL(reason) {
    canvas.hidden = true;
    const m = $('nogl');
    m.hidden = false;
    m.textContent = 'The picture needs WebGL, which this browser does not provide (' +
        reason + ').  The panel still works.';
}

function startGL() {
    try {
        if (!initGL()) {
            noWebGL('no WebGL context');
            return false;
        }
    } catch (e) {
        noWebGL(e.message);
        return false;
    }
    canvas.addEventListener('webglcontextlost', (e) => {
        e.preventDefault();
        showMessage('the WebGL context was lost; waiting for it to come back', true);
    });
    canvas.addEventListener('webglcontextrestored', () => {
        initGL();
        uploadHeat();
        showMessage('');
        if (app.state)
            app.pending = app.pending || app.state;
        requestDraw();
    });
    return true;
}

/* The scene and a state that belong together: fetched again (at most
 * three times) while the scene is changing under them. */
async function loadStill() {
    for (let k = 0; ; k++) {
        const scene = await getJSON('api/scene'), s = await getJSON('api/state');
        const same = scene.geometry === undefined || s.geometry === undefined ||
                     scene.geometry === s.geometry;
        if ((fits(scene, s) && same) || k === 2)
            return [scene, s];
    }
}

async function startStill() {
    try {
        const [scene, s] = await loadStill();
        app.scene = scene;
        app.geom = buildGeometry(scene);
        sizeCanvas();
        if (!startGL())
            throw new Error('no WebGL');
        applyState(s);
        draw();
        app.gl.finish();
        /* two frames: the picture is on the screen before "ready" */
        requestAnimationFrame(() => requestAnimationFrame(() => {
            const r = document.createElement('div');
            r.id = 'ready';
            r.hidden = true;
            document.body.appendChild(r);
            document.title = 'ready';
        }));
    } catch (e) {
        document.title = 'error: ' + e.message;
        const m = $('nogl');
        m.hidden = false;
        m.textContent = 'error: ' + e.message;
    }
}

async function startLive() {
    setConnection('loading the scene\u2026');
    try {
        app.scene = await getJSON('api/scene');
    } catch (e) {
        showMessage('cannot load the scene: ' + e.message, true);
        setConnection('no scene');
        return;
    }
    app.timing.scene = performance.now();
    app.geometry = app.scene.geometry;
    app.geom = buildGeometry(app.scene);
    sizeCanvas();
    attachPanel();
    /* the state is asked for before WebGL starts, which takes the longest
     * in a browser without a GPU: it is there when the context is */
    const state = getJSON('api/state');
    listen();
    if (startGL())
        attachMouse();
    app.timing.gl = performance.now();
    try {
        receiveState(await state);
    } catch (e) {
        showMessage('cannot load the state: ' + e.message, true);
    }
}

(STILL ? startStill : startLive)();

})();
