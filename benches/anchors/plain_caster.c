/*
 * The plain C anchor of `cargo bench -p render-benches --bench ray_casting` (issue 22).
 *
 * Lesson 08's scene (src/scenes.rs, `lesson08`) seen through lesson 08's pinhole
 * camera (`lesson08_pinhole`), cast shadowless with the textbook tests, in f32,
 * scalar, on one thread: what `course::measure::plain` computes, written in C from
 * the course's formulas so that the Rust casters have a fixed point to be timed
 * against. Compiled with -O2 and -ffp-contract=off (no fused multiply-add, as
 * Rust never fuses), without -march=native: the same instruction set rustc targets.
 *
 *   camera   w = -d/|d|, u = (k x w)/|k x w| made orthogonal to w again,
 *            v = w x u (chapter 05); pixel (px, py) -> the screen point
 *            s = ((px + 1/2)/W (x_max - x_min) + x_min,
 *                 (py' + 1/2)/H (y_max - y_min) + y_min, -distance),
 *            py' = H - 1 - py counted from the bottom row (chapter 03); the ray
 *            starts at the eye, direction (s - e)/|s - e| carried to the world by
 *            B = [u v w] (chapter 06).
 *   sphere   |o + t d - c|^2 = r^2 with |d| = 1: the school formula with b halved,
 *            t = -b' -+ sqrt(b'^2 - c'), b' = (o - c).d, c' = |o - c|^2 - r^2.
 *   plane    t = (p0 - o).n / (d.n).
 *   box      the slab test: t on each pair of planes from 1/d, the largest entry,
 *            the smallest exit.
 *   triangle Möller-Trumbore: p = d x e2, 1/det = 1/(e1.p), u = (o - v0).p/det,
 *            q = (o - v0) x e1, v = d.q/det, t = e2.q/det.
 *
 * The order of every sum is the one the Rust code uses (glam's dot is
 * (x x' + y y') + z z'), so the two images agree bit for bit; the bench checks it.
 */
#include <math.h>
#include <stdint.h>

typedef struct {
    float x, y, z;
} vec3;

static vec3 vec(float x, float y, float z) {
    vec3 v = {x, y, z};
    return v;
}
static vec3 add(vec3 a, vec3 b) { return vec(a.x + b.x, a.y + b.y, a.z + b.z); }
static vec3 sub(vec3 a, vec3 b) { return vec(a.x - b.x, a.y - b.y, a.z - b.z); }
static vec3 scale(float s, vec3 a) { return vec(s * a.x, s * a.y, s * a.z); }
static vec3 mul(vec3 a, vec3 b) { return vec(a.x * b.x, a.y * b.y, a.z * b.z); }
static float dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec3 cross(vec3 a, vec3 b) {
    return vec(a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y);
}
static vec3 normalize(vec3 a) { return scale(1.0f / sqrtf(dot(a, a)), a); }
static float min2(float a, float b) { return a < b ? a : b; }
static float max2(float a, float b) { return a > b ? a : b; }

/* ---- the camera (chapters 03, 05, 06) ---- */

typedef struct {
    uint32_t width, height;
    float x_min, x_max, y_min, y_max; /* the film on the screen plane */
    float distance;                   /* from the eye to the screen */
    vec3 u, v, w, eye;                /* the camera's frame in the world */
} camera;

/* Lesson 08's pinhole camera: eye (0, 3, 9) looking at (0, 0.8, 0), up +Y; the film
 * is 2 x 2.6 high, as wide as the image's aspect, at the distance of the target. */
static camera lesson08_pinhole(uint32_t width, uint32_t height) {
    vec3 eye = vec(0.0f, 3.0f, 9.0f), target = vec(0.0f, 0.8f, 0.0f), up = vec(0.0f, 1.0f, 0.0f);
    vec3 d = sub(target, eye);
    camera c;
    c.w = scale(-1.0f, normalize(d));
    c.u = normalize(cross(up, c.w));
    c.u = normalize(sub(c.u, scale(dot(c.u, c.w), c.w)));
    c.v = cross(c.w, c.u);
    c.eye = eye;
    c.width = width;
    c.height = height;
    float half_height = 2.6f, half_width = half_height * (float)width / (float)height;
    c.x_min = -half_width;
    c.x_max = half_width;
    c.y_min = -half_height;
    c.y_max = half_height;
    c.distance = sqrtf(dot(d, d));
    return c;
}

/* The unit direction, in the world, of the ray through the centre of pixel (px, py),
 * row 0 at the top; the ray starts at the eye. */
static vec3 camera_direction(const camera *c, uint32_t px, uint32_t py) {
    float x = (float)px, y = (float)(c->height - 1 - py);
    vec3 s = vec((x + 0.5f) / (float)c->width * (c->x_max - c->x_min) + c->x_min,
                 (y + 0.5f) / (float)c->height * (c->y_max - c->y_min) + c->y_min,
                 -c->distance);
    vec3 local = normalize(s);
    return add(add(scale(local.x, c->u), scale(local.y, c->v)), scale(local.z, c->w));
}

/* ---- the scene (chapter 08) and the textbook tests (chapter 07) ---- */

enum kind { SPHERE, PLANE, BOX, TRIANGLE };

typedef struct {
    enum kind kind;
    vec3 a, b, c;  /* sphere: centre; plane: point, normal; box: min, max; triangle: v0, e1, e2 */
    float radius_sq;
    vec3 colour;
} primitive;

