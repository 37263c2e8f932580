//! The check of chapter 11's first coding exercise, the slab test: the cases, the
//! reference answer for each, and the hints for the typical mistakes. The student's
//! function is in `ch11.rs`, beside this file (the second exercise's check is
//! `ch11_sah_check.rs`); the harness is `harness.rs`.

use glam::Vec3;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, run, v};
use crate::ray::{ClosedSpan, Interval, Ray};
use crate::shapes::Aabb;

/// Coding exercise 11.4.
pub const SLAB: Exercise = Exercise {
    number: "11.4",
    chapter: "11",
    chapter_title: "Speed against accuracy",
    function: "slab",
    file: "src/course/exercises/ch11.rs",
};

/// One case: the ray (its unit direction for the reference, `1/d` for the student),
/// the box and the range of `t`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct SlabArgs {
    ray: Ray,
    inv_d: Vec3,
    min: Vec3,
    max: Vec3,
    range: Interval,
}

/// The answer: the closed interval `[t0, t1]`, or `None`.
type SlabAnswer = Option<ClosedSpan>;

// ANCHOR: solution
/// A worked solution of exercise 11.4, written as the exercise asks (the book shows
/// it). The crate's own [`Aabb::slab`] computes `1 / d` itself, once per call.
pub fn slab_solution(
    o: Vec3,
    inv_d: Vec3,
    min: Vec3,
    max: Vec3,
    range: Interval,
) -> Option<ClosedSpan> {
    let (mut t0, mut t1) = (range.min, range.max);
    for i in 0..3 {
        let to_min = (min[i] - o[i]) * inv_d[i];
        let to_max = (max[i] - o[i]) * inv_d[i];
        // A negative d_i (or d_i = -0, inv_d_i = -inf) meets the max plane first. The
        // sign of inv_d_i decides, not a comparison of the two ends, which a NaN
        // (0 * inf, a ray in a face's plane) would defeat.
        let (t_near, t_far) = if inv_d[i] < 0.0 {
            (to_max, to_min)
        } else {
            (to_min, to_max)
        };
        // Written this way round, a NaN compares false and changes nothing.
        if t_near > t0 {
            t0 = t_near;
        }
        if t_far < t1 {
            t1 = t_far;
        }
        // Closed box: t0 == t1 (a touching point) is still a hit.
        if t0 > t1 {
            return None;
        }
    }
    Some(ClosedSpan { t0, t1 })
}
// ANCHOR_END: solution

/// The typical ways of getting the slab test wrong, as rules the check can run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Slab {
    /// (min - o) / inv_d: dividing by 1/d instead of multiplying.
    Divides,
    /// [t0, t1] starts at [-inf, inf], not [range.min, range.max].
    Unclipped,
    /// No swap of t_near and t_far when d_i < 0.
    NoSwap,
    /// Swapped when t_near > t_far, by comparing them: a NaN end (a ray in a face's
    /// plane) is never swapped, so with d_i = -0 the exit becomes -inf.
    ComparedSwap,
    /// Rejects when t0 >= t1: a touching ray misses the closed box.
    Strict,
    /// The test's `naive_slab`: swap with `if a < c`, update with
    /// `t0 = if t0 > near { t0 } else { near }`: a NaN wins both.
    NanWins,
    /// Swap with `f32::min` / `f32::max`, which drop a NaN and keep the infinity.
    MinMax,
    /// The right swap, but the update `t0 = if t0 > near { t0 } else { near }`, which
    /// lets a NaN t_near replace t0.
    NanUpdate,
}

