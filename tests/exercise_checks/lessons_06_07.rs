//! The checks of the coding exercises of lessons 06 and 07, themselves checked (run by
//! the default test suite): each check must pass the crate's reference and an
//! independent answer, and must fail wrong answers, each with a hint that names the
//! mistake, so that a wrong check fails CI. The mistakes the chapters warn about, as a
//! student writes them, are in `pitfalls_06_07.rs`; the student's own tests in
//! `tests/exercises.rs`.

use glam::{Vec2, Vec3};
use render_lessons::camera::{Film, Frame, PinholeCamera};
use render_lessons::course::exercises::check::*;
use render_lessons::ray::Interval;
use render_lessons::shapes::{Plane, Sphere};

use crate::common::{fails_with, ray};

// Chapter 06.

#[test]
fn pinhole_ray_accepts_the_reference() {
    let reference = |film: &Film, s, frame: &Frame, px, py| {
        let ray = PinholeCamera::new(*film, s, *frame).unwrap().ray(px, py);
        (ray.origin(), ray.direction())
    };
    assert_eq!(check_pinhole_ray(reference), Outcome::Pass);
    let by_hand = |film: &Film, s: f32, frame: &Frame, px, py| {
        let screen = film.pixel_to_plane(px, py).extend(-s);
        (frame.position(), frame.basis().to_world(screen.normalize()))
    };
    assert_eq!(check_pinhole_ray(by_hand), Outcome::Pass);
}

#[test]
fn pinhole_ray_rejects_mistakes() {
    fails_with(
        check_pinhole_ray(|film: &Film, s, frame: &Frame, px, py| {
            let screen = film.pixel_to_plane(px, py).extend(-s);
            (frame.position(), screen.normalize())
        }),
        "with the basis",
    );
    fails_with(
        check_pinhole_ray(|film: &Film, s, frame: &Frame, px, py| {
            let screen = film.pixel_to_plane(px, py).extend(-s);
            (Vec3::ZERO, frame.vector_to_world(screen.normalize()))
        }),
        "origin is not",
    );
    fails_with(
        check_pinhole_ray(|film: &Film, s, frame: &Frame, px, py| {
            let screen = film.pixel_to_plane(px, py).extend(s);
            (frame.position(), frame.vector_to_world(screen.normalize()))
        }),
        "z = -s",
    );
}

#[test]
fn project_accepts_the_reference() {
    let crate_answer = |film: &Film, s, frame: &Frame, x| {
        PinholeCamera::new(*film, s, *frame).unwrap().project(x)
    };
    assert_eq!(check_project(crate_answer), Outcome::Pass);
    // Independently: intersect the line from the eye to x with the screen plane
    // z = -s in camera space, then read the film's pixel coordinates by hand.
    let by_ray = |film: &Film, s: f32, frame: &Frame, x: Vec3| {
        let d = frame.basis().to_local(x - frame.position());
        (d.z < 0.0).then(|| {
            let on_screen = d * (-s / d.z);
            let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
            let (w, h) = (film.width() as f32, film.height() as f32);
            Vec2::new(
                (on_screen.x - x0) / (x1 - x0) * w,
                (y1 - on_screen.y) / (y1 - y0) * h,
            )
        })
    };
    assert_eq!(check_project(by_ray), Outcome::Pass);
}

/// Lesson 06's projection with the depth `depth(z)` and scale `s` chosen by the
/// caller, in the world frame or not.
fn project_with(
    depth: fn(f32) -> f32,
    scale: fn(f32) -> f32,
    to_camera: bool,
) -> impl Fn(&Film, f32, &Frame, Vec3) -> Option<Vec2> {
    move |film, s, frame, x| {
        let c = if to_camera {
            frame.point_to_camera(x)
        } else {
            x
        };
        (c.z < 0.0).then(|| film.plane_to_pixel(c.truncate() * (scale(s) / depth(c.z))))
    }
}

