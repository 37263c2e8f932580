//! The check of chapter 07's coding exercises: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's function
//! is in `ch07.rs`, beside this file; the harness is `check.rs`.

use glam::Vec3;

use super::check::{Answer, Case, Exercise, Mistake, Outcome, gives, run, v};
use crate::ray::Ray;
use crate::shapes::{Plane, Sphere};

/// Coding exercise 7.1.
pub const RAY_PLANE_T: Exercise = Exercise {
    number: "7.1",
    chapter: "07",
    chapter_title: "Ray/primitive intersections",
    function: "ray_plane_t",
    file: "src/course/exercises/ch07.rs",
};
/// Coding exercise 7.2.
pub const RAY_SPHERE_ROOTS: Exercise = Exercise {
    number: "7.2",
    chapter: "07",
    chapter_title: "Ray/primitive intersections",
    function: "ray_sphere_roots",
    file: "src/course/exercises/ch07.rs",
};

type PlaneArgs = (Vec3, Vec3, Vec3, Vec3);

/// Checks `ray_plane_t(o, d, p0, n)`: the `t` where the line o + t d meets the plane
/// through `p0` with normal `n` (`d` and `n` of unit length), `None` if parallel.
pub fn check_ray_plane_t(f: impl Fn(Vec3, Vec3, Vec3, Vec3) -> Option<f32>) -> Outcome {
    let diagonal = v(1.0, 1.0, 1.0).normalize();
    let cases: Vec<Case<PlaneArgs>> = [
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
    run(
        &cases,
        |&(o, d, p0, n)| {
            Plane::new(p0, n)
                .expect("valid plane")
                .t(&Ray::new(o, d).expect("valid ray"))
        },
        |(o, d, p0, n)| f(o, d, p0, n),
        &[
            Mistake {
                looks_like: &|a: &PlaneArgs, got: &Option<f32>| {
                    a.1.dot(a.3) == 0.0 && got.is_some()
                },
                hint: "the ray is parallel to the plane (d . n = 0): return None, never a NaN or an \
                       infinity",
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
/// unit length) meets the sphere, ascending, or `None` when it misses.
pub fn check_ray_sphere_roots(f: impl Fn(Vec3, Vec3, Vec3, f32) -> Option<(f32, f32)>) -> Outcome {
    let cases: Vec<Case<SphereArgs>> = [
        (v(-3.0, 0.0, 0.0), Vec3::X, Vec3::ZERO, 1.0),
        (Vec3::ZERO, Vec3::X, Vec3::ZERO, 1.0),
        (v(-3.0, 1.0, 0.0), Vec3::X, Vec3::ZERO, 1.0),
        (v(-3.0, 2.0, 0.0), Vec3::X, Vec3::ZERO, 1.0),
        (v(3.0, 0.0, 0.0), Vec3::X, Vec3::ZERO, 1.0),
        (v(1.0, 2.0, -5.0), Vec3::Z, v(1.0, 2.0, 3.0), 2.0),
        (v(0.0, 0.0, 5.0), v(0.0, 0.6, -0.8), v(0.0, 1.0, 0.0), 1.5),
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
    };
    run(
        &cases,
        reference,
        |(o, d, c, r)| f(o, d, c, r),
        &[
            Mistake {
                looks_like: &gives(&|a: &SphereArgs| Some(reference(a).map(|(t0, t1)| (t1, t0)))),
                hint: "return the roots in ascending order, (t0, t1) with t0 <= t1",
            },
            Mistake {
                looks_like: &gives(&|a: &SphereArgs| Some(reference(a).map(|(t0, t1)| (-t1, -t0)))),
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
        ],
        "with f = o - c: a = d . d, b = 2 f . d, c = f . f - r^2; no roots when \
         b^2 - 4ac < 0; otherwise (-b -+ sqrt(b^2 - 4ac)) / 2a, ascending",
    )
}
