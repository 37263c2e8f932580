//! The check of chapter 07's coding exercises: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's function
//! is in `ch07.rs`, beside this file; the harness is `harness.rs`.

use glam::Vec3;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run, v};
use crate::ray::{Interval, Ray};
use crate::shapes::{Plane, Sphere, Triangle};

/// Coding exercise 7.16.
pub const RAY_PLANE_T: Exercise = Exercise {
    number: "7.16",
    chapter: "07",
    chapter_title: "Ray/primitive intersections",
    function: "ray_plane_t",
    file: "src/course/exercises/ch07.rs",
};
/// Coding exercise 7.17.
pub const RAY_SPHERE_ROOTS: Exercise = Exercise {
    number: "7.17",
    chapter: "07",
    chapter_title: "Ray/primitive intersections",
    function: "ray_sphere_roots",
    file: "src/course/exercises/ch07.rs",
};
/// Coding exercise 7.18.
pub const MOLLER_TRUMBORE: Exercise = Exercise {
    number: "7.18",
    chapter: "07",
    chapter_title: "Ray/primitive intersections",
    function: "moller_trumbore",
    file: "src/course/exercises/ch07.rs",
};

type PlaneArgs = (Vec3, Vec3, Vec3, Vec3);

/// Checks `ray_plane_t(o, d, p0, n)`: the `t` where the line o + t d meets the plane
/// through `p0` with normal `n` (`d` and `n` of unit length), `None` if parallel.
pub fn check_ray_plane_t(
    f: impl Fn(Vec3, Vec3, Vec3, Vec3) -> Option<f32> + Send + Sync + 'static,
) -> Outcome {
    ray_plane_t_checked(Box::new(f))
}

/// [`check_ray_plane_t`] for the answer as a trait object: compiled once, here, not
/// again for every closure a test passes (see [`super::harness`]).
fn ray_plane_t_checked(
    f: Box<dyn Fn(Vec3, Vec3, Vec3, Vec3) -> Option<f32> + Send + Sync>,
) -> Outcome {
    let diagonal = v(1.0, 1.0, 1.0).normalize();
    let mut cases: Vec<Case<PlaneArgs>> = [
        (v(0.0, 3.0, 0.0), -Vec3::Y, Vec3::ZERO, Vec3::Y),
        (
            v(0.0, 3.0, 9.0),
            v(0.0, -2.2, -9.0).normalize(),
            Vec3::ZERO,
            Vec3::Y,
        ),
        (v(0.0, 3.0, 0.0), -Vec3::Y, Vec3::ZERO, -Vec3::Y),
        (v(0.0, -2.0, 0.0), -Vec3::Y, Vec3::ZERO, Vec3::Y),
        (v(0.0, 3.0, 0.0), Vec3::X, Vec3::ZERO, Vec3::Y),
        (Vec3::ZERO, diagonal, v(1.0, 2.0, 3.0), diagonal),
        (
            v(5.0, 1.0, -2.0),
            v(0.6, 0.0, 0.8),
            v(0.0, 0.0, 4.0),
            Vec3::Z,
        ),
    ]
    .into_iter()
    .map(|(o, d, p0, n)| {
        (
            format!(
                "o = {}, d = {}, plane through {} with normal {}",
                o.show(),
                d.show(),
                p0.show(),
                n.show()
            ),
            (o, d, p0, n),
        )
    })
    .collect();
    // The plane's pitfall "dividing before checking": d . n = -1e-30 is not 0, but
    // 1e9 / 1e-30 overflows f32.
    let grazing = (v(0.0, 1e9, 0.0), v(1.0, -1e-30, 0.0), Vec3::ZERO, Vec3::Y);
    cases.push((
        "o = (0, 1e9, 0), d = (1, -1e-30, 0): so nearly parallel to the plane through \
         (0, 0, 0) with normal (0, 1, 0) that t = 1e9 / 1e-30 overflows f32"
            .to_string(),
        grazing,
    ));
    run(
        &cases,
        |&(o, d, p0, n)| {
            Plane::new(p0, n)
                .expect("valid plane")
                .t(&Ray::new(o, d).expect("valid ray"))
        },
        move |(o, d, p0, n)| f(o, d, p0, n),
        &[
            Mistake {
                looks_like: &|a: &PlaneArgs, got: &Option<f32>| {
                    a.1.dot(a.3) == 0.0 && got.is_some()
                },
                hint: "the ray is parallel to the plane (d . n = 0): return None, never a NaN or an \
                       infinity",
            },
            Mistake {
                looks_like: &|_: &PlaneArgs, got: &Option<f32>| {
                    got.is_some_and(f32::is_infinite)
                },
                hint: "refuse a quotient that is not finite: d . n is not 0 here, but so small \
                       that (p0 - o) . n / (d . n) overflows to infinity, which a later \
                       comparison such as t > t_min lets through (the plane's pitfall \
                       \"dividing before checking\")",
            },
            Mistake {
                looks_like: &gives(&|&(o, d, p0, n): &PlaneArgs| {
                    Some(Some((o - p0).dot(n) / d.dot(n)))
                }),
                hint: "the sign is wrong: t = (p0 - o) . n / (d . n)",
            },
            Mistake {
                looks_like: &|&(o, d, p0, n): &PlaneArgs, got: &Option<f32>| {
                    got.is_none() && (p0 - o).dot(n) / d.dot(n) < 0.0
                },
                hint: "return the crossing even when t < 0 (behind the origin): choosing \
                       t_min < t < t_max is the hit function's job",
            },
        ],
        "t = (p0 - o) . n / (d . n), None when d . n = 0",
    )
}