#[test]
fn project_rejects_mistakes() {
    let minus: fn(f32) -> f32 = |z| -z;
    let same: fn(f32) -> f32 = |s| s;
    fails_with(
        check_project(|film: &Film, _, frame: &Frame, x| {
            let c = frame.point_to_camera(x);
            (c.z < 0.0).then(|| film.plane_to_pixel(c.truncate()))
        }),
        "orthographic",
    );
    fails_with(check_project(project_with(|z| z, same, true)), "-Z");
    fails_with(
        check_project(project_with(minus, |_| 1.0, true)),
        "distance s",
    );
    fails_with(
        check_project(project_with(minus, same, false)),
        "camera space first",
    );
    assert_eq!(check_project(|_, _, _, _| todo!()), Outcome::NotStarted);
}

// Chapter 07.

#[test]
fn ray_plane_t_accepts_the_reference() {
    let reference = |o, d, p0, n| Plane::new(p0, n).unwrap().t(&ray(o, d));
    assert_eq!(check_ray_plane_t(reference), Outcome::Pass);
    let by_hand = |o: Vec3, d: Vec3, p0: Vec3, n: Vec3| {
        let denom = d.dot(n);
        (denom != 0.0)
            .then(|| (p0 - o).dot(n) / denom)
            .filter(|t| t.is_finite())
    };
    assert_eq!(check_ray_plane_t(by_hand), Outcome::Pass);
}

#[test]
fn ray_plane_t_rejects_mistakes() {
    fails_with(
        check_ray_plane_t(|o: Vec3, d: Vec3, p0: Vec3, n: Vec3| {
            let denom = d.dot(n);
            (denom != 0.0).then(|| (o - p0).dot(n) / denom)
        }),
        "sign",
    );
    fails_with(
        check_ray_plane_t(|o: Vec3, d: Vec3, p0: Vec3, n: Vec3| {
            let denom = d.dot(n);
            (denom != 0.0)
                .then(|| (p0 - o).dot(n) / denom)
                .filter(|&t| t >= 0.0)
        }),
        "behind the origin",
    );
}

fn sphere(c: Vec3, r: f32) -> Sphere {
    Sphere::new(c, r).unwrap()
}

#[test]
fn ray_sphere_roots_accepts_the_reference() {
    assert_eq!(
        check_ray_sphere_roots(move |o, d, c, r| sphere(c, r)
            .roots_stable(&ray(o, d))
            .pair()),
        Outcome::Pass
    );
    // Written out independently: the Hearn-Baker discriminant r^2 - |l|^2 (with
    // b/2 = f . d) and the school formula's roots, which do not cancel here.
    let by_hand = |o: Vec3, d: Vec3, c: Vec3, r: f32| {
        let f = o - c;
        let half_b = f.dot(d);
        let l = f - half_b * d;
        let quarter_disc = r * r - l.dot(l);
        (quarter_disc >= 0.0).then(|| {
            let h = quarter_disc.sqrt();
            (-half_b - h, -half_b + h)
        })
    };
    assert_eq!(check_ray_sphere_roots(by_hand), Outcome::Pass);
}

#[test]
fn ray_sphere_roots_rejects_mistakes() {
    fails_with(
        check_ray_sphere_roots(move |o, d, c, r| {
            sphere(c, r)
                .roots_stable(&ray(o, d))
                .pair()
                .map(|(a, b)| (b, a))
        }),
        "ascending",
    );
    fails_with(
        check_ray_sphere_roots(move |o, d, c, r| {
            sphere(c, r)
                .roots_stable(&ray(o, d))
                .pair()
                .map(|(a, b)| (-b, -a))
        }),
        "f = o - c",
    );
    fails_with(
        check_ray_sphere_roots(move |o, d, c, r| {
            sphere(c, r)
                .roots_stable(&ray(o, d))
                .pair()
                .filter(|&(t0, _)| t0 >= 0.0)
        }),
        "negative",
    );
    let textbook_disc = |o: Vec3, d: Vec3, c: Vec3, r: f32, stable_roots: bool| {
        let f = o - c;
        let (a, b, c) = (d.dot(d), 2.0 * f.dot(d), f.dot(f) - r * r);
        let disc = b * b - 4.0 * a * c;
        if disc < 0.0 {
            return None;
        }
        let (t0, t1) = if stable_roots {
            let q = -0.5 * (b + b.signum() * disc.sqrt());
            if q == 0.0 {
                return Some((0.0, 0.0));
            }
            (c / q, q / a)
        } else {
            (
                (-b - disc.sqrt()) / (2.0 * a),
                (-b + disc.sqrt()) / (2.0 * a),
            )
        };
        Some((t0.min(t1), t0.max(t1)))
    };
    fails_with(
        check_ray_sphere_roots(move |o, d, c, r| textbook_disc(o, d, c, r, false)),
        "4 (r^2 - |f - (f . d) d|^2)",
    );
    // The stable roots alone do not repair a discriminant of the wrong sign.
    fails_with(
        check_ray_sphere_roots(move |o, d, c, r| textbook_disc(o, d, c, r, true)),
        "STABILITY S1",
    );
}

