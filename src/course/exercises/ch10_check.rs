//! The checks of chapter 10's coding exercises: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's functions
//! are in `ch10.rs`, beside this file; the harness is `harness.rs`.
//!
//! The check of exercise 10.11 runs in two rounds. First three statistics over 4096
//! directions from a fixed random stream (so the check is never flaky): how many
//! directions are not of unit length or lie below the horizon, the mean of cos(theta),
//! and an estimate of the integral of cos(theta) / pi over the hemisphere (1) with the
//! student's own pdf. Any correct cosine sampler passes them. Then exact cases against
//! the crate's `cosine_hemisphere` for fixed points of the unit square.

use std::f32::consts::PI;

use glam::{Vec2, Vec3};

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run, v};
use crate::material::diffuse_brdf;
use crate::rng::Rng;
use crate::sampling::cosine_hemisphere;

/// Coding exercise 10.11.
pub const COSINE_SAMPLE: Exercise = Exercise {
    number: "10.11",
    chapter: "10",
    chapter_title: "Path tracing: the rendering equation",
    function: "cosine_sample",
    file: "src/course/exercises/ch10.rs",
};
/// Coding exercise 10.12.
pub const BOUNCE_WEIGHT: Exercise = Exercise {
    number: "10.12",
    chapter: "10",
    chapter_title: "Path tracing: the rendering equation",
    function: "bounce_weight",
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
            Measure::Bad => {
                f64::from(u8::from(!((w.length() - 1.0).abs() <= 1e-3 && w.z >= 0.0)))
            }
            Measure::MeanCos => f64::from(w.z) / f64::from(SAMPLES),
            Measure::Integral => f64::from(w.z / PI / pdf) / f64::from(SAMPLES),
        };
    }
    Statistic(sum as f32)
}

/// Checks `cosine_sample(u)`: a cosine-weighted direction around +Z and its pdf.
pub fn check_cosine_sample(
    f: impl Fn(Vec2) -> (Vec3, f32) + Send + Sync + 'static,
) -> Outcome {
    cosine_sample_checked(Box::new(f))
}