type SphereArgs = (Vec3, Vec3, Vec3, f32);

/// Checks `ray_sphere_roots(o, d, c, r)`: both `t` where the line o + t d (`d` of
/// unit length) meets the sphere, ascending, or `None` when it misses. STABILITY S2's
/// rays from the centre and the surface (b = 0, c = 0) come before the last cases,
/// S1's small sphere far away, which the school formula gets wrong.
pub fn check_ray_sphere_roots(
    f: impl Fn(Vec3, Vec3, Vec3, f32) -> Option<(f32, f32)> + Send + Sync + 'static,
) -> Outcome {
    ray_sphere_roots_checked(Box::new(f))
}

/// [`check_ray_sphere_roots`] for the answer as a trait object: compiled once, here,
/// not again for every closure a test passes (see [`super::harness`]).
fn ray_sphere_roots_checked(
    f: Box<dyn Fn(Vec3, Vec3, Vec3, f32) -> Option<(f32, f32)> + Send + Sync>,
) -> Outcome {
    let aim = v(0.3, 0.2, -1.0).normalize();
    let far = 1e4 * aim;
    let across = aim.cross(Vec3::Y).normalize();
    let cases: Vec<Case<SphereArgs>> = [
        (v(-3.0, 0.0, 0.0), Vec3::X, Vec3::ZERO, 1.0),
        (Vec3::ZERO, Vec3::X, Vec3::ZERO, 1.0),
        (v(-3.0, 1.0, 0.0), Vec3::X, Vec3::ZERO, 1.0),
        (v(-3.0, 2.0, 0.0), Vec3::X, Vec3::ZERO, 1.0),
        (v(3.0, 0.0, 0.0), Vec3::X, Vec3::ZERO, 1.0),
        (v(1.0, 2.0, -5.0), Vec3::Z, v(1.0, 2.0, 3.0), 2.0),
        (v(0.0, 0.0, 5.0), v(0.0, 0.6, -0.8), v(0.0, 1.0, 0.0), 1.5),
        // STABILITY S2: the sphere of radius 2 around (1, 2, 3), from its centre
        // (b = 0), and from its surface point (1, 2, 1) towards the centre, away from
        // it (c = 0) and along a tangent (b = 0 and c = 0).
        (v(1.0, 2.0, 3.0), Vec3::Y, v(1.0, 2.0, 3.0), 2.0),
        (v(1.0, 2.0, 1.0), Vec3::Z, v(1.0, 2.0, 3.0), 2.0),
        (v(1.0, 2.0, 1.0), -Vec3::Z, v(1.0, 2.0, 3.0), 2.0),
        (v(1.0, 2.0, 1.0), Vec3::X, v(1.0, 2.0, 3.0), 2.0),
        // STABILITY S1: a unit sphere 1e4 away, rays aimed at its centre, 0.6 r off
        // it and 2 r off it (a miss). The textbook discriminant cancels on all three.
        (Vec3::ZERO, aim, far, 1.0),
        (Vec3::ZERO, (far + 0.6 * across).normalize(), far, 1.0),
        (Vec3::ZERO, (far - 2.0 * across).normalize(), far, 1.0),
    ]
    .into_iter()
    .map(|(o, d, c, r)| {
        (
            format!(
                "o = {}, d = {}, sphere around {} with radius {}",
                o.show(),
                d.show(),
                c.show(),
                r.show()
            ),
            (o, d, c, r),
        )
    })
    .collect();
    let reference = |&(o, d, c, r): &SphereArgs| {
        Sphere::new(c, r)
            .expect("valid sphere")
            .roots_stable(&Ray::new(o, d).expect("valid ray"))
            .pair()
    };
    run(
        &cases,
        reference,
        move |(o, d, c, r)| f(o, d, c, r),
        &[
            Mistake {
                looks_like: &gives(&|a: &SphereArgs| {
                    Some(reference(a).map(|(t0, t1)| (t1, t0)))
                }),
                hint: "return the roots in ascending order, (t0, t1) with t0 <= t1",
            },
            Mistake {
                looks_like: &gives(&|a: &SphereArgs| {
                    Some(reference(a).map(|(t0, t1)| (-t1, -t0)))
                }),
                hint: "the signs are flipped: f = o - c goes from the centre to the ray's origin, \
                       and b = 2 f . d",
            },
            Mistake {
                looks_like: &|a: &SphereArgs, got: &Option<(f32, f32)>| {
                    got.is_none() && reference(a).is_some_and(|(t0, _)| t0 < 0.0)
                },
                hint: "return both roots of the line, even negative ones (behind the origin); \
                       choosing t_min < t < t_max is the hit function's job",
            },
            Mistake {
                looks_like: &|&(o, d, c, r): &SphereArgs, got: &Option<(f32, f32)>| {
                    let f = o - c;
                    f.dot(d) == 0.0
                        && f.dot(f) == r * r
                        && got.is_some_and(|(t0, t1)| t0.is_nan() || t1.is_nan())
                },
                hint: "the line only touches the sphere, at its origin (STABILITY S2): b = 0 and \
                       c = 0, so the discriminant is 0 and q = -(b + sign(b) sqrt(0)) / 2 = 0, \
                       and c/q is 0/0 = NaN. When q = 0 the double root is 0: return (0, 0)",
            },
            Mistake {
                looks_like: &|&(o, d, c, _): &SphereArgs, got: &Option<(f32, f32)>| {
                    (o - c).dot(d) == 0.0
                        && got
                            .is_some_and(|(t0, t1)| !(t0.is_finite() && t1.is_finite()))
                },
                hint: "b = 2 f . d is 0 here (STABILITY S2: the origin at the centre, or a \
                       tangent): a sign function with sign(0) = 0 makes \
                       q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2 = 0, and the root c/q infinite or \
                       NaN. Take sign(0) = +1 (b >= 0), as f32::signum does for +0",
            },
            Mistake {
                looks_like: &|&(o, _, c, r): &SphereArgs, _: &Option<(f32, f32)>| {
                    (c - o).length() > 1e3 * r
                },
                hint: "the sphere is small and far away (D/r = 1e4, STABILITY S1): b^2 and 4ac \
                       are both about 4 D^2, and the school formula's b^2 - 4ac loses their \
                       small difference to rounding. Compute the discriminant as \
                       b^2 - 4ac = 4 (r^2 - |f - (f . d) d|^2), with no big numbers subtracted, \
                       and the roots in the stable form q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2 \
                       (sign(0) = +1), t = c/q and q/a",
            },
        ],
        "with f = o - c: a = d . d, b = 2 f . d, c = f . f - r^2; no roots when \
         r^2 - |f - (f . d) d|^2 < 0; otherwise q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2 \
         and the roots c/q and q/a, ascending",
    )
}

