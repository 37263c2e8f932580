#!/usr/bin/env python3
"""Lesson 10's path tracer against Mitsuba 3, region by region (run by scripts/cross-check).

Each configuration (a scene, the crate's sampling and --max-depth) is rendered by the
crate (the `cross-check` bin of render-benches, Russian roulette off) and by Mitsuba 3
(`scalar_rgb`, the `path` integrator with Russian roulette pushed out of reach), each
with SEEDS independent seeds. The scene Mitsuba renders is built from the crate's own
numbers (`cross-check describe`), never typed here.

For each region of a 4 x 4 grid and each channel, the mean of the region in every
seed's image gives a mean and a standard error per renderer; Welch's t of the
difference, with its degrees of freedom, gives a two-sided p-value, printed as the
normal z of the same p. The run fails if any p is below ALPHA / M, M the number of
tests of the run (Bonferroni: the chance that a correct renderer fails the run is
at most ALPHA, whatever the tests' dependence). Where the crate has a closed form
(the two-light floor: direct light only), the region means of both renderers are
also tested against it.

Standard library and Mitsuba only (no numpy).
"""

import argparse
import json
import math
import os
import struct
import subprocess
import sys
import time
from statistics import NormalDist

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.path.join(ROOT, "target", "release", "cross-check")

WIDTH, HEIGHT = 64, 48
GRID = 4
SEEDS = 16
ALPHA = 0.01
# Walls are planes in the crate; Mitsuba gets rectangles that reach this far along an
# axis the box leaves open (a rectangle of 1e5 loses precision in f32).
FAR = 1.0e4
# How far a wall's rectangle overhangs the walls it meets, so that no ray slips
# through a seam; the overhang lies behind the other walls, where no path goes.
OVERHANG = 1.0

# (scene, crate sampling, crate --max-depth, samples per pixel per seed); the two
# strategies of a depth are compared with the same Mitsuba images.
CONFIGS = [
    ("cornell", "mis", 0, 32),
    ("cornell", "cosine", 1, 64),
    ("cornell", "mis", 1, 64),
    ("cornell", "cosine", 2, 64),
    ("cornell", "mis", 2, 64),
    ("cornell", "mis", 8, 32),
    ("two-lights", "nee", 1, 64),
    ("two-lights", "mis", 1, 64),
]
# The configurations whose per-pixel z the z-map figure shows (book-figures).
ZMAPS = ["cornell_mis_1", "cornell_mis_2", "cornell_mis_8", "two-lights_mis_1"]

SAMPLING_NAMES = {"cosine": "cosine", "mis": "MIS", "nee": "next event"}
SCENE_NAMES = {"cornell": "Cornell box", "two-lights": "two lights"}


# ---------------------------------------------------------------- the crate


def crate(*args):
    out = subprocess.run([BIN, *args], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"cross-check: `{BIN} {' '.join(args)}` failed:\n{out.stderr}")
    return out.stdout


def read_pfm(path):
    """RGB rows top to bottom, as a flat list [r, g, b, r, g, b, ...]."""
    with open(path, "rb") as f:
        data = f.read()
    header, rest = data.split(b"\n", 1)
    size, rest = rest.split(b"\n", 1)
    scale, raw = rest.split(b"\n", 1)
    assert header == b"PF", header
    w, h = map(int, size.split())
    endian = "<" if float(scale) < 0 else ">"
    values = struct.unpack(f"{endian}{w * h * 3}f", raw[: w * h * 12])
    rows = [values[y * w * 3 : (y + 1) * w * 3] for y in range(h)]
    return [v for row in reversed(rows) for v in row]


def crate_images(scene, sampling, depth, spp, seeds, scratch, threads=None):
    images, seconds = [], 0.0
    for seed in seeds:
        path = os.path.join(scratch, f"crate_{scene}_{sampling}_{depth}_{seed}.pfm")
        args = ["render", "--scene", scene, "--width", str(WIDTH), "--height", str(HEIGHT),
                "--sampling", sampling, "--max-depth", str(depth), "--spp", str(spp),
                "--seed", str(seed), "--out", path]
        if threads:
            args += ["--threads", str(threads)]
        line = crate(*args)
        if " 0 non-finite" not in line:
            sys.exit(f"cross-check: the crate dropped NaN samples: {line}")
        seconds += float(line.split(" in ")[1].split(" s")[0])
        images.append(read_pfm(path))
    return images, seconds


