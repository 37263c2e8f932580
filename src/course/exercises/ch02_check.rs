//! The checks of chapter 02's coding exercises: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's functions
//! are in `ch02.rs`, beside this file; the harness is `harness.rs`.

use glam::Vec3;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run, v};
use crate::ray::Ray;

/// Coding exercise 2.5.
pub const POINT_AT: Exercise = Exercise {
    number: "2.5",
    chapter: "02",
    chapter_title: "The ray",
    function: "point_at",
    file: "src/course/exercises/ch02.rs",
};
/// Coding exercise 2.6.
pub const T_CLOSEST: Exercise = Exercise {
    number: "2.6",
    chapter: "02",
    chapter_title: "The ray",
    function: "t_closest",
    file: "src/course/exercises/ch02.rs",
};

/// Checks `point_at(o, d, t)`: the point r(t) = o + t d/|d|, `t` a distance, also
/// for directions whose |d|^2 overflows or underflows `f32` (lesson 02's last
/// pitfall), which `Ray::new` accepts.
pub fn check_point_at(
    f: impl Fn(Vec3, Vec3, f32) -> Vec3 + Send + Sync + 'static,
) -> Outcome {
    point_at_checked(Box::new(f))
}

/// [`check_point_at`] for the answer as a trait object: compiled once, here, not again
/// for every closure a test passes (see [`super::harness`]).
fn point_at_checked(f: Box<dyn Fn(Vec3, Vec3, f32) -> Vec3 + Send + Sync>) -> Outcome {
    let cases: Vec<Case<(Vec3, Vec3, f32)>> = [
        (v(1.0, 1.0, 0.0), v(4.0, 3.0, 0.0), 0.0, None),
        (v(1.0, 1.0, 0.0), v(4.0, 3.0, 0.0), 5.0, None),
        (v(1.0, 1.0, 0.0), v(4.0, 3.0, 0.0), -2.0, None),
        (v(1.0, 1.0, 0.0), v(8.0, 6.0, 0.0), 2.5, None),
        (v(1.0, 2.0, 3.0), v(0.0, 0.0, -2.0), 4.0, None),
        (v(-1.0, 0.5, 2.0), v(1.0, 2.0, 2.0), 3.0, None),
        // Lesson 02's last pitfall: |d|^2 leaves f32's range, though d is a fine
        // direction (Ray::new accepts it).
        (
            v(1.0, 1.0, 0.0),
            v(1e30, 1e30, 0.0),
            -2.0,
            Some("d = (1e30, 1e30, 0), so long that |d|^2 overflows f32 to infinity"),
        ),
        (
            v(1.0, 1.0, 0.0),
            v(1e-30, 1e-30, 0.0),
            2.0,
            Some("d = (1e-30, 1e-30, 0), so short that |d|^2 underflows f32 to 0"),
        ),
    ]
    .into_iter()
    .map(|(o, d, t, extreme)| {
        let d_shown =
            extreme.map_or_else(|| format!("d = {}", d.show()), str::to_string);
        (
            format!("o = {}, {d_shown}, t = {}", o.show(), t.show()),
            (o, d, t),
        )
    })
    .collect();
    run(
        &cases,
        |&(o, d, t)| Ray::new(o, d).expect("valid ray").at(t),
        move |(o, d, t)| f(o, d, t),
        &[
            Mistake {
                looks_like: &|&(o, d, t): &(Vec3, Vec3, f32), got: &Vec3| {
                    !d.length_squared().is_normal()
                        && (got.close(&(o + t * d.normalize())) || !got.is_finite())
                },
                hint: "|d|^2 leaves f32's range for this direction (it overflows to infinity or \
                       underflows to 0), so d / |d| (d.normalize()) is no unit vector: divide d by \
                       its largest component first, d / max(|d_x|, |d_y|, |d_z|), which brings it to \
                       a length between 1 and 2, then normalise (lesson 02's last pitfall)",
            },
            Mistake {
                looks_like: &gives(&|&(o, d, t): &(Vec3, Vec3, f32)| Some(o + t * d)),
                hint: "t is a distance only along a unit direction: use d / |d| (d.normalize()), not d",
            },
            Mistake {
                looks_like: &gives(&|&(_, d, t): &(Vec3, Vec3, f32)| {
                    Some(t * d.normalize())
                }),
                hint: "the ray starts at o: r(t) = o + t d/|d|",
            },
            Mistake {
                looks_like: &gives(&|&(o, d, t): &(Vec3, Vec3, f32)| {
                    Some(o - t * d.normalize())
                }),
                hint: "positive t goes forward, along d: r(t) = o + t d/|d|",
            },
        ],
        "r(t) = o + t d/|d|",
    )
}

