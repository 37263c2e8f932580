//! The pitfalls lessons 06 and 07 warn about, as a student writes them: each a plain
//! function in an exercise's shape, which the exercise's check must fail with a hint
//! naming the mistake, so that a check that lets a warned mistake through fails CI.
//! The checks' references and their other wrong answers are in `lessons_06_07.rs`.

use glam::{Vec2, Vec3};
use render_lessons::camera::{Film, Frame};
use render_lessons::course::exercises::check::*;

use crate::common::fails_with;

/// Lesson 06's erratum, "the orthographic ray in pinhole clothing".
fn pinhole_ray_as_on_the_slides(
    film: &Film,
    _: f32,
    frame: &Frame,
    px: u32,
    py: u32,
) -> (Vec3, Vec3) {
    let p = film.pixel_to_plane(px, py).extend(0.0);
    (frame.point_to_world(p), frame.vector_to_world(-Vec3::Z))
}

/// Lesson 06, "forgetting to normalise": s - e as it is.
fn pinhole_ray_unnormalised(
    film: &Film,
    s: f32,
    frame: &Frame,
    px: u32,
    py: u32,
) -> (Vec3, Vec3) {
    let screen = film.pixel_to_plane(px, py).extend(-s);
    (frame.position(), frame.vector_to_world(screen))
}

/// Lesson 06, "rows from the bottom" (STABILITY S11): the slide's row, unflipped.
fn pinhole_ray_upside_down(
    film: &Film,
    s: f32,
    frame: &Frame,
    px: u32,
    py: u32,
) -> (Vec3, Vec3) {
    let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
    let (w, h) = (film.width() as f32, film.height() as f32);
    let x = (px as f32 + 0.5) / w * (x1 - x0) + x0;
    let y = (py as f32 + 0.5) / h * (y1 - y0) + y0;
    let d = Vec3::new(x, y, -s).normalize();
    (frame.position(), frame.vector_to_world(d))
}

/// Lesson 06, "points behind the eye": divided by -Z whatever its sign.
fn project_behind_the_eye_too(
    film: &Film,
    s: f32,
    frame: &Frame,
    x: Vec3,
) -> Option<Vec2> {
    let c = frame.point_to_camera(x);
    Some(film.plane_to_pixel(c.truncate() * (s / -c.z)))
}

/// Lesson 06, "rows from the bottom" (STABILITY S11): pixel rows counted upwards.
fn project_upside_down(film: &Film, s: f32, frame: &Frame, x: Vec3) -> Option<Vec2> {
    let c = frame.point_to_camera(x);
    let p = c.truncate() * (s / -c.z);
    let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
    let (w, h) = (film.width() as f32, film.height() as f32);
    (c.z < 0.0)
        .then(|| Vec2::new((p.x - x0) / (x1 - x0) * w, (p.y - y0) / (y1 - y0) * h))
}

/// Lesson 07, the plane's "dividing before checking": no test at all.
fn ray_plane_t_dividing_first(o: Vec3, d: Vec3, p0: Vec3, n: Vec3) -> Option<f32> {
    Some((p0 - o).dot(n) / d.dot(n))
}

/// The same pitfall's second half: d . n = 0 refused, an overflowing quotient kept.
fn ray_plane_t_infinite_kept(o: Vec3, d: Vec3, p0: Vec3, n: Vec3) -> Option<f32> {
    let denom = d.dot(n);
    (denom != 0.0).then(|| (p0 - o).dot(n) / denom)
}

/// Lesson 07, "the textbook discriminant far from the origin" (STABILITY S1).
fn ray_sphere_roots_school(o: Vec3, d: Vec3, c: Vec3, r: f32) -> Option<(f32, f32)> {
    let f = o - c;
    let (a, b, c) = (d.dot(d), 2.0 * f.dot(d), f.dot(f) - r * r);
    let disc = b * b - 4.0 * a * c;
    (disc >= 0.0).then(|| {
        (
            (-b - disc.sqrt()) / (2.0 * a),
            (-b + disc.sqrt()) / (2.0 * a),
        )
    })
}

