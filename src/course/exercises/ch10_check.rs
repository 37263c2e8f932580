//! The check of chapter 10's coding exercise: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's function
//! is in `ch10.rs`, beside this file; the harness is `harness.rs`.
//!
//! The check runs in two rounds. First three statistics over 4096 directions from a
//! fixed random stream (so the check is never flaky): how many directions are not of
//! unit length or lie below the horizon, the mean of cos(theta), and an estimate of
//! the integral of cos(theta) / pi over the hemisphere (1) with the student's own pdf.
//! Any correct cosine sampler passes them. Then exact cases against the crate's
//! `cosine_hemisphere` for fixed points of the unit square.

use std::f32::consts::PI;

use glam::{Vec2, Vec3};

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run};
use crate::pathtrace::Rng;
use crate::sampling::cosine_hemisphere;

/// Coding exercise 10.1.
pub const COSINE_SAMPLE: Exercise = Exercise {
    number: "10.1",
    chapter: "10",
    chapter_title: "Path tracing: the rendering equation",
    function: "cosine_sample",
    file: "src/course/exercises/ch10.rs",
};

// ANCHOR: solution
/// The crate's answer: Malley's direction and its density cos(theta) / pi.
pub fn cosine_sample_reference(u: Vec2) -> (Vec3, f32) {
    let w = cosine_hemisphere(u);
    (w, w.z / PI)
}
// ANCHOR_END: solution

/// Samples in each statistic of the first round.
const SAMPLES: u32 = 4096;

/// A statistic of many samples: equal within 0.02, about five standard errors of
/// the mean of cos(theta) over 4096 samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Statistic(pub f32);

impl Answer for Statistic {
    fn close(&self, other: &Statistic) -> bool {
        (self.0 - other.0).abs() <= 0.02
    }
    fn show(&self) -> String {
        self.0.show()
    }
}

/// The statistics of the first round.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Measure {
    /// Directions not of unit length (to 1e-3) or below the horizon.
    Bad,
    /// The mean of cos(theta), the direction's z: 2/3 for cosine sampling.
    MeanCos,
    /// The mean of (cos(theta) / pi) / pdf: estimates the integral of cos(theta) / pi
    /// over the hemisphere, 1, when the pdf is the directions' true density.
    Integral,
}

/// `measure` of `f` over the fixed sample set.
fn statistic(f: &dyn Fn(Vec2) -> (Vec3, f32), measure: Measure) -> Statistic {
    let mut rng = Rng::for_pixel(10, 0, 1);
    let mut sum = 0.0f64;
    for _ in 0..SAMPLES {
        let (w, pdf) = f(rng.next_vec2());
        sum += match measure {
            Measure::Bad => f64::from(u8::from(!((w.length() - 1.0).abs() <= 1e-3 && w.z >= 0.0))),
            Measure::MeanCos => f64::from(w.z) / f64::from(SAMPLES),
            Measure::Integral => f64::from(w.z / PI / pdf) / f64::from(SAMPLES),
        };
    }
    Statistic(sum as f32)
}

/// Checks `cosine_sample(u)`: a cosine-weighted direction around +Z and its pdf.
pub fn check_cosine_sample(f: impl Fn(Vec2) -> (Vec3, f32)) -> Outcome {
    let stats: Vec<Case<Measure>> = vec![
        (
            format!(
                "{SAMPLES} directions from a fixed stream: how many are not of unit length or lie below the horizon"
            ),
            Measure::Bad,
        ),
        (
            format!(
                "{SAMPLES} directions from a fixed stream: the mean of cos(theta) (2/3 for cosine sampling)"
            ),
            Measure::MeanCos,
        ),
        (
            format!(
                "{SAMPLES} directions from a fixed stream: the mean of (cos(theta)/pi) / pdf, an estimate of the integral of cos(theta)/pi over the hemisphere, 1"
            ),
            Measure::Integral,
        ),
    ];
    let near = |value: f32| {
        move |m: &Measure, got: &Statistic| *m == Measure::MeanCos && (got.0 - value).abs() < 0.02
    };
    let uniform = near(0.5);
    let no_sqrt = near(PI / 4.0);
    let integral_near = |value: f32| {
        move |m: &Measure, got: &Statistic| *m == Measure::Integral && (got.0 - value).abs() < 0.02
    };
    let no_pi = integral_near(1.0 / PI);
    let uniform_pdf = integral_near(4.0 / 3.0);
    let bad = |m: &Measure, _: &Statistic| *m == Measure::Bad;
    let outcome = run(
        &stats,
        |m| statistic(&cosine_sample_reference, *m),
        |m| statistic(&f, m),
        &[
            Mistake {
                looks_like: &bad,
                hint: "a direction must have unit length and z >= 0: with the disc point at radius r = sqrt(u.x), lift it to z = sqrt(1 - r^2) = sqrt(1 - u.x) (the square root goes on z too, not just on r)",
            },
            Mistake {
                looks_like: &uniform,
                hint: "mean cos(theta) of 1/2 is uniform hemisphere sampling (z = u.x); cosine sampling picks a uniform point on the disc, r = sqrt(u.x), and lifts it: z = sqrt(1 - u.x), mean 2/3",
            },
            Mistake {
                looks_like: &no_sqrt,
                hint: "too many directions near the normal: r = u.x crowds the disc's centre; a point uniform over the disc's area has r = sqrt(u.x)",
            },
            Mistake {
                looks_like: &no_pi,
                hint: "the pdf misses 1/pi: the integral of cos(theta) over the hemisphere is pi, so the density is cos(theta) / pi",
            },
            Mistake {
                looks_like: &uniform_pdf,
                hint: "1/(2 pi) is the uniform hemisphere's density; the cosine-weighted directions have pdf cos(theta) / pi",
            },
        ],
        "the directions must be cosine-distributed around +Z and the pdf must be their density, cos(theta) / pi",
    );
    if outcome != Outcome::Pass {
        return outcome;
    }
    let cases: Vec<Case<Vec2>> = [
        (0.0, 0.0),
        (0.25, 0.0),
        (0.5, 0.25),
        (0.75, 0.5),
        (0.36, 0.125),
        (0.9, 0.8),
        (0.999_999, 0.3),
    ]
    .into_iter()
    .map(|(x, y)| (format!("u = ({x}, {y})"), Vec2::new(x, y)))
    .collect();
    let swapped = |u: &Vec2| Some(cosine_sample_reference(Vec2::new(u.y, u.x)));
    let swapped = gives(&swapped);
    let clockwise = |u: &Vec2| {
        let (w, pdf) = cosine_sample_reference(*u);
        Some((Vec3::new(w.x, -w.y, w.z), pdf))
    };
    let clockwise = gives(&clockwise);
    run(
        &cases,
        |u| cosine_sample_reference(*u),
        &f,
        &[
            Mistake {
                looks_like: &swapped,
                hint: "u.x and u.y are swapped: u.x chooses the radius r = sqrt(u.x), u.y the angle phi = 2 pi u.y",
            },
            Mistake {
                looks_like: &clockwise,
                hint: "the angle turns the wrong way: x = r cos(phi), y = r sin(phi) with phi = 2 pi u.y",
            },
        ],
        "a correct cosine sampler, but not the crate's mapping: take r = sqrt(u.x), phi = 2 pi u.y, x = r cos(phi), y = r sin(phi), z = sqrt(1 - u.x)",
    )
}
