//! The pitfalls lessons 10 and 11 warn about, as a student writes them: each a plain
//! function in an exercise's shape, which the exercise's check must fail with a hint
//! naming the mistake, so that a check that lets a warned mistake through fails CI.
//! The checks' references and their other wrong answers are in `lessons_10_11.rs`.

use glam::{Vec2, Vec3};
use render_lessons::course::exercises::check::*;
use render_lessons::ray::{ClosedSpan, Interval};
use render_lessons::shapes::Aabb;

use crate::common::fails_with;

/// Lesson 10, step 3's "dropping the square root": r = u.x crowds the disc's centre.
fn cosine_sample_without_the_square_root(u: Vec2) -> (Vec3, f32) {
    let (s, c) = (std::f32::consts::TAU * u.y).sin_cos();
    let r = u.x;
    let w = Vec3::new(r * c, r * s, (1.0 - r * r).max(0.0).sqrt());
    (w, w.z / std::f32::consts::PI)
}

/// Lesson 10, step 3: a pdf that does not match the directions, 1/pi missing.
fn cosine_sample_pdf_without_pi(u: Vec2) -> (Vec3, f32) {
    let (s, c) = (std::f32::consts::TAU * u.y).sin_cos();
    let r = u.x.sqrt();
    let w = Vec3::new(r * c, r * s, (1.0 - u.x).max(0.0).sqrt());
    (w, w.z)
}

/// Lesson 10, step 2's "forgetting the 1/pi of Lambert".
fn bounce_weight_without_pi(albedo: Vec3, n: Vec3, wi: Vec3, pdf: f32) -> Vec3 {
    let cos = n.dot(wi);
    if cos <= 0.0 || pdf <= 0.0 {
        return Vec3::ZERO;
    }
    albedo * cos / pdf
}

/// Lesson 10, step 3's "dividing by a zero density": only the cosine guarded.
fn bounce_weight_dividing_by_zero(albedo: Vec3, n: Vec3, wi: Vec3, pdf: f32) -> Vec3 {
    let cos = n.dot(wi);
    if cos <= 0.0 {
        return Vec3::ZERO;
    }
    albedo / std::f32::consts::PI * cos / pdf
}

/// The exercise's old text and solution, which lesson 07 warns about: the ends
/// sorted by comparing them, which a NaN end defeats for d_i = -0 in a face's plane.
fn slab_ordered_by_comparing(
    o: Vec3,
    inv_d: Vec3,
    min: Vec3,
    max: Vec3,
    range: Interval,
) -> Option<ClosedSpan> {
    let (mut t0, mut t1) = (range.min, range.max);
    for i in 0..3 {
        let mut t_near = (min[i] - o[i]) * inv_d[i];
        let mut t_far = (max[i] - o[i]) * inv_d[i];
        if t_near > t_far {
            std::mem::swap(&mut t_near, &mut t_far);
        }
        if t_near > t0 {
            t0 = t_near;
        }
        if t_far < t1 {
            t1 = t_far;
        }
        if t0 > t1 {
            return None;
        }
    }
    Some(ClosedSpan { t0, t1 })
}

/// Ordered by the sign of d_i = 1 / inv_d_i, which is -0 for d_i = -0: -0 < 0 is false.
fn slab_ordered_by_the_sign_of_d(
    o: Vec3,
    inv_d: Vec3,
    min: Vec3,
    max: Vec3,
    range: Interval,
) -> Option<ClosedSpan> {
    let (mut t0, mut t1) = (range.min, range.max);
    for i in 0..3 {
        let (to_min, to_max) = ((min[i] - o[i]) * inv_d[i], (max[i] - o[i]) * inv_d[i]);
        let (t_near, t_far) = if 1.0 / inv_d[i] < 0.0 {
            (to_max, to_min)
        } else {
            (to_min, to_max)
        };
        t0 = t0.max(t_near);
        t1 = t1.min(t_far);
        if t0 > t1 {
            return None;
        }
    }
    Some(ClosedSpan { t0, t1 })
}

/// Lesson 07's "comparing with NaN": `t0 = if t0 > t_near { t0 } else { t_near }`.
fn slab_letting_nan_in(
    o: Vec3,
    inv_d: Vec3,
    min: Vec3,
    max: Vec3,
    range: Interval,
) -> Option<ClosedSpan> {
    let (mut t0, mut t1) = (range.min, range.max);
    for i in 0..3 {
        let (to_min, to_max) = ((min[i] - o[i]) * inv_d[i], (max[i] - o[i]) * inv_d[i]);
        let (t_near, t_far) = if inv_d[i] < 0.0 {
            (to_max, to_min)
        } else {
            (to_min, to_max)
        };
        t0 = if t0 > t_near { t0 } else { t_near };
        t1 = if t1 < t_far { t1 } else { t_far };
        if t0 > t1 {
            return None;
        }
    }
    Some(ClosedSpan { t0, t1 })
}

/// Lesson 11's heuristic weighed by volume, which a flat box does not have.
fn sah_cost_by_volume(
    node: &Aabb,
    left: &Aabb,
    nl: usize,
    right: &Aabb,
    nr: usize,
) -> f32 {
    let volume = |b: &Aabb| (b.max() - b.min()).element_product();
    let weighted = volume(left) * nl as f32 + volume(right) * nr as f32;
    render_lessons::bvh::build::TRAVERSAL_COST + weighted / volume(node)
}

#[test]
fn every_exercise_of_lessons_10_and_11_fails_what_its_chapter_warns_about() {
    for (outcome, hint) in [
        (
            check_cosine_sample(cosine_sample_without_the_square_root),
            "r = sqrt(u.x)",
        ),
        (
            check_cosine_sample(cosine_sample_pdf_without_pi),
            "misses 1/pi",
        ),
        (check_bounce_weight(bounce_weight_without_pi), "albedo / pi"),
        (
            check_bounce_weight(bounce_weight_dividing_by_zero),
            "density of 0",
        ),
        (
            check_slab(slab_ordered_by_comparing),
            "Decide by the sign of inv_d_i",
        ),
        (check_slab(slab_ordered_by_the_sign_of_d), "-0 < 0 is false"),
        (
            check_slab(slab_letting_nan_in),
            "takes t_near when it is NaN",
        ),
        (check_sah_cost(sah_cost_by_volume), "not their volume"),
    ] {
        fails_with(outcome, hint);
    }
}