# ---------------------------------------------------------------- Mitsuba


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def add(a, b):
    return [x + y for x, y in zip(a, b)]


def mul(a, s):
    return [x * s for x in a]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(dot(a, a))


def axis_of(normal):
    """The axis a wall's normal lies along, and its sign; walls must be axis planes."""
    k = max(range(3), key=lambda i: abs(normal[i]))
    if any(abs(normal[i]) > 1e-6 for i in range(3) if i != k):
        sys.exit(f"cross-check: a plane with normal {normal} is not an axis plane")
    return k, 1 if normal[k] > 0 else -1


def box_of(planes):
    """[lo, hi] per axis: the planes facing +axis bound it below, those facing -axis
    above; an axis without one is open, to FAR."""
    box = [[-FAR, FAR] for _ in range(3)]
    for p in planes:
        k, sign = axis_of(p["normal"])
        box[k][0 if sign > 0 else 1] = p["point"][k]
    return box


def frame_matrix(a, b, n, centre):
    """The 4x4 matrix taking Mitsuba's rectangle [-1, 1]^2 (normal +z) to the
    parallelogram centre + s a + t b with normal n (a x b along n: det > 0)."""
    assert dot(cross(a, b), n) > 0, (a, b, n)
    return [[a[i], b[i], n[i], centre[i]] for i in range(3)] + [[0.0, 0.0, 0.0, 1.0]]


def rectangle_of_plane(plane, box):
    k, _ = axis_of(plane["normal"])
    n = plane["normal"]
    i, j = (k + 1) % 3, (k + 2) % 3
    lo = [box[i][0] - OVERHANG, box[j][0] - OVERHANG]
    hi = [box[i][1] + OVERHANG, box[j][1] + OVERHANG]
    centre = [0.0, 0.0, 0.0]
    centre[k] = plane["point"][k]
    centre[i], centre[j] = (lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2
    a, b = [0.0] * 3, [0.0] * 3
    a[i], b[j] = (hi[0] - lo[0]) / 2, (hi[1] - lo[1]) / 2
    if dot(cross(a, b), n) < 0:
        a, b = b, a
    return frame_matrix(a, b, n, centre)


def rectangle_of_quad(q):
    a = mul(sub(q["end_a"], q["corner"]), 0.5)
    b = mul(sub(q["end_b"], q["corner"]), 0.5)
    centre = add(q["corner"], add(a, b))
    return frame_matrix(a, b, q["normal"], centre)


# ANCHOR: bsdf
def bsdf_of(material):
    kind = material["type"]
    if kind == "diffuse":
        # The crate's Lambertian surfaces scatter on both sides.
        return {"type": "twosided",
                "bsdf": {"type": "diffuse",
                         "reflectance": {"type": "rgb", "value": material["albedo"]}}}
    if kind == "mirror":
        reflectance = {"type": "rgb", "value": material["reflectance"]}
        return {"type": "conductor", "material": "none",
                "specular_reflectance": reflectance}
    if kind == "glass":
        # Outside the glass: index 1 (`Material::Glass`).
        return {"type": "dielectric", "int_ior": material["ior"], "ext_ior": 1.0}
    sys.exit(f"cross-check: no Mitsuba BSDF for {material}")
# ANCHOR_END: bsdf


def mitsuba_dict(desc, max_depth, spp):
    """The Mitsuba scene of the crate's `desc`, its `path` integrator at the crate's
    --max-depth `max_depth` (Mitsuba counts the camera ray's segment as one: +1)."""
    import mitsuba as mi

    cam = desc["camera"]
    (x0, x1), (y0, y1) = cam["x_extent"], cam["y_extent"]
    if abs(x0 + x1) > 1e-6 or abs(y0 + y1) > 1e-6:
        sys.exit("cross-check: the film is not centred on the view axis")
    if abs(x1 / y1 - cam["width"] / cam["height"]) > 1e-5:
        sys.exit("cross-check: the film's pixels are not square")
    if any(desc["background"]):
        sys.exit("cross-check: a background needs a Mitsuba `constant` emitter")
    # ANCHOR: sensor
    fov = math.degrees(2 * math.atan(y1 / cam["screen_distance"]))
    scene = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": max_depth + 1,
                       "rr_depth": max_depth + 1000},
        "sensor": {
            "type": "perspective", "fov_axis": "y", "fov": fov,
            "to_world": mi.ScalarTransform4f().look_at(
                origin=cam["eye"], target=sub(cam["eye"], cam["w"]), up=cam["v"]),
            "film": {"type": "hdrfilm", "width": cam["width"], "height": cam["height"],
                     "pixel_format": "rgb", "rfilter": {"type": "box"}},
            "sampler": {"type": "independent", "sample_count": spp},
        },
    }
    # ANCHOR_END: sensor
    planes = [o["shape"] for o in desc["objects"] if o["shape"]["type"] == "plane"]
    box = box_of(planes)
    for index, o in enumerate(desc["objects"]):
        shape = o["shape"]
        if shape["type"] == "plane":
            m = {"type": "rectangle",
                 "to_world": mi.ScalarTransform4f(rectangle_of_plane(shape, box))}
        elif shape["type"] == "quad":
            m = {"type": "rectangle",
                 "to_world": mi.ScalarTransform4f(rectangle_of_quad(shape))}
        elif shape["type"] == "sphere":
            m = {"type": "sphere", "center": shape["centre"], "radius": shape["radius"]}
        else:
            sys.exit(f"cross-check: no Mitsuba shape for {shape}")
        if any(o["emission"]):
            # Mitsuba's area lights shine from the front (the normal's side) only: a
            # lamp's one side, or a sphere's outside, all that can be seen of it.
            if not (o["front_only"] or shape["type"] == "sphere"):
                sys.exit(f"cross-check: a two-sided emitter Mitsuba cannot match: {shape}")
            m["emitter"] = {"type": "area",
                            "radiance": {"type": "rgb", "value": o["emission"]}}
        m["bsdf"] = bsdf_of(o["material"])
        scene[f"object_{index}"] = m
    return scene, fov