/// The arguments of `t_closest`: the ray and the point.
type ClosestArgs = (Ray, Vec3);

/// Checks `t_closest(ray, p)`: the `t` of the point of the ray's line closest to `p`,
/// (p - o) . d for the unit direction d.
pub fn check_t_closest(
    f: impl Fn(&Ray, Vec3) -> f32 + Send + Sync + 'static,
) -> Outcome {
    t_closest_checked(Box::new(f))
}

/// [`check_t_closest`] for the answer as a trait object: compiled once, here, not again
/// for every closure a test passes (see [`super::harness`]).
fn t_closest_checked(f: Box<dyn Fn(&Ray, Vec3) -> f32 + Send + Sync>) -> Outcome {
    let ray = |o, d| Ray::new(o, d).expect("valid ray");
    let lesson = ray(v(1.0, 1.0, 0.0), v(4.0, 3.0, 0.0));
    let cases: Vec<Case<ClosestArgs>> = [
        ("on the ray, 5 ahead", lesson, v(5.0, 4.0, 0.0)),
        ("the origin itself", lesson, v(1.0, 1.0, 0.0)),
        (
            "off the ray, beside the point at t = 5",
            lesson,
            v(2.0, 5.5, 0.0),
        ),
        ("off the ray, behind the origin", lesson, v(-2.0, 1.0, 2.0)),
        (
            "on the x axis, where the ray crosses y = 0",
            lesson,
            v(-1.0 / 3.0, 0.0, 0.0),
        ),
        (
            "a ray along -Z, a point beside it",
            ray(v(1.0, 2.0, 3.0), v(0.0, 0.0, -2.0)),
            v(4.0, -2.0, -1.0),
        ),
    ]
    .into_iter()
    .map(|(what, ray, p)| {
        let case = format!(
            "ray from {} along {}, p = {}: {what}",
            ray.origin().show(),
            ray.direction().show(),
            p.show()
        );
        (case, (ray, p))
    })
    .collect();
    let on_line = |&(ray, p): &ClosestArgs| (p - ray.origin()).dot(ray.direction());
    run(
        &cases,
        |&(ray, p)| ray.t_closest_to(p),
        move |(ray, p)| f(&ray, p),
        &[
            Mistake {
                looks_like: &gives(&|a: &ClosestArgs| Some(-on_line(a))),
                hint: "the sign is wrong: t = (p - o) . d, from the origin to the point",
            },
            Mistake {
                looks_like: &gives(&|&(ray, p): &ClosestArgs| {
                    Some((p - ray.origin()).length())
                }),
                hint: "|p - o| is the distance to p, not its t: the two agree only for a point \
                       ahead on the ray. Project p - o onto the direction: t = (p - o) . d",
            },
            Mistake {
                looks_like: &gives(&|a: &ClosestArgs| Some(on_line(a).max(0.0))),
                hint: "the line goes on behind the origin: a point behind it has a negative t; \
                       do not clamp it to 0",
            },
            Mistake {
                looks_like: &gives(&|&(ray, p): &ClosestArgs| {
                    let to_p = p - ray.origin();
                    (to_p.length() > 0.0)
                        .then(|| to_p.dot(ray.direction()) / to_p.length())
                }),
                hint: "dividing by |p - o| gives the cosine of the angle at o, not a distance: \
                       d already has length 1, so t = (p - o) . d",
            },
        ],
        "t = (p - o) . d: the projection of p - o onto the unit direction",
    )
}
