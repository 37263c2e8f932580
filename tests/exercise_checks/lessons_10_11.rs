//! The checks of the coding exercises of lessons 10 and 11, themselves checked (run by
//! the default test suite): each check must pass the crate's reference and an
//! independent answer, and must fail wrong answers, each with a hint that names the
//! mistake, so that a wrong check fails CI. The mistakes the chapters warn about, as a
//! student writes them, are in `pitfalls_10_11.rs`; the student's own tests in
//! `tests/exercises.rs`.

use glam::{Vec2, Vec3};
use render_lessons::course::exercises::check::*;
use render_lessons::ray::{ClosedSpan, Interval, Ray};
use render_lessons::shapes::Aabb;

use crate::common::fails_with;

// Chapter 10.

#[test]
fn cosine_sample_accepts_the_reference() {
    use render_lessons::sampling::cosine_hemisphere;
    let reference = |u: Vec2| {
        let w = cosine_hemisphere(u);
        (w, w.z / std::f32::consts::PI)
    };
    assert_eq!(check_cosine_sample(reference), Outcome::Pass);
    // Independently: theta from sin^2(theta) = u.x, then spherical coordinates.
    let by_angles = |u: Vec2| {
        let theta = u.x.sqrt().asin();
        let phi = std::f32::consts::TAU * u.y;
        let w = Vec3::new(
            theta.sin() * phi.cos(),
            theta.sin() * phi.sin(),
            theta.cos(),
        );
        (w, theta.cos() / std::f32::consts::PI)
    };
    assert_eq!(check_cosine_sample(by_angles), Outcome::Pass);
}

/// Malley's method with the pieces the mistakes below get wrong: the radius
/// on the disc, the height, and the pdf of the direction.
fn malley(
    u: Vec2,
    r: fn(f32) -> f32,
    z: fn(f32) -> f32,
    pdf: fn(Vec3) -> f32,
) -> (Vec3, f32) {
    let (s, c) = (std::f32::consts::TAU * u.y).sin_cos();
    let w = Vec3::new(r(u.x) * c, r(u.x) * s, z(u.x));
    (w, pdf(w))
}

#[test]
fn cosine_sample_rejects_mistakes() {
    use std::f32::consts::{PI, TAU};
    let cos_over_pi = |w: Vec3| w.z / PI;
    let sqrt = |x: f32| x.sqrt();
    let lift = |x: f32| (1.0 - x).max(0.0).sqrt();
    // Uniform directions (z = u.x) with the cosine pdf.
    fails_with(
        check_cosine_sample(move |u| {
            malley(u, |x| (1.0 - x * x).max(0.0).sqrt(), |x| x, cos_over_pi)
        }),
        "uniform hemisphere",
    );
    // The uniform density for cosine directions.
    fails_with(
        check_cosine_sample(move |u| malley(u, sqrt, lift, |_| 1.0 / TAU)),
        "uniform hemisphere's density",
    );
    // The square root on the radius only: z = 1 - u.x is not unit length.
    fails_with(
        check_cosine_sample(move |u| malley(u, sqrt, |x| 1.0 - x, cos_over_pi)),
        "unit length",
    );
    // No square root on the radius: r = u.x, lifted to unit length.
    fails_with(
        check_cosine_sample(move |u| {
            malley(u, |x| x, |x| (1.0 - x * x).max(0.0).sqrt(), cos_over_pi)
        }),
        "r = sqrt(u.x)",
    );
    // A right sampler, u.x and u.y swapped.
    fails_with(
        check_cosine_sample(move |u| {
            malley(Vec2::new(u.y, u.x), sqrt, lift, cos_over_pi)
        }),
        "swapped",
    );
}

#[test]
fn bounce_weight_accepts_the_reference() {
    use std::f32::consts::{PI, TAU};
    assert_eq!(check_bounce_weight(bounce_weight_solution), Outcome::Pass);
    // Steps 2 and 3's closed forms: 2 albedo cos for uniform directions, the
    // albedo itself for cosine-weighted ones.
    let albedo = Vec3::new(0.75, 0.25, 0.25);
    let (n, wi) = (Vec3::Z, Vec3::new(0.6, 0.0, 0.8));
    let uniform = bounce_weight_solution(albedo, n, wi, 1.0 / TAU);
    assert!(uniform.close(&(2.0 * albedo * 0.8)), "{uniform}");
    let cosine = bounce_weight_solution(albedo, n, wi, 0.8 / PI);
    assert!(cosine.close(&albedo), "{cosine}");
    let by_hand = |albedo: Vec3, n: Vec3, wi: Vec3, pdf: f32| {
        let cos = n.dot(wi);
        if cos > 0.0 && pdf > 0.0 {
            albedo * cos / (PI * pdf)
        } else {
            Vec3::ZERO
        }
    };
    assert_eq!(check_bounce_weight(by_hand), Outcome::Pass);
}