type TriangleArgs = (Vec3, Vec3, Vec3, Vec3, Vec3);

/// det, b1 and b2 of Möller-Trumbore for these arguments, in f64 (to recognise
/// mistakes, not to grade): det = e1 . (d x e2), b1 and b2 by Cramer's rule.
fn cramer(&(o, d, v0, v1, v2): &TriangleArgs) -> (f64, f64, f64) {
    let [o, d, v0, v1, v2] = [o, d, v0, v1, v2].map(Vec3::as_dvec3);
    let (e1, e2, s) = (v1 - v0, v2 - v0, o - v0);
    let p = d.cross(e2);
    let det = e1.dot(p);
    let q = s.cross(e1);
    (det, s.dot(p) / det, d.dot(q) / det)
}

/// Checks `moller_trumbore(o, d, v0, v1, v2)`: `(t, b1, b2)` of the hit with t > 0 of
/// the ray o + t d (`d` of unit length) on the two-sided triangle, or `None`.
///
/// Besides single triangles, the cases shoot rays exactly through the edge two
/// triangles of a square share and through the vertex four triangles of a fan share.
/// Their coordinates are small integers, so every step is exact in `f32`: each
/// triangle finds a barycentric weight of exactly 0 or 1, and an inclusive test hits
/// every one of them, as the crate's does. (With rounding, Möller-Trumbore can still
/// let such a ray through: STABILITY S4, S5, which the watertight test fixes.)
pub fn check_moller_trumbore(
    f: impl Fn(Vec3, Vec3, Vec3, Vec3, Vec3) -> Option<(f32, f32, f32)>
    + Send
    + Sync
    + 'static,
) -> Outcome {
    moller_trumbore_checked(Box::new(f))
}