def mitsuba_images(desc, depth, spp, seeds, threads=None):
    import drjit as dr
    import mitsuba as mi

    if threads:
        dr.set_thread_count(threads)
    scene = mi.load_dict(mitsuba_dict(desc, depth, spp)[0])
    images, seconds = [], 0.0
    for seed in seeds:
        start = time.perf_counter()
        image = mi.render(scene, seed=seed, spp=spp)
        seconds += time.perf_counter() - start
        images.append(list(image.array))
    return images, seconds


# ---------------------------------------------------------------- statistics


def betacf(a, b, x):
    """The continued fraction of the incomplete beta function (Lentz)."""
    tiny = 1e-300
    qab, qap, qam = a + b, a + 1, a - 1
    c, d = 1.0, 1 - qab * x / qap
    d = 1 / (d if abs(d) > tiny else tiny)
    h = d
    for m in range(1, 500):
        m2 = 2 * m
        aa = m * (b - m) * x / ((qam + m2) * (a + m2))
        d = 1 + aa * d
        d = 1 / (d if abs(d) > tiny else tiny)
        c = 1 + aa / c
        c = c if abs(c) > tiny else tiny
        h *= d * c
        aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2))
        d = 1 + aa * d
        d = 1 / (d if abs(d) > tiny else tiny)
        c = 1 + aa / c
        c = c if abs(c) > tiny else tiny
        delta = d * c
        h *= delta
        if abs(delta - 1) < 1e-15:
            break
    return h


def incomplete_beta(a, b, x):
    if x <= 0:
        return 0.0
    if x >= 1:
        return 1.0
    front = math.exp(math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b)
                     + a * math.log(x) + b * math.log(1 - x))
    if x < (a + 1) / (a + b + 2):
        return front * betacf(a, b, x) / a
    return 1 - front * betacf(b, a, 1 - x) / b


def t_two_sided_p(t, dof):
    """P(|T| >= |t|) for Student's t with `dof` degrees of freedom."""
    return incomplete_beta(dof / 2, 0.5, dof / (dof + t * t))


def z_of_p(p, sign):
    """The normal deviate with the same two-sided p, signed."""
    p = max(p, 1e-300)
    return -sign * NormalDist().inv_cdf(p / 2) if p < 1 else 0.0


def mean_and_se2(values):
    """The mean of `values` and the square of its standard error."""
    n = len(values)
    m = sum(values) / n
    var = sum((v - m) ** 2 for v in values) / (n - 1)
    return m, var / n