#define PRIMITIVES 6

static const vec3 BACKGROUND = {0.6f, 0.75f, 0.95f};

static primitive sphere(vec3 centre, float radius, vec3 colour) {
    primitive p = {SPHERE, centre, {0, 0, 0}, {0, 0, 0}, radius * radius, colour};
    return p;
}

/* Lesson 08's objects in the scene's order: a floor, three spheres, a box, a triangle. */
static void lesson08(primitive scene[PRIMITIVES]) {
    primitive floor = {PLANE, {0, 0, 0}, {0, 1, 0}, {0, 0, 0}, 0, {0.75f, 0.75f, 0.7f}};
    vec3 v0 = vec(2.0f, 0.0f, -2.0f), v1 = vec(3.4f, 0.0f, -1.2f), v2 = vec(2.7f, 2.2f, -1.6f);
    primitive box = {BOX, {-0.3f, 0.0f, -2.0f}, {0.9f, 1.6f, -0.8f}, {0, 0, 0}, 0, {0.9f, 0.75f, 0.2f}};
    primitive triangle = {TRIANGLE, v0, sub(v1, v0), sub(v2, v0), 0, {0.6f, 0.3f, 0.75f}};
    scene[0] = floor;
    scene[1] = sphere(vec(-1.6f, 1.0f, 0.0f), 1.0f, vec(0.85f, 0.2f, 0.15f));
    scene[2] = sphere(vec(1.3f, 0.7f, 1.2f), 0.7f, vec(0.2f, 0.35f, 0.85f));
    scene[3] = sphere(vec(0.2f, 0.4f, 2.4f), 0.4f, vec(0.2f, 0.7f, 0.3f));
    scene[4] = box;
    scene[5] = triangle;
}

/* The t of the primitive's nearest crossing, or NAN for none (NAN fails every
 * comparison, so the caller's 0 < t < t_max rejects it). */
static float nearest(const primitive *p, vec3 o, vec3 d, vec3 inv_d) {
    switch (p->kind) {
    case SPHERE: {
        vec3 f = sub(o, p->a);
        float half_b = dot(f, d), c = dot(f, f) - p->radius_sq;
        float disc = half_b * half_b - c;
        if (disc < 0.0f) return NAN;
        float s = sqrtf(disc), t0 = -half_b - s;
        return t0 > 0.0f ? t0 : -half_b + s;
    }
    case PLANE:
        return dot(sub(p->a, o), p->b) / dot(d, p->b);
    case BOX: {
        vec3 a = mul(sub(p->a, o), inv_d), b = mul(sub(p->b, o), inv_d);
        float t0 = max2(min2(a.x, b.x), max2(min2(a.y, b.y), min2(a.z, b.z)));
        float t1 = min2(max2(a.x, b.x), min2(max2(a.y, b.y), max2(a.z, b.z)));
        if (t0 > t1) return NAN;
        return t0 > 0.0f ? t0 : t1;
    }
    case TRIANGLE: {
        vec3 e1 = p->b, e2 = p->c;
        vec3 pv = cross(d, e2);
        float inv = 1.0f / dot(e1, pv);
        vec3 tvec = sub(o, p->a);
        float b1 = dot(tvec, pv) * inv;
        vec3 q = cross(tvec, e1);
        float b2 = dot(d, q) * inv;
        if (b1 < 0.0f || b2 < 0.0f || b1 + b2 > 1.0f) return NAN;
        return dot(e2, q) * inv;
    }
    }
    return NAN;
}

/* Shadowless ray casting: the colour of the nearest primitive, or the background. */
static vec3 shadowless(const primitive scene[PRIMITIVES], vec3 o, vec3 d) {
    vec3 inv_d = vec(1.0f / d.x, 1.0f / d.y, 1.0f / d.z);
    float t_max = INFINITY;
    vec3 colour = BACKGROUND;
    for (int i = 0; i < PRIMITIVES; i++) {
        float t = nearest(&scene[i], o, d, inv_d);
        if (t > 0.0f && t < t_max) {
            t_max = t;
            colour = scene[i].colour;
        }
    }
    return colour;
}

/* ---- what the bench calls ---- */

/* One frame of lesson 08, `width` x `height`, into `rgb` (3 floats a pixel, row 0 at
 * the top, the caller's buffer of 3 width height floats), on this thread. */
void plain_caster_frame(uint32_t width, uint32_t height, float *rgb) {
    camera cam = lesson08_pinhole(width, height);
    primitive scene[PRIMITIVES];
    lesson08(scene);
    for (uint32_t y = 0; y < height; y++) {
        for (uint32_t x = 0; x < width; x++) {
            vec3 c = shadowless(scene, cam.eye, camera_direction(&cam, x, y));
            float *out = rgb + 3 * ((uint64_t)y * width + x);
            out[0] = c.x;
            out[1] = c.y;
            out[2] = c.z;
        }
    }
}

/* The camera alone: every pixel's ray direction into `xyz` (3 floats a pixel). */
void plain_camera_frame(uint32_t width, uint32_t height, float *xyz) {
    camera cam = lesson08_pinhole(width, height);
    for (uint32_t y = 0; y < height; y++) {
        for (uint32_t x = 0; x < width; x++) {
            vec3 d = camera_direction(&cam, x, y);
            float *out = xyz + 3 * ((uint64_t)y * width + x);
            out[0] = d.x;
            out[1] = d.y;
            out[2] = d.z;
        }
    }
}