/// Möller-Trumbore written out, with switches for the typical mistakes.
#[derive(Clone, Copy, Default)]
struct MtMistakes {
    no_sum_test: bool,
    accept_negative_t: bool,
    no_parallel_test: bool,
}

// `b1 < 0.0 || b1 > 1.0` on purpose: unlike `!(0.0..=1.0).contains(&b1)` it lets a
// NaN through, which is the mistake `no_parallel_test` shows.
#[allow(clippy::manual_range_contains)]
fn moller_trumbore_with(
    m: MtMistakes,
) -> impl Fn(Vec3, Vec3, Vec3, Vec3, Vec3) -> Option<(f32, f32, f32)> {
    move |o, d, v0, v1, v2| {
        let (e1, e2) = (v1 - v0, v2 - v0);
        let p = d.cross(e2);
        let det = e1.dot(p);
        if det == 0.0 && !m.no_parallel_test {
            return None;
        }
        let s = o - v0;
        let b1 = s.dot(p) / det;
        if b1 < 0.0 || b1 > 1.0 {
            return None;
        }
        let q = s.cross(e1);
        let b2 = d.dot(q) / det;
        if b2 < 0.0 || (b1 + b2 > 1.0 && !m.no_sum_test) {
            return None;
        }
        let t = e2.dot(q) / det;
        if t <= 0.0 && !m.accept_negative_t {
            return None;
        }
        Some((t, b1, b2))
    }
}

#[test]
fn moller_trumbore_accepts_the_reference() {
    use render_lessons::shapes::Triangle;
    let triangle = |v0, v1, v2| Triangle::new(v0, v1, v2).unwrap();
    assert_eq!(
        check_moller_trumbore(move |o, d, v0, v1, v2| {
            triangle(v0, v1, v2)
                .moller_trumbore(&ray(o, d), Interval::AHEAD)
                .map(|c| (c.t, c.b[1], c.b[2]))
        }),
        Outcome::Pass
    );
    assert_eq!(
        check_moller_trumbore(moller_trumbore_with(MtMistakes::default())),
        Outcome::Pass
    );
    // The watertight test gives the same answers on these exact cases.
    assert_eq!(
        check_moller_trumbore(move |o, d, v0, v1, v2| {
            triangle(v0, v1, v2)
                .watertight(&ray(o, d), Interval::AHEAD)
                .map(|c| (c.t, c.b[1], c.b[2]))
        }),
        Outcome::Pass
    );
}

#[test]
fn moller_trumbore_rejects_mistakes() {
    let with = |m| check_moller_trumbore(moller_trumbore_with(m));
    let no = MtMistakes::default();
    fails_with(
        with(MtMistakes {
            no_sum_test: true,
            ..no
        }),
        "b1 + b2 <= 1",
    );
    fails_with(
        with(MtMistakes {
            accept_negative_t: true,
            ..no
        }),
        "behind the ray's origin",
    );
    fails_with(
        with(MtMistakes {
            no_parallel_test: true,
            ..no
        }),
        "before dividing by det",
    );
    let swapped = moller_trumbore_with(no);
    fails_with(
        check_moller_trumbore(move |o, d, v0, v1, v2| {
            swapped(o, d, v0, v1, v2).map(|(t, b1, b2)| (t, b2, b1))
        }),
        "swapped",
    );
}