# ANCHOR: welch
def welch(a, b):
    """(z, p) of mean(a) - mean(b): Welch's t and its degrees of freedom."""
    (ma, va), (mb, vb) = mean_and_se2(a), mean_and_se2(b)
    diff, var = ma - mb, va + vb
    if var == 0:
        return (0.0, 1.0) if diff == 0 else (math.copysign(math.inf, diff), 0.0)
    dof = var * var / (va * va / (len(a) - 1) + vb * vb / (len(b) - 1))
    t = diff / math.sqrt(var)
    p = t_two_sided_p(t, dof)
    return z_of_p(p, math.copysign(1, t)), p
# ANCHOR_END: welch


def one_sample(a, exact):
    m, v = mean_and_se2(a)
    diff = m - exact
    if v == 0:
        return (0.0, 1.0) if abs(diff) <= 1e-12 * abs(exact) else (math.copysign(math.inf, diff), 0.0)
    t = diff / math.sqrt(v)
    p = t_two_sided_p(t, len(a) - 1)
    return z_of_p(p, math.copysign(1, t)), p


def region_means(image):
    """[region][channel] means, regions row by row from the top left."""
    rw, rh = WIDTH // GRID, HEIGHT // GRID
    out = []
    for gy in range(GRID):
        for gx in range(GRID):
            sums = [0.0, 0.0, 0.0]
            for y in range(gy * rh, (gy + 1) * rh):
                for x in range(gx * rw, (gx + 1) * rw):
                    i = (y * WIDTH + x) * 3
                    for c in range(3):
                        sums[c] += image[i + c]
            out.append([s / (rw * rh) for s in sums])
    return out


# ---------------------------------------------------------------- the closed form


def ray_sphere(o, d, centre, r):
    oc = sub(o, centre)
    b = dot(oc, d)
    c = dot(oc, oc) - r * r
    disc = b * b - c
    if disc < 0:
        return None
    s = math.sqrt(disc)
    t = -b - s if -b - s > 1e-9 else -b + s
    return t if t > 1e-9 else None


def sphere_on_floor(p, rho, centre, r, radiance):
    """The light a Lambertian floor point p (normal +Y, albedo rho) reflects from a
    uniform sphere light wholly above its horizon: rho L (r/d)^2 cos theta_c, the
    sphere's irradiance pi L (r/d)^2 cos theta_c times rho / pi
    (`sphere_light_on_floor` in tests/lessons/lesson_10_path_tracing.rs)."""
    to_c = sub(centre, p)
    d2 = dot(to_c, to_c)
    return rho * radiance * r * r / d2 * to_c[1] / math.sqrt(d2)