/// The slab test gone wrong the way `rule` says.
fn slab_wrongly(rule: Slab, a: &SlabArgs) -> SlabAnswer {
    let o = a.ray.origin();
    let (mut t0, mut t1) = match rule {
        Slab::Unclipped => (f32::NEG_INFINITY, f32::INFINITY),
        _ => (a.range.min, a.range.max),
    };
    for i in 0..3 {
        let (lo, hi) = (a.min[i] - o[i], a.max[i] - o[i]);
        let (p, q) = match rule {
            Slab::Divides => (lo / a.inv_d[i], hi / a.inv_d[i]),
            _ => (lo * a.inv_d[i], hi * a.inv_d[i]),
        };
        let (near, far) = match rule {
            Slab::NoSwap => (p, q),
            Slab::ComparedSwap => {
                if p > q {
                    (q, p)
                } else {
                    (p, q)
                }
            }
            Slab::NanWins => {
                if p < q {
                    (p, q)
                } else {
                    (q, p)
                }
            }
            Slab::MinMax => (p.min(q), p.max(q)),
            _ => {
                if a.inv_d[i] < 0.0 {
                    (q, p)
                } else {
                    (p, q)
                }
            }
        };
        match rule {
            Slab::NanWins | Slab::NanUpdate => {
                t0 = if t0 > near { t0 } else { near };
                t1 = if t1 < far { t1 } else { far };
            }
            _ => {
                t0 = t0.max(near);
                t1 = t1.min(far);
            }
        }
        let empty = match rule {
            Slab::Strict => t0 >= t1,
            _ => t0 > t1,
        };
        if empty {
            return None;
        }
    }
    Some(ClosedSpan { t0, t1 })
}

impl Answer for ClosedSpan {
    /// Both ends equal within the tolerance.
    fn close(&self, other: &ClosedSpan) -> bool {
        self.t0.close(&other.t0) && self.t1.close(&other.t1)
    }
    /// `[t0, t1]`, closed.
    fn show(&self) -> String {
        format!("[{}, {}]", self.t0.show(), self.t1.show())
    }
}

/// The same interval, a NaN matching a NaN.
fn same(a: &SlabAnswer, b: &SlabAnswer) -> bool {
    let eq = |x: f32, y: f32| x.close(&y) || (x.is_nan() && y.is_nan());
    match (a, b) {
        (None, None) => true,
        (Some(a), Some(b)) => eq(a.t0, b.t0) && eq(a.t1, b.t1),
        _ => false,
    }
}

/// Checks `slab(o, inv_d, min, max, range)`: the interval of the ray inside
/// the closed box, clipped to `[range.min, range.max]`, against the crate's
/// [`Aabb::slab`], on rays parallel to slabs (`inv_d` infinite), lying in a face's
/// plane (0 * inf = NaN), starting inside, touching a flat box, and with d < 0 and d =
/// -0.
pub fn check_slab(
    f: impl Fn(Vec3, Vec3, Vec3, Vec3, Interval) -> SlabAnswer + Send + Sync + 'static,
) -> Outcome {
    slab_checked(Box::new(f))
}