/// Lesson 07, "sign(0) = 0" (STABILITY S2): GLSL's sign in the stable roots.
fn ray_sphere_roots_sign_of_zero_is_zero(
    o: Vec3,
    d: Vec3,
    c: Vec3,
    r: f32,
) -> Option<(f32, f32)> {
    let sign = |x: f32| {
        if x > 0.0 {
            1.0
        } else if x < 0.0 {
            -1.0
        } else {
            0.0
        }
    };
    let f = o - c;
    let (a, b, cc) = (d.dot(d), 2.0 * f.dot(d), f.dot(f) - r * r);
    let l = f - (f.dot(d) / a) * d;
    let disc = 4.0 * a * (r * r - l.dot(l));
    (disc >= 0.0).then(|| {
        let q = -0.5 * (b + sign(b) * disc.sqrt());
        let (t0, t1) = (cc / q, q / a);
        (t0.min(t1), t0.max(t1))
    })
}

/// STABILITY S2's tangent: sign(0) = +1, but q = 0 not caught, so c/q = 0/0.
fn ray_sphere_roots_q_zero_divided(
    o: Vec3,
    d: Vec3,
    c: Vec3,
    r: f32,
) -> Option<(f32, f32)> {
    let f = o - c;
    let (a, b, cc) = (d.dot(d), 2.0 * f.dot(d), f.dot(f) - r * r);
    let l = f - (f.dot(d) / a) * d;
    let disc = 4.0 * a * (r * r - l.dot(l));
    (disc >= 0.0).then(|| {
        let q = -0.5 * (b + if b >= 0.0 { 1.0 } else { -1.0 } * disc.sqrt());
        let (t0, t1) = (cc / q, q / a);
        if t0 < t1 { (t0, t1) } else { (t1, t0) }
    })
}

/// Lesson 07, "culling by accident": `if det < eps { return None }`.
fn moller_trumbore_culling(
    o: Vec3,
    d: Vec3,
    v0: Vec3,
    v1: Vec3,
    v2: Vec3,
) -> Option<(f32, f32, f32)> {
    let (e1, e2, s) = (v1 - v0, v2 - v0, o - v0);
    let (p, q) = (d.cross(e2), s.cross(e1));
    let det = e1.dot(p);
    if det < 1e-8 {
        return None;
    }
    let (b1, b2, t) = (s.dot(p) / det, d.dot(q) / det, e2.dot(q) / det);
    (b1 >= 0.0 && b2 >= 0.0 && b1 + b2 <= 1.0 && t > 0.0).then_some((t, b1, b2))
}

/// Lesson 07, "strict inequalities": every shared edge a crack.
fn moller_trumbore_strict(
    o: Vec3,
    d: Vec3,
    v0: Vec3,
    v1: Vec3,
    v2: Vec3,
) -> Option<(f32, f32, f32)> {
    let (e1, e2, s) = (v1 - v0, v2 - v0, o - v0);
    let (p, q) = (d.cross(e2), s.cross(e1));
    let det = e1.dot(p);
    if det == 0.0 {
        return None;
    }
    let (b1, b2, t) = (s.dot(p) / det, d.dot(q) / det, e2.dot(q) / det);
    (b1 > 0.0 && b2 > 0.0 && b1 + b2 < 1.0 && t > 0.0).then_some((t, b1, b2))
}

#[test]
fn every_exercise_of_lessons_06_and_07_fails_what_its_chapter_warns_about() {
    for (outcome, hint) in [
        (
            check_pinhole_ray(pinhole_ray_as_on_the_slides),
            "orthographic ray",
        ),
        (check_pinhole_ray(pinhole_ray_unnormalised), "length 1"),
        (check_pinhole_ray(pinhole_ray_upside_down), "STABILITY S11"),
        (
            check_project(project_behind_the_eye_too),
            "not in front of the eye",
        ),
        (check_project(project_upside_down), "STABILITY S11"),
        (check_ray_plane_t(ray_plane_t_dividing_first), "parallel"),
        (check_ray_plane_t(ray_plane_t_infinite_kept), "not finite"),
        (
            check_ray_sphere_roots(ray_sphere_roots_school),
            "STABILITY S1",
        ),
        (
            check_ray_sphere_roots(ray_sphere_roots_sign_of_zero_is_zero),
            "sign(0) = +1",
        ),
        (
            check_ray_sphere_roots(ray_sphere_roots_q_zero_divided),
            "When q = 0",
        ),
        (
            check_moller_trumbore(moller_trumbore_culling),
            "from its back",
        ),
        (check_moller_trumbore(moller_trumbore_strict), "crack"),
    ] {
        fails_with(outcome, hint);
    }
}