class Exact:
    """The two-light floor's exact image: direct light only (the lights are black,
    the floor sees no other surface). A sphere light seen directly gives its L; a
    floor point gets `sphere_on_floor` from each light. That holds where no sphere
    stands in front of another as seen from the floor point (`apart` > 0); the
    regions where one does (a shadow of one light cast by the other) have no closed
    form here and are left out of the closed-form test."""

    def __init__(self, desc):
        cam = desc["camera"]
        floor = [o for o in desc["objects"] if o["shape"]["type"] == "plane"]
        self.lights = [(o["shape"]["centre"], o["shape"]["radius"], o["emission"][0])
                       for o in desc["objects"] if o["shape"]["type"] == "sphere"]
        grey = lambda v: v[0] == v[1] == v[2]
        assert len(floor) == 1 and floor[0]["shape"]["normal"] == [0.0, 1.0, 0.0]
        assert len(self.lights) + 1 == len(desc["objects"])
        assert all(o["material"]["type"] == "diffuse" and grey(o["material"]["albedo"])
                   and grey(o["emission"]) for o in desc["objects"])
        assert all(not any(o["material"]["albedo"]) for o in desc["objects"]
                   if o["shape"]["type"] == "sphere")
        self.floor_y = floor[0]["shape"]["point"][1]
        assert all(c[1] - r > self.floor_y for c, r, _ in self.lights)  # above the horizon
        self.rho = floor[0]["material"]["albedo"][0]
        self.cam = cam
        self.pixel_angle = (cam["y_extent"][1] - cam["y_extent"][0]) / cam["height"] \
            / cam["screen_distance"]

    def direction(self, fx, fy):
        """The unit camera ray through film point (fx, fy) in pixels from the top left."""
        cam = self.cam
        (x0, x1), (y0, y1) = cam["x_extent"], cam["y_extent"]
        x = x0 + fx / cam["width"] * (x1 - x0)
        y = y1 - fy / cam["height"] * (y1 - y0)
        d = [cam["u"][i] * x + cam["v"][i] * y - cam["w"][i] * cam["screen_distance"]
             for i in range(3)]
        return mul(d, 1 / norm(d))

    def radiance(self, d):
        """(the exact radiance along the unit camera ray d, and `apart`: the least
        angle between two lights' cones seen from the floor point it meets, inf if
        it meets none; where `apart` <= 0 the radiance is not exact)."""
        eye = self.cam["eye"]
        best, seen = math.inf, None
        for c, r, radiance in self.lights:
            t = ray_sphere(eye, d, c, r)
            if t is not None and t < best:
                best, seen = t, radiance
        t_floor = (self.floor_y - eye[1]) / d[1] if d[1] < 0 else math.inf
        if seen is not None and best < t_floor:
            return seen, math.inf
        if t_floor == math.inf:
            return 0.0, math.inf
        p = add(eye, mul(d, t_floor))
        total, apart = 0.0, math.inf
        cones = []
        for c, r, radiance in self.lights:
            to_c = sub(c, p)
            dist = norm(to_c)
            cones.append((mul(to_c, 1 / dist), math.asin(r / dist)))
            total += sphere_on_floor(p, self.rho, c, r, radiance)
        for i in range(len(cones)):
            for j in range(i + 1, len(cones)):
                angle = math.acos(max(-1.0, min(1.0, dot(cones[i][0], cones[j][0]))))
                apart = min(apart, angle - cones[i][1] - cones[j][1])
        return total, apart

    def straddles(self, fx, fy, half):
        """The radiance of the brightest sphere whose outline the square may hold, 0 if
        none. Can the square of half-side `half` pixels around film point (fx, fy) hold
        part of a sphere's outline? (The angle from the sphere's centre to the
        square's centre is within 1.5 times the square's angular half-diagonal of
        the sphere's angular radius.)"""
        d = self.direction(fx, fy)
        reach = 1.5 * half * math.sqrt(2) * self.pixel_angle
        eye, jump = self.cam["eye"], 0.0
        for c, r, radiance in self.lights:
            to_c = sub(c, eye)
            dist = norm(to_c)
            angle = math.acos(max(-1.0, min(1.0, dot(d, to_c) / dist)))
            if abs(angle - math.asin(r / dist)) <= reach:
                jump = max(jump, radiance)
        return jump

    def cell(self, fx, fy, size, budget):
        """(the mean radiance over the square of side `size` pixels centred at (fx, fy),
        the least `apart` in it). A square that may hold part of a sphere's outline
        is split into 4 x 4 until its share of the pixel times the radiance of that
        sphere is below `budget`; any other square is smooth, and 4 x 4 Gauss-Legendre
        points integrate it."""
        if self.straddles(fx, fy, size / 2) * size * size > budget:
            step = size / 4
            cells = [self.cell(fx + (i - 1.5) * step, fy + (j - 1.5) * step, step, budget)
                     for j in range(4) for i in range(4)]
            return sum(c[0] for c in cells) / 16, min(c[1] for c in cells)
        total, apart = 0.0, math.inf
        for xi, wx in GAUSS_4:
            for yi, wy in GAUSS_4:
                value, a = self.radiance(self.direction(fx + xi * size / 2, fy + yi * size / 2))
                total += wx * wy * value / 4
                apart = min(apart, a)
        return total, apart


# Gauss-Legendre on [-1, 1], four points: exact for polynomials of degree 7.
GAUSS_4 = [(-0.8611363115940526, 0.3478548451374638), (-0.3399810435848563, 0.6521451548625461),
           (0.3399810435848563, 0.6521451548625461), (0.8611363115940526, 0.3478548451374638)]


