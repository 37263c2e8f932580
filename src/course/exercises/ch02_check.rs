//! The check of chapter 02's coding exercise: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's function
//! is in `ch02.rs`, beside this file; the harness is `harness.rs`.

use glam::Vec3;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run, v};
use crate::ray::Ray;

/// Coding exercise 2.1.
pub const POINT_AT: Exercise = Exercise {
    number: "2.1",
    chapter: "02",
    chapter_title: "The ray",
    function: "point_at",
    file: "src/course/exercises/ch02.rs",
};

/// Checks `point_at(o, d, t)`: the point r(t) = o + t d/|d|, `t` a distance.
pub fn check_point_at(f: impl Fn(Vec3, Vec3, f32) -> Vec3) -> Outcome {
    let cases: Vec<Case<(Vec3, Vec3, f32)>> = [
        (v(1.0, 1.0, 0.0), v(4.0, 3.0, 0.0), 0.0),
        (v(1.0, 1.0, 0.0), v(4.0, 3.0, 0.0), 5.0),
        (v(1.0, 1.0, 0.0), v(4.0, 3.0, 0.0), -2.0),
        (v(1.0, 1.0, 0.0), v(8.0, 6.0, 0.0), 2.5),
        (v(1.0, 2.0, 3.0), v(0.0, 0.0, -2.0), 4.0),
        (v(-1.0, 0.5, 2.0), v(1.0, 2.0, 2.0), 3.0),
    ]
    .into_iter()
    .map(|(o, d, t)| {
        (
            format!("o = {}, d = {}, t = {}", o.show(), d.show(), t.show()),
            (o, d, t),
        )
    })
    .collect();
    run(
        &cases,
        |&(o, d, t)| Ray::new(o, d).expect("valid ray").at(t),
        |(o, d, t)| f(o, d, t),
        &[
            Mistake {
                looks_like: &gives(&|&(o, d, t): &(Vec3, Vec3, f32)| Some(o + t * d)),
                hint: "t is a distance only along a unit direction: use d / |d| (d.normalize()), not d",
            },
            Mistake {
                looks_like: &gives(&|&(_, d, t): &(Vec3, Vec3, f32)| Some(t * d.normalize())),
                hint: "the ray starts at o: r(t) = o + t d/|d|",
            },
            Mistake {
                looks_like: &gives(&|&(o, d, t): &(Vec3, Vec3, f32)| Some(o - t * d.normalize())),
                hint: "positive t goes forward, along d: r(t) = o + t d/|d|",
            },
        ],
        "r(t) = o + t d/|d|",
    )
}