/// f_r cos / pdf with switches for the typical mistakes.
#[derive(Clone, Copy, Default)]
struct BounceMistakes {
    divide_by_zero: bool,
    negative_cos: bool,
    no_pi: bool,
    no_cos: bool,
    times_pdf: bool,
}

fn bounce_weight_with(m: BounceMistakes) -> impl Fn(Vec3, Vec3, Vec3, f32) -> Vec3 {
    move |albedo, n, wi, pdf| {
        let cos = if m.negative_cos {
            n.dot(wi)
        } else {
            n.dot(wi).max(0.0)
        };
        if pdf <= 0.0 && !m.divide_by_zero {
            return Vec3::ZERO;
        }
        let f_r = if m.no_pi {
            albedo
        } else {
            albedo / std::f32::consts::PI
        };
        let cos = if m.no_cos { 1.0 } else { cos };
        if m.times_pdf {
            f_r * cos * pdf
        } else {
            f_r * cos / pdf
        }
    }
}

#[test]
fn bounce_weight_rejects_mistakes() {
    let with = |m| check_bounce_weight(bounce_weight_with(m));
    let no = BounceMistakes::default();
    assert_eq!(with(no), Outcome::Pass);
    for (m, hint) in [
        (
            BounceMistakes {
                divide_by_zero: true,
                ..no
            },
            "density of 0",
        ),
        (
            BounceMistakes {
                negative_cos: true,
                ..no
            },
            "below the surface",
        ),
        (BounceMistakes { no_cos: true, ..no }, "cosine is missing"),
        (
            BounceMistakes {
                times_pdf: true,
                ..no
            },
            "do not multiply",
        ),
    ] {
        fails_with(with(m), hint);
    }
    fails_with(
        check_bounce_weight(|albedo, _, _, _| albedo),
        "only for cosine sampling",
    );
    assert_eq!(
        check_bounce_weight(|_, _, _, _| todo!()),
        Outcome::NotStarted
    );
}

// Chapter 11.

/// How a student's slab test orders each axis's two ends.
#[derive(Clone, Copy)]
enum Order {
    /// Not at all.
    None,
    /// With f32::min and f32::max.
    MinMax,
    /// By the sign of inv_d_i, as lesson 07 does.
    Sign,
}

/// The slab test as a student might write it, with its parts chosen by the flags:
/// `order` sorts t_near and t_far, `keep_nan` writes the updates so that a NaN
/// changes nothing, `closed` accepts t0 == t1.
fn slab_with(
    order: Order,
    keep_nan: bool,
    closed: bool,
) -> impl Fn(Vec3, Vec3, Vec3, Vec3, Interval) -> Option<ClosedSpan> {
    move |o, inv_d, min, max, range: Interval| {
        let (mut t0, mut t1) = (range.min, range.max);
        for i in 0..3 {
            let a = (min[i] - o[i]) * inv_d[i];
            let b = (max[i] - o[i]) * inv_d[i];
            let (near, far) = match order {
                Order::None => (a, b),
                Order::MinMax => (a.min(b), a.max(b)),
                Order::Sign if inv_d[i] < 0.0 => (b, a),
                Order::Sign => (a, b),
            };
            if keep_nan {
                t0 = t0.max(near);
                t1 = t1.min(far);
            } else {
                t0 = if t0 > near { t0 } else { near };
                t1 = if t1 < far { t1 } else { far };
            }
            if t0 > t1 || (!closed && t0 == t1) {
                return None;
            }
        }
        Some(ClosedSpan { t0, t1 })
    }
}