def closed_form(desc, budget=1e-2):
    """The exact region means, None for a region where one light may stand in front
    of the other: `apart` <= 0 at a quadrature point, or `apart` at some pixel
    less than it changes by between neighbouring pixels (a shadow's edge could fall
    between them)."""
    exact = Exact(desc)
    values, apart = [], []
    for py in range(HEIGHT):
        for px in range(WIDTH):
            v, a = exact.cell(px + 0.5, py + 0.5, 1.0, budget)
            values.append(v)
            apart.append(a)
    rw, rh = WIDTH // GRID, HEIGHT // GRID
    out = []
    for gy in range(GRID):
        for gx in range(GRID):
            pixels = [(x, y) for y in range(gy * rh, (gy + 1) * rh)
                      for x in range(gx * rw, (gx + 1) * rw)]
            at = lambda x, y: apart[y * WIDTH + x]
            least = min(at(x, y) for x, y in pixels)
            change = max((abs(at(x, y) - at(x2, y2)) for x, y in pixels
                          for x2, y2 in ((x + 1, y), (x, y + 1))
                          if x2 < WIDTH and y2 < HEIGHT and math.isfinite(at(x, y))
                          and math.isfinite(at(x2, y2))), default=0.0)
            clean = least > 0 and least > change
            out.append(sum(values[y * WIDTH + x] for x, y in pixels) / len(pixels)
                       if clean else None)
    return out


# ---------------------------------------------------------------- one configuration


def compare(desc, scene, sampling, depth, spp, scratch, exact, cache):
    seeds = list(range(1, SEEDS + 1))
    ours, t_ours = crate_images(scene, sampling, depth, spp, seeds, scratch)
    if (scene, depth, spp) not in cache:
        cache[(scene, depth, spp)] = mitsuba_images(desc, depth, spp, seeds)
    theirs, t_theirs = cache[(scene, depth, spp)]
    r_ours = [region_means(im) for im in ours]
    r_theirs = [region_means(im) for im in theirs]
    regions = []
    for k in range(GRID * GRID):
        cells = []
        for c in range(3):
            a = [r[k][c] for r in r_ours]
            b = [r[k][c] for r in r_theirs]
            z, p = welch(a, b)
            se = math.sqrt(mean_and_se2(a)[1] + mean_and_se2(b)[1])
            cell = {"crate": sum(a) / len(a), "mitsuba": sum(b) / len(b), "z": z, "p": p,
                    "se": se}
            if exact is not None and exact[k] is not None:
                cell["exact"] = exact[k]
                cell["z_crate_exact"], cell["p_crate_exact"] = one_sample(a, exact[k])
                cell["z_mitsuba_exact"], cell["p_mitsuba_exact"] = one_sample(b, exact[k])
            cells.append(cell)
        regions.append(cells)
    # Per pixel: z of the grey value's difference, for the z-map.
    zmap = []
    for i in range(WIDTH * HEIGHT):
        a = [sum(im[3 * i : 3 * i + 3]) / 3 for im in ours]
        b = [sum(im[3 * i : 3 * i + 3]) / 3 for im in theirs]
        zmap.append(welch(a, b)[0])
    image_means = lambda images: [sum(im) / len(im) for im in images]
    mean = lambda images: sum(image_means(images)) / len(images)
    z_mean, p_mean = welch(image_means(ours), image_means(theirs))
    return {
        "z_mean": z_mean, "p_mean": p_mean,
        "scene": scene, "sampling": sampling, "depth": depth, "spp": spp,
        "regions": regions, "zmap": zmap,
        "mean_crate": mean(ours), "mean_mitsuba": mean(theirs),
        "seconds_crate": t_ours, "seconds_mitsuba": t_theirs,
    }


# ---------------------------------------------------------------- report


def fmt(x, digits=4):
    return f"{x:.{digits}f}"


def zs(x):
    return "inf" if math.isinf(x) else f"{x:+.2f}".replace("+0.00", "0.00").replace("-0.00", "0.00")


def tests_of(result):
    """(p, z, what) of every test of one configuration."""
    out = [(result["p_mean"], result["z_mean"], "image mean, crate - Mitsuba")]
    for k, cells in enumerate(result["regions"]):
        for c, cell in enumerate(cells):
            out.append((cell["p"], cell["z"], f"region {k}, {'RGB'[c]}, crate - Mitsuba"))
            for who in ("crate", "mitsuba"):
                if f"p_{who}_exact" in cell:
                    out.append((cell[f"p_{who}_exact"], cell[f"z_{who}_exact"],
                                f"region {k}, {'RGB'[c]}, {who} - closed form"))
    return out


def label(r):
    return (f"{SCENE_NAMES[r['scene']]}, {SAMPLING_NAMES[r['sampling']]}, "
            f"depth {r['depth']} (Mitsuba {r['depth'] + 1})")