/// [`check_slab`] for the answer as a trait object: compiled once, here, not again
/// for every closure a test passes (see [`super::harness`]).
fn slab_checked(
    f: Box<dyn Fn(Vec3, Vec3, Vec3, Vec3, Interval) -> SlabAnswer + Send + Sync>,
) -> Outcome {
    let cube = (v(-1.0, -1.0, -1.0), v(1.0, 1.0, 1.0));
    let flat = (v(-1.0, 0.0, -1.0), v(1.0, 0.0, 1.0));
    let inf = f32::INFINITY;
    let cases: Vec<Case<SlabArgs>> = [
        (
            "straight through along +Z (d_x = d_y = 0, so inv_d_x = inv_d_y = inf)",
            cube,
            v(0.2, 0.3, -5.0),
            v(0.0, 0.0, 1.0),
            0.0,
            inf,
        ),
        (
            "the origin inside the box",
            cube,
            v(0.0, 0.0, 0.0),
            v(1.0, 0.0, 0.0),
            0.0,
            inf,
        ),
        (
            "along -X (d_x < 0: the ray meets x = 1 first)",
            cube,
            v(5.0, 0.2, 0.3),
            v(-1.0, 0.0, 0.0),
            0.0,
            inf,
        ),
        (
            "a diagonal ray",
            cube,
            v(-4.0, -3.5, -3.0),
            v(1.0, 1.0, 1.0),
            0.0,
            inf,
        ),
        (
            "the box behind the origin",
            cube,
            v(0.0, 0.0, 5.0),
            v(0.0, 0.0, 1.0),
            0.0,
            inf,
        ),
        (
            "range.max = 5 ends inside the box",
            cube,
            v(0.2, 0.3, -5.0),
            v(0.0, 0.0, 1.0),
            0.0,
            5.0,
        ),
        (
            "range.max = 3 ends before the box",
            cube,
            v(0.2, 0.3, -5.0),
            v(0.0, 0.0, 1.0),
            0.0,
            3.0,
        ),
        (
            "a flat box (zero thickness in y) hit head on: it touches at one t",
            flat,
            v(0.5, 1.0, 0.5),
            v(0.0, -1.0, 0.0),
            0.0,
            inf,
        ),
        (
            "in the plane z = 3 beside the box (y = 1 is the top face's plane: 0 * inf = NaN)",
            cube,
            v(-5.0, 1.0, 3.0),
            v(1.0, 0.0, 0.0),
            0.0,
            inf,
        ),
        (
            "along the top face's plane y = 1, over the face (0 * inf = NaN for t_far in y)",
            cube,
            v(0.0, 1.0, -5.0),
            v(0.0, 0.0, 1.0),
            0.0,
            inf,
        ),
        (
            "along an edge, x = 1 and y = 1",
            cube,
            v(1.0, 1.0, -5.0),
            v(0.0, 0.0, 1.0),
            0.0,
            inf,
        ),
        (
            "along the bottom face's plane z = -1 (0 * inf = NaN for t_near in z, the last axis)",
            cube,
            v(-5.0, 0.0, -1.0),
            v(1.0, 0.0, 0.0),
            0.0,
            inf,
        ),
        (
            "negative zero components (inv_d = -inf)",
            cube,
            v(0.5, 0.5, 5.0),
            v(-0.0, -0.0, -1.0),
            0.0,
            inf,
        ),
        (
            "a -0 component and in a face's plane: d_y = -0 on the bottom face's plane y = -1 \
             (0 * -inf = NaN as the exit in y, -inf as the entry)",
            cube,
            v(-5.0, -1.0, 0.0),
            v(1.0, -0.0, 0.0),
            0.0,
            inf,
        ),
        (
            "a -0 component along the top face's plane: d_x = d_y = -0 in the plane y = 1 \
             ((1 - 1) * -inf = NaN as the entry in y, +inf as the exit)",
            cube,
            v(0.0, 1.0, -5.0),
            v(-0.0, -0.0, 1.0),
            0.0,
            inf,
        ),
        (
            "parallel to x, just above the top face",
            cube,
            v(-5.0, 1.0 + 1e-6, 0.0),
            v(1.0, 0.0, 0.0),
            0.0,
            inf,
        ),
        (
            "in the top face's plane, beside the box in x",
            cube,
            v(3.0, 1.0, -5.0),
            v(0.0, 0.0, 1.0),
            0.0,
            inf,
        ),
    ]
    .into_iter()
    .map(|(place, (min, max), o, d, t_min, t_max)| {
        let ray = Ray::new(o, d).expect("valid ray");
        let inv_d = Vec3::ONE / ray.direction();
        (
            format!(
                "box {} to {}, o = {}, inv_d = {}, t in [{}, {}]: {place}",
                min.show(),
                max.show(),
                o.show(),
                inv_d.show(),
                t_min.show(),
                t_max.show()
            ),
            SlabArgs {
                ray,
                inv_d,
                min,
                max,
                range: Interval::new(t_min, t_max),
            },
        )
    })
    .collect();
    let reference = |a: &SlabArgs| {
        Aabb::new(a.min, a.max)
            .expect("valid box")
            .slab(&a.ray, a.range)
    };
    // The mistake that explains a failure gives the received answer on this case and,
    // like the implementation, the right one on every case before it.
    let wrong_first_here = |rule: Slab| {
        let cases = &cases;
        move |args: &SlabArgs, got: &SlabAnswer| {
            same(got, &slab_wrongly(rule, args))
                && cases.iter().take_while(|(_, earlier)| earlier != args).all(
                    |(_, earlier)| {
                        same(&slab_wrongly(rule, earlier), &reference(earlier))
                    },
                )
        }
    };
    let divides = wrong_first_here(Slab::Divides);
    let unclipped = wrong_first_here(Slab::Unclipped);
    let no_swap = wrong_first_here(Slab::NoSwap);
    let compared_swap = wrong_first_here(Slab::ComparedSwap);
    let strict = wrong_first_here(Slab::Strict);
    let nan_wins = wrong_first_here(Slab::NanWins);
    let min_max = wrong_first_here(Slab::MinMax);
    let nan_update = wrong_first_here(Slab::NanUpdate);
    run(
        &cases,
        reference,
        move |a| f(a.ray.origin(), a.inv_d, a.min, a.max, a.range),
        &[
            Mistake {
                looks_like: &divides,
                hint: "inv_d is already 1/d: multiply by it, (min_i - o_i) * inv_d_i, do not \
                       divide by it",
            },
            Mistake {
                looks_like: &unclipped,
                hint: "start the interval at [range.min, range.max], not at [-inf, inf]: a ray that \
                       starts inside the box enters it at range.min, not behind its origin",
            },
            Mistake {
                looks_like: &no_swap,
                hint: "when d_i < 0 the ray crosses the max plane first: t_near = (min_i - o_i) \
                       * inv_d_i is then the larger of the two, so swap t_near and t_far when \
                       inv_d_i < 0",
            },
            Mistake {
                looks_like: &compared_swap,
                hint: "swapping when t_near > t_far compares the two ends, and a NaN end (0 * inf, \
                       a ray in a face's plane) compares false: with d_i = -0 the pair (NaN, -inf) \
                       stays unswapped and t1 becomes -inf. Decide by the sign of inv_d_i \
                       instead: the max plane comes first when inv_d_i < 0 (1 / -0 = -inf)",
            },
            Mistake {
                looks_like: &strict,
                hint: "the box is closed: t0 == t1 is a hit (a ray touching an edge, a corner or \
                       a box of zero thickness). Give up only when t0 > t1, not when t0 >= t1",
            },
            Mistake {
                looks_like: &nan_wins,
                hint: "a ray lying in a face's plane gives 0 * inf = NaN, and every comparison \
                       with NaN is false: `if a < b { a } else { b }` then picks the NaN, which \
                       wipes out the interval, and no later test can reject it. Order the ends \
                       by the sign of inv_d_i, and update with `if t_near > t0 { t0 = t_near }`, \
                       so that a NaN changes nothing",
            },
            Mistake {
                looks_like: &min_max,
                hint: "f32::min and f32::max drop a NaN and return the other value: sorting \
                       t_near and t_far with them turns the NaN of a ray lying in a face's plane \
                       into -inf, and the ray along the face misses. Order the ends by the sign \
                       of inv_d_i, which leaves the NaN where it is",
            },
            Mistake {
                looks_like: &nan_update,
                hint: "`t0 = if t0 > t_near { t0 } else { t_near }` takes t_near when it is NaN \
                       (0 * inf, a ray lying in a face's plane): write \
                       `if t_near > t0 { t0 = t_near }` (or t0.max(t_near)), which keeps t0",
            },
            Mistake {
                looks_like: &|a: &SlabArgs, _: &SlabAnswer| {
                    a.inv_d.to_array().contains(&f32::NEG_INFINITY)
                },
                hint: "this ray has a component d_i = -0, so inv_d_i = 1 / -0 = -inf: negative, \
                       and the ray meets the max plane first, t_near = (max_i - o_i) * inv_d_i, \
                       t_far = (min_i - o_i) * inv_d_i. Decide by inv_d_i < 0: the sign of d_i \
                       itself (-0 < 0 is false), or of 1 / inv_d_i = -0, gets it wrong, and so \
                       does comparing the two ends when the ray lies in a face's plane, where \
                       one of them is 0 * -inf = NaN. Then update with \
                       `if t_near > t0 { t0 = t_near }` and `if t_far < t1 { t1 = t_far }`, so \
                       that a NaN end changes nothing",
            },
        ],
        "per axis t_near = (min_i - o_i) * inv_d_i, t_far = (max_i - o_i) * inv_d_i, swapped \
         if inv_d_i < 0; start at [range.min, range.max], then `if t_near > t0 { t0 = t_near }`, \
         `if t_far < t1 { t1 = t_far }`, and None as soon as t0 > t1",
    )
}