/// [`check_moller_trumbore`] for the answer as a trait object: compiled once, here, not
/// again for every closure a test passes (see [`super::harness`]).
fn moller_trumbore_checked(
    f: Box<
        dyn Fn(Vec3, Vec3, Vec3, Vec3, Vec3) -> Option<(f32, f32, f32)> + Send + Sync,
    >,
) -> Outcome {
    let down = -Vec3::Z;
    let unit = (Vec3::ZERO, Vec3::X, Vec3::Y);
    let lesson = (v(1.0, -1.0, -1.0), v(1.0, 1.5, 0.0), v(1.0, -1.0, 1.0));
    let diagonal = v(1.0, 1.0, 1.0).normalize();
    let corners = (Vec3::X, Vec3::Y, Vec3::Z);
    let hub = v(1.0, 1.0, 0.0);
    let (a, b, c, e) = (
        Vec3::ZERO,
        v(2.0, 0.0, 0.0),
        v(2.0, 2.0, 0.0),
        v(0.0, 2.0, 0.0),
    );
    let cases: Vec<Case<TriangleArgs>> = [
        ("front face", v(0.25, 0.5, 5.0), down, unit),
        ("the lesson's triangle, back face", v(-2.0, 0.2, 0.0), v(1.0, 0.1, 0.0).normalize(), lesson),
        ("outside, b1 + b2 > 1", v(0.75, 0.5, 5.0), down, unit),
        ("behind the origin", v(0.25, 0.5, 5.0), Vec3::Z, unit),
        ("parallel, in the triangle's plane", v(-1.0, 0.25, 0.0), Vec3::X, unit),
        ("parallel, above the plane", v(-1.0, 0.25, 1.0), Vec3::X, unit),
        ("through the centroid", Vec3::ZERO, diagonal, corners),
        ("square (0,0)-(2,2) split on its diagonal, triangle 1 of 2, ray through the shared edge", v(1.0, 1.0, 3.0), down, (a, b, c)),
        ("square (0,0)-(2,2) split on its diagonal, triangle 2 of 2, ray through the shared edge", v(1.0, 1.0, 3.0), down, (e, a, c)),
        ("fan of 4 around (1, 1, 0), triangle 1, ray through the shared vertex", v(1.0, 1.0, 3.0), down, (hub, a, b)),
        ("fan of 4 around (1, 1, 0), triangle 2, ray through the shared vertex", v(1.0, 1.0, 3.0), down, (b, c, hub)),
        ("fan of 4 around (1, 1, 0), triangle 3, ray through the shared vertex", v(1.0, 1.0, 3.0), down, (e, hub, c)),
        ("fan of 4 around (1, 1, 0), triangle 4, ray through the shared vertex", v(1.0, 1.0, 3.0), down, (e, a, hub)),
    ]
    .into_iter()
    .map(|(what, o, d, (v0, v1, v2))| {
        (
            format!(
                "{what}: o = {}, d = {}, v0 = {}, v1 = {}, v2 = {}",
                o.show(),
                d.show(),
                v0.show(),
                v1.show(),
                v2.show()
            ),
            (o, d, v0, v1, v2),
        )
    })
    .collect();
    let reference = |&(o, d, v0, v1, v2): &TriangleArgs| {
        Triangle::new(v0, v1, v2)
            .expect("valid triangle")
            .moller_trumbore(&Ray::new(o, d).expect("valid ray"), Interval::AHEAD)
            .map(|c| (c.t, c.b[1], c.b[2]))
    };
    let hits_inside = |a: &TriangleArgs| {
        reference(a).is_some_and(|(_, b1, b2)| b1 > 0.0 && b2 > 0.0 && b1 + b2 < 1.0)
    };
    run(
        &cases,
        reference,
        move |(o, d, v0, v1, v2)| f(o, d, v0, v1, v2),
        &[
            Mistake {
                looks_like: &|a: &TriangleArgs, got: &Option<(f32, f32, f32)>| {
                    got.is_some_and(|(t, b1, b2)| {
                        !(t.is_finite() && b1.is_finite() && b2.is_finite())
                    }) || (cramer(a).0 == 0.0 && got.is_some())
                },
                hint: "the ray is parallel to the triangle's plane, det = e1 . (d x e2) = 0: \
                       return None before dividing by det (1/0 is inf, 0 * inf is NaN, and a \
                       NaN passes every comparison)",
            },
            Mistake {
                looks_like: &|_: &TriangleArgs, got: &Option<(f32, f32, f32)>| {
                    got.is_some_and(|(t, ..)| t <= 0.0)
                },
                hint: "the triangle is behind the ray's origin: a hit needs t > 0",
            },
            Mistake {
                looks_like: &|a: &TriangleArgs, got: &Option<(f32, f32, f32)>| {
                    let (_, b1, b2) = cramer(a);
                    got.is_some() && b1 >= 0.0 && b2 >= 0.0 && b1 + b2 > 1.0
                },
                hint: "b1 >= 0 and b2 >= 0 are not enough: also require b1 + b2 <= 1 (the weight \
                       of v0, b0 = 1 - b1 - b2, must not be negative either)",
            },
            Mistake {
                looks_like: &|a: &TriangleArgs, got: &Option<(f32, f32, f32)>| {
                    got.is_none() && reference(a).is_some() && !hits_inside(a)
                },
                hint: "the ray goes through an edge or a corner this triangle shares with its \
                       neighbours: count the boundary as inside (b1 >= 0, b2 >= 0, \
                       b1 + b2 <= 1), or the ray slips through a crack between them",
            },
            Mistake {
                looks_like: &|a: &TriangleArgs, got: &Option<(f32, f32, f32)>| {
                    got.is_none() && hits_inside(a) && cramer(a).0 < 0.0
                },
                hint: "this ray meets the triangle from its back, where det = e1 . (d x e2) < 0: \
                       only det = 0 (a parallel ray) means no hit; the sign of det just tells \
                       the side the ray comes from",
            },
            Mistake {
                looks_like: &gives(&|a: &TriangleArgs| {
                    Some(reference(a).map(|(t, b1, b2)| (t, b2, b1)))
                }),
                hint: "b1 and b2 are swapped: b1 = s . p / det is the weight of v1, \
                       b2 = d . q / det the weight of v2",
            },
        ],
        "with e1 = v1 - v0, e2 = v2 - v0, s = o - v0, p = d x e2, q = s x e1: det = e1 . p \
         (None if 0), b1 = s . p / det, b2 = d . q / det, t = e2 . q / det; a hit needs \
         b1 >= 0, b2 >= 0, b1 + b2 <= 1 and t > 0",
    )
}