def catchable(r, z_limit):
    """The relative bias of a region the test would catch (|z| = z_limit), the median
    over the regions and channels that are not black."""
    ratios = sorted(z_limit * c["se"] / c["mitsuba"] for cells in r["regions"] for c in cells
                    if c["mitsuba"] > 0)
    return ratios[len(ratios) // 2] if ratios else math.nan


def summary_table(results, z_limit):
    lines = [
        "| scene, sampling | depth: crate, Mitsuba | image mean: crate / Mitsuba | ratio (z) "
        "| worst \\|z\\| | bias caught | closed form: worst \\|z\\| |",
        "|---|---|---:|---:|---:|---:|---:|",
    ]
    for r in results:
        worst = max(abs(c["z"]) for cells in r["regions"] for c in cells)
        exact = [abs(c[k]) for cells in r["regions"] for c in cells
                 for k in ("z_crate_exact", "z_mitsuba_exact") if k in c]
        lines.append(
            f"| {SCENE_NAMES[r['scene']]}, {SAMPLING_NAMES[r['sampling']]} "
            f"| {r['depth']}, {r['depth'] + 1} "
            f"| {fmt(r['mean_crate'], 5)} / {fmt(r['mean_mitsuba'], 5)} "
            f"| {fmt(r['mean_crate'] / r['mean_mitsuba'], 4)} ({zs(r['z_mean'])}) | {worst:.2f} "
            f"| {100 * catchable(r, z_limit):.1f} % "
            f"| {f'{max(exact):.2f}' if exact else '-'} |")
    return "\n".join(lines)


def region_table(r):
    """The 4 x 4 grid: crate / Mitsuba grey means and the channel z of largest size."""
    lines = ["| row | " + " | ".join(f"column {i}" for i in range(GRID)) + " |",
             "|---|" + "---:|" * GRID]
    for gy in range(GRID):
        cells = []
        for gx in range(GRID):
            cs = r["regions"][gy * GRID + gx]
            grey = lambda key: sum(c[key] for c in cs) / 3
            z = max((c["z"] for c in cs), key=abs)
            cell = f"{fmt(grey('crate'))} / {fmt(grey('mitsuba'))} ({zs(z)})"
            if "exact" in cs[0]:
                cell += f", exact {fmt(cs[0]['exact'])}"
            cells.append(cell)
        lines.append(f"| {gy} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def anchor(name):
    return name.replace("-", "_")


def vec(v):
    return "(" + ", ".join(f"{x + 0.0:g}" for x in v) + ")"


def parameters(desc, fov):
    """The Cornell box's camera and lamp as the crate holds them, and what Mitsuba
    is given for them."""
    cam = desc["camera"]
    lamp = next(o for o in desc["objects"] if o["front_only"])
    q = lamp["shape"]
    half = cam["y_extent"][1]
    return "\n".join([
        "| the crate's value | | Mitsuba's |",
        "|---|---|---|",
        f"| eye | {vec(cam['eye'])} | sensor `\"origin\"` |",
        f"| **w** (from the scene to the eye) | {vec(cam['w'])} "
        "| `\"target\"`: eye - **w** |",
        f"| **v** | {vec(cam['v'])} | `\"up\"` |",
        f"| film half height, screen distance | {half:g}, {cam['screen_distance']:g} "
        f"| `\"fov\"`: 2 atan({half:g}) = {fov:.4f} degrees, `\"fov_axis\": \"y\"` |",
        f"| lamp: corner, edge ends | {vec(q['corner'])}, {vec(q['end_a'])}, "
        f"{vec(q['end_b'])} | `\"rectangle\"` with that centre and half edges |",
        f"| lamp: normal, radiance | {vec(q['normal'])}, {lamp['emission'][0]:g} "
        "| `\"area\"` emitter, one-sided, black BSDF |",
    ])


def write_outputs(out_dir, results, z_limit, alpha, m, desc, fov):
    os.makedirs(out_dir, exist_ok=True)
    md = ["<!-- Written by scripts/cross-check; do not edit. -->"]
    md += ["<!-- ANCHOR: setup -->",
           f"{WIDTH} x {HEIGHT} pixels, {GRID} x {GRID} regions, {SEEDS} seeds per renderer; "
           f"{m} tests, family-wise alpha {alpha}: a test fails at |z| above {z_limit:.2f}",
           "<!-- ANCHOR_END: setup -->"]
    if desc is not None:
        md += ["<!-- ANCHOR: parameters -->", parameters(desc, fov),
               "<!-- ANCHOR_END: parameters -->"]
    md += ["<!-- ANCHOR: summary -->", summary_table(results, z_limit),
           "<!-- ANCHOR_END: summary -->"]
    for r in results:
        name = anchor(f"{r['scene']}_{r['sampling']}_{r['depth']}")
        md += [f"<!-- ANCHOR: {name} -->",
               f"**{label(r)}**, {SEEDS} x {r['spp']} samples per pixel: region means "
               "crate / Mitsuba (grey), z of the channel furthest off",
               "", region_table(r), f"<!-- ANCHOR_END: {name} -->"]
    with open(os.path.join(out_dir, "10_9_cross_check.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    # The per-pixel z-maps, one line a configuration (book-figures draws them).
    with open(os.path.join(out_dir, "10_9_cross_check_z.csv"), "w") as f:
        f.write(f"# per-pixel z of crate - Mitsuba (grey), {WIDTH} x {HEIGHT}, rows from the top\n")
        for r in results:
            if f"{r['scene']}_{r['sampling']}_{r['depth']}" in ZMAPS:
                f.write(f"{label(r)};" + ",".join(f"{z:.1f}" for z in r["zmap"]) + "\n")


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "time":
        # One timed Mitsuba render (the benchmarks' entry point): see cross_check_time.py.
        import cross_check_time
        return cross_check_time.mitsuba_main(sys.argv[2:])
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=os.path.join(ROOT, "target", "cross-check", "out"),
                        help="where the table fragment and the z-map data go")
    parser.add_argument("--only", action="append", default=[],
                        help="only configurations whose scene_sampling_depth starts so")
    args = parser.parse_args()

    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    scratch = os.path.join(ROOT, "target", "cross-check", "renders")
    os.makedirs(scratch, exist_ok=True)
    start = time.perf_counter()
    descs, exact, fov, cache = {}, {}, None, {}
    results = []
    for scene, sampling, depth, spp in CONFIGS:
        key = f"{scene}_{sampling}_{depth}"
        if args.only and not any(key.startswith(o) for o in args.only):
            continue
        if scene not in descs:
            descs[scene] = json.loads(crate("describe", "--scene", scene,
                                            "--width", str(WIDTH), "--height", str(HEIGHT)))
            exact[scene] = closed_form(descs[scene]) if scene == "two-lights" else None
            if scene == "cornell":
                fov = mitsuba_dict(descs[scene], depth, spp)[1]
        t0 = time.perf_counter()
        results.append(compare(descs[scene], scene, sampling, depth, spp, scratch, exact[scene],
                               cache))
        print(f"  {key}: {time.perf_counter() - t0:.1f} s", file=sys.stderr)
    tests = [t for r in results for t in tests_of(r)]
    m = len(tests)
    p_limit = ALPHA / m
    z_limit = NormalDist().inv_cdf(1 - p_limit / 2)
    seconds = time.perf_counter() - start

    print(f"cross-check: the crate against Mitsuba {mi.__version__} (scalar_rgb), "
          f"{WIDTH} x {HEIGHT}, {GRID} x {GRID} regions, {SEEDS} seeds per renderer")
    print(summary_table(results, z_limit))
    for r in results:
        print()
        print(f"{label(r)}: region means crate / Mitsuba (grey), z of the channel furthest off")
        print(region_table(r))
    write_outputs(args.out, results, z_limit, ALPHA, m, descs.get("cornell"), fov)
    failed = [t for t in tests if t[0] < p_limit]
    worst = max(tests, key=lambda t: abs(t[1]))
    print()
    print(f"{m} tests; family-wise alpha {ALPHA}: each fails below p = {p_limit:.2e}, "
          f"|z| > {z_limit:.2f}; worst |z| {abs(worst[1]):.2f} ({worst[2]})")
    print(f"wrote {args.out}; {seconds:.0f} s")
    if failed:
        print(f"cross-check: FAILED: {len(failed)} of {m} tests beyond |z| = {z_limit:.2f}:",
              file=sys.stderr)
        for p, z, what in sorted(failed)[:20]:
            print(f"  z = {zs(z)} (p = {p:.1e}): {what}", file=sys.stderr)
        return 1
    print(f"cross-check: {m} passed, 0 failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