/// [`check_cosine_sample`] for the answer as a trait object: compiled once, here, not
/// again for every closure a test passes (see [`super::harness`]).
fn cosine_sample_checked(f: Box<dyn Fn(Vec2) -> (Vec3, f32) + Send + Sync>) -> Outcome {
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
        move |m: &Measure, got: &Statistic| {
            *m == Measure::MeanCos && (got.0 - value).abs() < 0.02
        }
    };
    let uniform = near(0.5);
    let no_sqrt = near(PI / 4.0);
    let integral_near = |value: f32| {
        move |m: &Measure, got: &Statistic| {
            *m == Measure::Integral && (got.0 - value).abs() < 0.02
        }
    };
    let no_pi = integral_near(1.0 / PI);
    let uniform_pdf = integral_near(4.0 / 3.0);
    let bad = |m: &Measure, _: &Statistic| *m == Measure::Bad;
    // Both rounds run `f`, each on a thread of its own: they share it.
    let f = std::sync::Arc::new(f);
    let first = std::sync::Arc::clone(&f);
    let outcome = run(
        &stats,
        |m| statistic(&cosine_sample_reference, *m),
        move |m| statistic(&*first, m),
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
        move |u| f(u),
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

// ANCHOR: bounce_weight
/// A worked solution of exercise 10.12: f_r cos(theta) / pdf with Lambert's
/// f_r = albedo / pi, and nothing for a direction below the surface or of density 0.
pub fn bounce_weight_solution(albedo: Vec3, n: Vec3, wi: Vec3, pdf: f32) -> Vec3 {
    let cos_theta = n.dot(wi);
    if cos_theta <= 0.0 || pdf <= 0.0 {
        return Vec3::ZERO;
    }
    diffuse_brdf(albedo) * cos_theta / pdf
}
// ANCHOR_END: bounce_weight

/// The arguments of `bounce_weight`: albedo, n, wi, pdf.
type BounceArgs = (Vec3, Vec3, Vec3, f32);

/// Checks `bounce_weight(albedo, n, wi, pdf)`: f_r cos(theta) / pdf for Lambert's
/// f_r = albedo / pi, zero below the surface and for a density of 0.
pub fn check_bounce_weight(
    f: impl Fn(Vec3, Vec3, Vec3, f32) -> Vec3 + Send + Sync + 'static,
) -> Outcome {
    bounce_weight_checked(Box::new(f))
}

/// [`check_bounce_weight`] for the answer as a trait object: compiled once, here, not
/// again for every closure a test passes (see [`super::harness`]).
fn bounce_weight_checked(
    f: Box<dyn Fn(Vec3, Vec3, Vec3, f32) -> Vec3 + Send + Sync>,
) -> Outcome {
    let grey = Vec3::splat(0.5);
    let red = v(0.75, 0.25, 0.25);
    let up = Vec3::Z;
    let tilted = v(0.0, 0.6, 0.8);
    let slanted = v(0.6, 0.0, 0.8);
    let cases: Vec<Case<BounceArgs>> = [
        ("cosine sampling, pdf = cos/pi", grey, up, slanted, 0.8 / PI),
        (
            "uniform sampling, pdf = 1/(2 pi)",
            red,
            up,
            slanted,
            1.0 / (2.0 * PI),
        ),
        (
            "uniform sampling, straight up",
            red,
            up,
            up,
            1.0 / (2.0 * PI),
        ),
        (
            "another density (light sampling)",
            red,
            tilted,
            v(0.0, 0.0, 1.0),
            2.5,
        ),
        (
            "cosine sampling around a tilted normal",
            grey,
            tilted,
            tilted,
            1.0 / PI,
        ),
        (
            "a direction below the surface",
            red,
            up,
            v(0.6, 0.0, -0.8),
            1.0 / (2.0 * PI),
        ),
        (
            "a direction of density 0, at the horizon",
            grey,
            up,
            v(1.0, 0.0, 0.0),
            0.0,
        ),
        (
            "a direction above the surface that the sampler cannot draw: density 0",
            red,
            up,
            slanted,
            0.0,
        ),
    ]
    .into_iter()
    .map(|(what, albedo, n, wi, pdf)| {
        let case = format!(
            "{what}: albedo = {}, n = {}, wi = {}, pdf = {}",
            albedo.show(),
            n.show(),
            wi.show(),
            pdf.show()
        );
        (case, (albedo, n, wi, pdf))
    })
    .collect();
    let plain = |&(albedo, n, wi, pdf): &BounceArgs| albedo / PI * n.dot(wi) / pdf;
    let right =
        |&(albedo, n, wi, pdf): &BounceArgs| bounce_weight_solution(albedo, n, wi, pdf);
    run(
        &cases,
        right,
        move |(albedo, n, wi, pdf)| f(albedo, n, wi, pdf),
        &[
            Mistake {
                looks_like: &|_: &BounceArgs, got: &Vec3| !got.is_finite(),
                hint: "never divide by a density of 0: a direction the sampler cannot draw \
                       carries nothing, return zero (an infinity or a NaN would spread to the \
                       whole pixel)",
            },
            Mistake {
                looks_like: &gives(&|a: &BounceArgs| Some(plain(a))),
                hint: "a direction below the surface (cos(theta) <= 0) carries nothing: a \
                       surface that reflects does not send light through itself, return zero",
            },
            Mistake {
                looks_like: &gives(&|a: &BounceArgs| Some(right(a) * PI)),
                hint: "Lambert's BRDF is albedo / pi, not the albedo: the cosine integrates to \
                       pi over the hemisphere, so without the 1/pi a white surface reflects pi \
                       times the light it receives",
            },
            Mistake {
                looks_like: &|a: &BounceArgs, got: &Vec3| {
                    right(a) != Vec3::ZERO && got.close(&a.0)
                },
                hint: "the factor is the albedo only for cosine sampling, where pdf = cos/pi \
                       cancels f_r cos: compute f_r cos(theta) / pdf for the pdf you are given",
            },
            Mistake {
                looks_like: &gives(&|&(albedo, _, _, pdf): &BounceArgs| {
                    (pdf > 0.0).then(|| albedo / PI / pdf)
                }),
                hint: "the cosine is missing: f_r cos(theta) / pdf, with cos(theta) = n . wi",
            },
            Mistake {
                looks_like: &gives(&|&(albedo, n, wi, pdf): &BounceArgs| {
                    Some(albedo / PI * n.dot(wi).max(0.0) * pdf)
                }),
                hint: "divide by the pdf, do not multiply: a direction drawn often (high pdf) \
                       must count less",
            },
        ],
        "f_r cos(theta) / pdf = (albedo / pi) (n . wi) / pdf, and zero when n . wi <= 0 or \
         pdf <= 0",
    )
}