#[test]
fn slab_accepts_the_reference() {
    use render_lessons::shapes::Aabb;
    let crate_slab = |o: Vec3, inv_d: Vec3, min: Vec3, max: Vec3, range| {
        let ray = Ray::new(o, Vec3::ONE / inv_d).unwrap();
        Aabb::new(min, max).unwrap().slab(&ray, range)
    };
    assert_eq!(check_slab(crate_slab), Outcome::Pass);
    assert_eq!(check_slab(slab_solution), Outcome::Pass);
    assert_eq!(
        check_slab(slab_with(Order::Sign, true, true)),
        Outcome::Pass
    );
}

#[test]
fn slab_rejects_mistakes() {
    fails_with(
        check_slab(slab_with(Order::None, true, true)),
        "swap t_near and t_far",
    );
    fails_with(
        check_slab(slab_with(Order::Sign, true, false)),
        "the box is closed",
    );
    fails_with(
        check_slab(slab_with(Order::MinMax, true, true)),
        "f32::min and f32::max",
    );
    fails_with(
        check_slab(slab_with(Order::Sign, false, true)),
        "takes t_near when it is NaN",
    );
    fails_with(
        check_slab(|o, inv_d, min, max, _| {
            slab_solution(o, inv_d, min, max, Interval::EVERYWHERE)
        }),
        "start the interval at [range.min, range.max]",
    );
    fails_with(
        check_slab(|o, inv_d, min, max, range| {
            slab_solution(o, Vec3::ONE / inv_d, min, max, range)
        }),
        "multiply by it",
    );
    assert_eq!(check_slab(|_, _, _, _, _| todo!()), Outcome::NotStarted);
}

#[test]
fn sah_cost_accepts_the_reference() {
    use render_lessons::bvh::build::{TRAVERSAL_COST, split_cost};
    let crate_answer =
        |node: &Aabb, left: &Aabb, nl: usize, right: &Aabb, nr: usize| {
            split_cost(
                node.surface_area(),
                (left.surface_area(), nl as u32),
                (right.surface_area(), nr as u32),
            )
        };
    assert_eq!(check_sah_cost(crate_answer), Outcome::Pass);
    assert_eq!(check_sah_cost(sah_cost_solution), Outcome::Pass);
    // Independently, the areas by hand in f64.
    let by_hand = |node: &Aabb, left: &Aabb, nl: usize, right: &Aabb, nr: usize| {
        let area = |b: &Aabb| {
            let e = (b.max() - b.min()).as_dvec3();
            2.0 * (e.x * e.y + e.y * e.z + e.z * e.x)
        };
        let weighted = area(left) * nl as f64 + area(right) * nr as f64;
        (f64::from(TRAVERSAL_COST) + weighted / area(node)) as f32
    };
    assert_eq!(check_sah_cost(by_hand), Outcome::Pass);
}

#[test]
fn sah_cost_rejects_mistakes() {
    use render_lessons::bvh::build::TRAVERSAL_COST;
    let measured =
        |measure: fn(&Aabb) -> f32, c_trav: f32, divide: bool, count: bool| {
            move |node: &Aabb, left: &Aabb, nl: usize, right: &Aabb, nr: usize| {
                let (nl, nr) = if count {
                    (nl as f32, nr as f32)
                } else {
                    (1.0, 1.0)
                };
                let weighted = measure(left) * nl + measure(right) * nr;
                c_trav
                    + if divide {
                        weighted / measure(node)
                    } else {
                        weighted
                    }
            }
        };
    let area: fn(&Aabb) -> f32 = Aabb::surface_area;
    let volume: fn(&Aabb) -> f32 = |b| {
        let e = b.max() - b.min();
        e.x * e.y * e.z
    };
    assert_eq!(
        check_sah_cost(measured(area, TRAVERSAL_COST, true, true)),
        Outcome::Pass
    );
    fails_with(
        check_sah_cost(measured(area, 0.0, true, true)),
        "cost of visiting the node",
    );
    fails_with(
        check_sah_cost(measured(area, TRAVERSAL_COST, false, true)),
        "divide by the node's surface area",
    );
    fails_with(
        check_sah_cost(measured(volume, TRAVERSAL_COST, true, true)),
        "not their volume",
    );
    fails_with(
        check_sah_cost(measured(area, TRAVERSAL_COST, true, false)),
        "number of primitives",
    );
    assert_eq!(check_sah_cost(|_, _, _, _, _| todo!()), Outcome::NotStarted);
}
