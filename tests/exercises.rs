//! The coding exercises.
//!
//! For the student, with the `exercises` feature: one test per exercise runs its check
//! on the student's function in `src/course/exercises/chNN.rs` and fails, naming the
//! exercise, the case, the expected and the received answer and a hint, unless every
//! case passes:
//!
//! ```text
//! cargo test --features exercises --test exercises            # all exercises
//! cargo test --features exercises --test exercises ch03       # one chapter
//! cargo test --features exercises --test exercises summary -- --nocapture   # the table
//! ```
//!
//! Always (module `checks`): every check must pass the crate's reference
//! implementation and an independent one, and must fail a deliberately wrong one with
//! the right hint, so that a wrong check fails CI.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use glam::{Mat4, Vec2, Vec3};
use render_lessons::basis::Basis;
use render_lessons::camera::{
    Film, Frame, OrthoCamera, PinholeCamera, camera_basis, camera_basis_as_on_slide,
};
use render_lessons::course::exercises::check::*;
use render_lessons::raster::ScreenVertex;
use render_lessons::ray::{ClosedSpan, Interval, Ray};
use render_lessons::scene::{Object, PointLight, Scene};
use render_lessons::shapes::{Aabb, Plane, Shape, Sphere};
use render_lessons::transform::Transform;

mod checks {
    use super::*;

    /// Asserts a `Fail` whose hint contains `hint`.
    #[track_caller]
    fn fails_with(outcome: Outcome, hint: &str) {
        match &outcome {
            Outcome::Fail { hint: got, .. } => {
                assert!(
                    got.contains(hint),
                    "hint {got:?} does not mention {hint:?}\n{outcome}"
                );
            }
            other => panic!("expected a failure with hint {hint:?}, got {other}"),
        }
    }

    // Chapter 01.

    #[test]
    fn rotation_y_accepts_the_reference() {
        use render_lessons::transform::Transform;
        assert_eq!(
            check_rotation_y(|theta| Transform::rotation_y(theta).matrix()),
            Outcome::Pass
        );
        assert_eq!(check_rotation_y(Mat4::from_rotation_y), Outcome::Pass);
    }

    #[test]
    fn rotation_y_rejects_mistakes() {
        // The slide's rows handed to glam as columns: the transpose, -sin top-right.
        fails_with(
            check_rotation_y(|theta| {
                let (s, c) = theta.sin_cos();
                Mat4::from_cols_array_2d(&[
                    [c, 0.0, s, 0.0],
                    [0.0, 1.0, 0.0, 0.0],
                    [-s, 0.0, c, 0.0],
                    [0.0, 0.0, 0.0, 1.0],
                ])
            }),
            "bottom-left",
        );
        fails_with(
            check_rotation_y(|theta| Mat4::from_rotation_y(theta.to_radians())),
            "radians",
        );
        fails_with(check_rotation_y(|_| Mat4::IDENTITY), "x' = x cos + z sin");
    }

    #[test]
    fn compose_accepts_the_reference() {
        assert_eq!(
            check_compose(|first: &Transform, second: &Transform| first.then(*second).matrix()),
            Outcome::Pass
        );
        assert_eq!(check_compose(compose_solution), Outcome::Pass);
        // `*` on transforms is written in the paper's order: `b * a` is "first a, then b".
        assert_eq!(
            check_compose(|first: &Transform, second: &Transform| (*second * *first).matrix()),
            Outcome::Pass
        );
    }

    #[test]
    fn compose_rejects_mistakes() {
        fails_with(
            check_compose(|first: &Transform, second: &Transform| first.matrix() * second.matrix()),
            "stands rightmost",
        );
        fails_with(
            check_compose(|first: &Transform, _: &Transform| first.matrix()),
            "one of the two matrices",
        );
        assert_eq!(check_compose(|_, _| todo!()), Outcome::NotStarted);
    }

    // Chapter 02.

    #[test]
    fn point_at_accepts_the_reference() {
        assert_eq!(
            check_point_at(|o, d, t| Ray::new(o, d).unwrap().at(t)),
            Outcome::Pass
        );
        assert_eq!(
            check_point_at(|o, d: Vec3, t| o + t * d / d.length()),
            Outcome::Pass
        );
    }

    #[test]
    fn point_at_rejects_mistakes() {
        fails_with(check_point_at(|o, d, t| o + t * d), "unit direction");
        fails_with(
            check_point_at(|_, d: Vec3, t| t * d.normalize()),
            "starts at o",
        );
        fails_with(
            check_point_at(|o, d: Vec3, t| o - t * d.normalize()),
            "forward",
        );
        fails_with(check_point_at(|o, _, _| o), "r(t) = o + t d/|d|");
    }

    #[test]
    fn t_closest_accepts_the_reference() {
        assert_eq!(
            check_t_closest(|ray: &Ray, p| ray.t_closest_to(p)),
            Outcome::Pass
        );
        // Independently: where the derivative of |o + t d - p|^2 vanishes, with d
        // not assumed to be a unit vector.
        let by_derivative = |ray: &Ray, p: Vec3| {
            let (o, d) = (ray.origin(), ray.direction());
            (p - o).dot(d) / d.dot(d)
        };
        assert_eq!(check_t_closest(by_derivative), Outcome::Pass);
    }

    #[test]
    fn t_closest_rejects_mistakes() {
        fails_with(
            check_t_closest(|ray: &Ray, p: Vec3| (ray.origin() - p).dot(ray.direction())),
            "sign",
        );
        fails_with(
            check_t_closest(|ray: &Ray, p: Vec3| (p - ray.origin()).length()),
            "not its t",
        );
        fails_with(
            check_t_closest(|ray: &Ray, p: Vec3| ray.t_closest_to(p).max(0.0)),
            "do not clamp",
        );
        fails_with(
            check_t_closest(|ray: &Ray, p: Vec3| {
                let to_p = p - ray.origin();
                to_p.dot(ray.direction()) / to_p.length()
            }),
            "cosine",
        );
        assert_eq!(check_t_closest(|_, _| todo!()), Outcome::NotStarted);
    }

    // Chapter 03.

    /// The slide's formula, written out independently of `Film::pixel_to_plane`.
    fn slide_pixel_to_plane(film: &Film, px: u32, py: u32) -> Vec2 {
        let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
        let (w, h) = (film.width(), film.height());
        let y_pixel = (h - 1 - py) as f32;
        Vec2::new(
            (px as f32 + 0.5) / w as f32 * (x1 - x0) + x0,
            (y_pixel + 0.5) / h as f32 * (y1 - y0) + y0,
        )
    }

    /// `pixel_to_plane` with the row used as `row(film, py)` and `offset` added to the
    /// pixel index.
    fn pixel_to_plane_with(
        row: fn(&Film, u32) -> f32,
        offset: f32,
    ) -> impl Fn(&Film, u32, u32) -> Vec2 {
        move |film, px, py| {
            let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
            Vec2::new(
                (px as f32 + offset) / film.width() as f32 * (x1 - x0) + x0,
                (row(film, py) + offset) / film.height() as f32 * (y1 - y0) + y0,
            )
        }
    }

    #[test]
    fn pixel_to_plane_accepts_the_reference() {
        let slide = Film::new(4, 3, (-8.0, 8.0), (-6.0, 6.0)).unwrap();
        assert_eq!(slide.pixel_to_plane(0, 0), Vec2::new(-6.0, 4.0));
        assert_eq!(
            check_pixel_to_plane(|film: &Film, px, py| film.pixel_to_plane(px, py)),
            Outcome::Pass
        );
        assert_eq!(check_pixel_to_plane(slide_pixel_to_plane), Outcome::Pass);
        assert_eq!(check_pixel_to_plane(pixel_to_plane_solution), Outcome::Pass);
    }

    #[test]
    fn pixel_to_plane_rejects_mistakes() {
        let from_top: fn(&Film, u32) -> f32 = |_, py| py as f32;
        let from_bottom: fn(&Film, u32) -> f32 = |film, py| (film.height() - 1 - py) as f32;
        let one_off: fn(&Film, u32) -> f32 = |film, py| (film.height() - py) as f32;
        fails_with(
            check_pixel_to_plane(pixel_to_plane_with(from_top, 0.5)),
            "row flip",
        );
        fails_with(
            check_pixel_to_plane(pixel_to_plane_with(from_bottom, 0.0)),
            "centre",
        );
        fails_with(
            check_pixel_to_plane(pixel_to_plane_with(one_off, 0.5)),
            "off by one",
        );
    }

    /// `plane_to_pixel` written out, with the row as `row(height, sy)` and `shift`
    /// added to both coordinates.
    fn plane_to_pixel_with(row: fn(f32, f32) -> f32, shift: f32) -> impl Fn(&Film, Vec2) -> Vec2 {
        move |film, p| {
            let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
            let sx = (p.x - x0) / (x1 - x0) * film.width() as f32;
            let sy = (p.y - y0) / (y1 - y0) * film.height() as f32;
            Vec2::new(sx, row(film.height() as f32, sy)) + shift
        }
    }

    #[test]
    fn plane_to_pixel_accepts_the_reference() {
        let crate_answer = |film: &Film, p| film.plane_to_pixel(p);
        assert_eq!(check_plane_to_pixel(crate_answer), Outcome::Pass);
        assert_eq!(
            check_plane_to_pixel(plane_to_pixel_with(|h, sy| h - sy, 0.0)),
            Outcome::Pass
        );
        // The round trip of lesson 03: every pixel centre comes back half a pixel in.
        let film = Film::new(5, 4, (0.0, 10.0), (-1.0, 3.0)).unwrap();
        let centre = film.plane_to_pixel(film.pixel_to_plane(4, 0));
        assert!(centre.close(&Vec2::new(4.5, 0.5)), "{centre}");
    }

    #[test]
    fn plane_to_pixel_rejects_mistakes() {
        fails_with(
            check_plane_to_pixel(plane_to_pixel_with(|_, sy| sy, 0.0)),
            "rows count from the top",
        );
        fails_with(
            check_plane_to_pixel(plane_to_pixel_with(|h, sy| h - 1.0 - sy, 0.0)),
            "height - 1 - row",
        );
        fails_with(
            check_plane_to_pixel(plane_to_pixel_with(|h, sy| h - sy, -0.5)),
            "half pixel",
        );
        fails_with(
            check_plane_to_pixel(|film: &Film, p| film.plane_to_pixel(p).floor()),
            "do not round",
        );
        assert_eq!(check_plane_to_pixel(|_, _| todo!()), Outcome::NotStarted);
    }

    // Chapter 04.

    #[test]
    fn to_world_and_to_local_accept_the_reference() {
        let basis = |u, v, w| Basis::new(u, v, w).unwrap();
        assert_eq!(
            check_to_world(move |u, v, w, b| basis(u, v, w).to_world(b)),
            Outcome::Pass
        );
        assert_eq!(
            check_to_local(move |u, v, w, a| basis(u, v, w).to_local(a)),
            Outcome::Pass
        );
        let matrix = glam::Mat3::from_cols;
        assert_eq!(
            check_to_world(move |u, v, w, b| matrix(u, v, w) * b),
            Outcome::Pass
        );
        assert_eq!(
            check_to_local(move |u, v, w, a| matrix(u, v, w).transpose() * a),
            Outcome::Pass
        );
    }

    #[test]
    fn to_world_and_to_local_reject_mistakes() {
        let matrix = glam::Mat3::from_cols;
        fails_with(
            check_to_world(move |u, v, w, b| matrix(u, v, w).transpose() * b),
            "to_local",
        );
        fails_with(
            check_to_local(move |u, v, w, a| matrix(u, v, w) * a),
            "to_world",
        );
        fails_with(check_to_world(|_, _, _, b| b), "columns of B");
    }

    // Chapter 05.

    fn uvw(b: Basis) -> (Vec3, Vec3, Vec3) {
        (b.u(), b.v(), b.w())
    }

    #[test]
    fn camera_basis_accepts_the_reference() {
        assert_eq!(
            check_camera_basis(|d, k| uvw(camera_basis(d, k).unwrap())),
            Outcome::Pass
        );
        // The formula as printed, without the crate's extra Gram-Schmidt step.
        let plain = |d: Vec3, k: Vec3| {
            let w = -d.normalize();
            let u = k.cross(w).normalize();
            (u, w.cross(u), w)
        };
        assert_eq!(check_camera_basis(plain), Outcome::Pass);
    }

    #[test]
    fn camera_basis_rejects_mistakes() {
        fails_with(
            check_camera_basis(|d, k| uvw(camera_basis_as_on_slide(d, k).unwrap())),
            "backwards",
        );
        fails_with(
            check_camera_basis(|d: Vec3, k: Vec3| {
                let w = -d.normalize();
                (k.cross(w).normalize(), k.normalize(), w)
            }),
            "not the up vector",
        );
        fails_with(
            check_camera_basis(|d: Vec3, k: Vec3| {
                let w = -d.normalize();
                let u = w.cross(k).normalize();
                (u, w.cross(u), w)
            }),
            "order of a cross product",
        );
        fails_with(
            check_camera_basis(|d: Vec3, k: Vec3| {
                let w = -d;
                let u = k.cross(w);
                (u, w.cross(u), w)
            }),
            "length 1",
        );
    }

    #[test]
    fn ortho_ray_accepts_the_reference() {
        let crate_ray = |film: &Film, frame: &Frame, px, py| {
            let ray = OrthoCamera::new(*film, *frame).ray(px, py);
            (ray.origin(), ray.direction())
        };
        assert_eq!(check_ortho_ray(crate_ray), Outcome::Pass);
        assert_eq!(check_ortho_ray(ortho_ray_solution), Outcome::Pass);
        // Written with the view matrix's inverse, the camera-to-world transform.
        let by_matrix = |film: &Film, frame: &Frame, px, py| {
            let to_world = frame.camera_to_world();
            let o = film.pixel_to_plane(px, py).extend(0.0);
            (to_world.point(o), to_world.vector(-Vec3::Z))
        };
        assert_eq!(check_ortho_ray(by_matrix), Outcome::Pass);
    }

    #[test]
    fn ortho_ray_rejects_mistakes() {
        let local = |film: &Film, px: u32, py: u32| film.pixel_to_plane(px, py).extend(0.0);
        fails_with(
            check_ortho_ray(move |film: &Film, frame: &Frame, px, py| {
                let b = frame.basis();
                (b.to_world(local(film, px, py)), b.to_world(-Vec3::Z))
            }),
            "move it to the camera's position",
        );
        fails_with(
            check_ortho_ray(move |film: &Film, frame: &Frame, px, py| {
                (
                    frame.point_to_world(local(film, px, py)),
                    frame.point_to_world(-Vec3::Z),
                )
            }),
            "an arrow, not a point",
        );
        fails_with(
            check_ortho_ray(move |film: &Film, frame: &Frame, px, py| {
                (frame.point_to_world(local(film, px, py)), -Vec3::Z)
            }),
            "carry it to the world",
        );
        fails_with(
            check_ortho_ray(move |film: &Film, frame: &Frame, px, py| {
                let b = frame.basis();
                let p = frame.position();
                (b.to_local(local(film, px, py)) + p, b.to_local(-Vec3::Z))
            }),
            "to_local",
        );
        assert_eq!(check_ortho_ray(|_, _, _, _| todo!()), Outcome::NotStarted);
    }

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
            check_pinhole_ray(|film: &Film, _, frame: &Frame, px, py| {
                let p = film.pixel_to_plane(px, py).extend(0.0);
                (frame.point_to_world(p), frame.vector_to_world(-Vec3::Z))
            }),
            "orthographic",
        );
        fails_with(
            check_pinhole_ray(|film: &Film, s, frame: &Frame, px, py| {
                let screen = film.pixel_to_plane(px, py).extend(-s);
                (frame.position(), frame.vector_to_world(screen))
            }),
            "length 1",
        );
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
    /// caller, in front of the eye only if `in_front`, in the world frame or not.
    fn project_with(
        depth: fn(f32) -> f32,
        scale: fn(f32) -> f32,
        in_front: bool,
        to_camera: bool,
    ) -> impl Fn(&Film, f32, &Frame, Vec3) -> Option<Vec2> {
        move |film, s, frame, x| {
            let c = if to_camera {
                frame.point_to_camera(x)
            } else {
                x
            };
            (!in_front || c.z < 0.0)
                .then(|| film.plane_to_pixel(c.truncate() * (scale(s) / depth(c.z))))
        }
    }

    #[test]
    fn project_rejects_mistakes() {
        let minus: fn(f32) -> f32 = |z| -z;
        let same: fn(f32) -> f32 = |s| s;
        fails_with(
            check_project(project_with(minus, same, false, true)),
            "not in front of the eye",
        );
        fails_with(
            check_project(|film: &Film, _, frame: &Frame, x| {
                let c = frame.point_to_camera(x);
                (c.z < 0.0).then(|| film.plane_to_pixel(c.truncate()))
            }),
            "orthographic",
        );
        fails_with(check_project(project_with(|z| z, same, true, true)), "-Z");
        fails_with(
            check_project(project_with(minus, |_| 1.0, true, true)),
            "distance s",
        );
        fails_with(
            check_project(project_with(minus, same, true, false)),
            "camera space first",
        );
        assert_eq!(check_project(|_, _, _, _| todo!()), Outcome::NotStarted);
    }

    // Chapter 07.

    #[test]
    fn ray_plane_t_accepts_the_reference() {
        let reference = |o, d, p0, n| Plane::new(p0, n).unwrap().t(&Ray::new(o, d).unwrap());
        assert_eq!(check_ray_plane_t(reference), Outcome::Pass);
        let by_hand = |o: Vec3, d: Vec3, p0: Vec3, n: Vec3| {
            let denom = d.dot(n);
            (denom != 0.0).then(|| (p0 - o).dot(n) / denom)
        };
        assert_eq!(check_ray_plane_t(by_hand), Outcome::Pass);
    }

    #[test]
    fn ray_plane_t_rejects_mistakes() {
        fails_with(
            check_ray_plane_t(|o: Vec3, d: Vec3, p0: Vec3, n: Vec3| {
                Some((p0 - o).dot(n) / d.dot(n))
            }),
            "parallel",
        );
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
        let ray = |o, d| Ray::new(o, d).unwrap();
        assert_eq!(
            check_ray_sphere_roots(move |o, d, c, r| sphere(c, r).roots_stable(&ray(o, d)).pair()),
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
        let ray = |o, d| Ray::new(o, d).unwrap();
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
        // The school formula: right near the origin, wrong on the far sphere (S1).
        fails_with(
            check_ray_sphere_roots(move |o, d, c, r| {
                sphere(c, r).roots_textbook(&ray(o, d)).pair()
            }),
            "STABILITY S1",
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
        cull_back_faces: bool,
        no_sum_test: bool,
        accept_negative_t: bool,
        no_parallel_test: bool,
        strict_edges: bool,
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
            if (det == 0.0 && !m.no_parallel_test) || (m.cull_back_faces && det < 0.0) {
                return None;
            }
            let inside = |b: f32| if m.strict_edges { b > 0.0 } else { b >= 0.0 };
            let s = o - v0;
            let b1 = s.dot(p) / det;
            if b1 < 0.0 || b1 > 1.0 || (m.strict_edges && !inside(b1)) {
                return None;
            }
            let q = s.cross(e1);
            let b2 = d.dot(q) / det;
            let sum_outside = if m.strict_edges {
                b1 + b2 >= 1.0
            } else {
                b1 + b2 > 1.0
            };
            if b2 < 0.0 || (m.strict_edges && !inside(b2)) || (sum_outside && !m.no_sum_test) {
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
        let ray = |o, d| Ray::new(o, d).unwrap();
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
                cull_back_faces: true,
                ..no
            }),
            "from its back",
        );
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
        fails_with(
            with(MtMistakes {
                strict_edges: true,
                ..no
            }),
            "crack",
        );
        let swapped = moller_trumbore_with(no);
        fails_with(
            check_moller_trumbore(move |o, d, v0, v1, v2| {
                swapped(o, d, v0, v1, v2).map(|(t, b1, b2)| (t, b2, b1))
            }),
            "swapped",
        );
    }

    // Chapter 08.

    #[test]
    fn closest_accepts_the_reference() {
        let reference = |ray: &Ray, shapes: &[Shape], range| {
            let objects = shapes
                .iter()
                .map(|s| Object::diffuse(s.clone(), Vec3::ONE))
                .collect();
            let scene = Scene::new(objects, Vec3::ZERO).unwrap();
            scene.closest(ray, range)
        };
        assert_eq!(check_closest(reference), Outcome::Pass);
        assert_eq!(check_closest(closest_solution), Outcome::Pass);
        // Every hit, then the smallest t: no shrinking of range.max.
        let min_of_all = |ray: &Ray, shapes: &[Shape], range| {
            each_hit(ray, shapes, range).min_by(|a, b| a.hit.t.total_cmp(&b.hit.t))
        };
        assert_eq!(check_closest(min_of_all), Outcome::Pass);
    }

    #[test]
    fn closest_rejects_mistakes() {
        fails_with(
            check_closest(|ray: &Ray, shapes: &[Shape], range| each_hit(ray, shapes, range).next()),
            "first hit",
        );
        fails_with(
            check_closest(|ray: &Ray, shapes: &[Shape], range| {
                each_hit(ray, shapes, range).next_back()
            }),
            "shrink range.max",
        );
    }

    #[test]
    fn lambert_accepts_the_reference() {
        use render_lessons::lighting::lambert;
        assert_eq!(
            check_lambert(|p, n, albedo, light: &PointLight, visible| {
                lambert(p, n, albedo, light, || visible)
            }),
            Outcome::Pass
        );
        // Independently, in f64 and with the cosine as a ratio of lengths.
        let by_hand = |p: Vec3, n: Vec3, albedo: Vec3, light: &PointLight, visible: bool| {
            let to_light = (light.position - p).as_dvec3();
            let cos = n.as_dvec3().dot(to_light) / to_light.length();
            let direct = if visible && cos > 0.0 {
                light.intensity.as_dvec3() * cos / to_light.length_squared()
            } else {
                glam::DVec3::ZERO
            };
            let ambient = f64::from(render_lessons::lighting::AMBIENT);
            (albedo.as_dvec3() * (direct + ambient)).as_vec3()
        };
        assert_eq!(check_lambert(by_hand), Outcome::Pass);
    }

    /// Lambert's law with switches for the typical mistakes.
    #[derive(Clone, Copy, Default)]
    struct LambertMistakes {
        no_ambient: bool,
        black_shadow: bool,
        ignore_shadow: bool,
        no_falloff: bool,
        over_d: bool,
        not_unit: bool,
        unclamped: bool,
        no_albedo: bool,
    }

    fn lambert_with(m: LambertMistakes) -> impl Fn(Vec3, Vec3, Vec3, &PointLight, bool) -> Vec3 {
        move |p, n, albedo, light, visible| {
            let to_light = light.position - p;
            let d = to_light.length();
            let cos = n.dot(if m.not_unit { to_light } else { to_light / d });
            let falloff = match (m.no_falloff, m.over_d) {
                (true, _) => 1.0,
                (_, true) => d,
                _ => d * d,
            };
            let seen = visible || m.ignore_shadow;
            let lit = seen && (cos > 0.0 || m.unclamped);
            let direct = if lit {
                light.intensity * cos / falloff
            } else {
                Vec3::ZERO
            };
            if m.black_shadow && !seen {
                return Vec3::ZERO;
            }
            let ambient = if m.no_ambient {
                0.0
            } else {
                render_lessons::lighting::AMBIENT
            };
            let albedo = if m.no_albedo { Vec3::ONE } else { albedo };
            albedo * (Vec3::splat(ambient) + direct)
        }
    }

    #[test]
    fn lambert_rejects_mistakes() {
        let with = |m| check_lambert(lambert_with(m));
        let no = LambertMistakes::default();
        assert_eq!(with(no), Outcome::Pass);
        for (m, hint) in [
            (
                LambertMistakes {
                    no_ambient: true,
                    ..no
                },
                "ambient share is missing",
            ),
            (
                LambertMistakes {
                    black_shadow: true,
                    ..no
                },
                "ambient share",
            ),
            (
                LambertMistakes {
                    ignore_shadow: true,
                    ..no
                },
                "visible = false",
            ),
            (
                LambertMistakes {
                    no_falloff: true,
                    ..no
                },
                "spreads over a sphere",
            ),
            (LambertMistakes { over_d: true, ..no }, "1/d here"),
            (
                LambertMistakes {
                    not_unit: true,
                    ..no
                },
                "1/d here",
            ),
            (
                LambertMistakes {
                    unclamped: true,
                    ..no
                },
                "facing away",
            ),
            (
                LambertMistakes {
                    no_albedo: true,
                    ..no
                },
                "by the albedo",
            ),
        ] {
            fails_with(with(m), hint);
        }
        assert_eq!(check_lambert(|_, _, _, _, _| todo!()), Outcome::NotStarted);
    }

    // Chapter 09.

    type P = (i64, i64);

    fn edge(u: P, v: P, q: P) -> i64 {
        (q.0 - u.0) * (v.1 - u.1) - (q.1 - u.1) * (v.0 - u.0)
    }

    fn top_left(u: P, v: P) -> bool {
        v.1 > u.1 || (v.1 == u.1 && v.0 < u.0)
    }

    /// The edges b -> c, c -> a, a -> b, with b and c swapped if the area is
    /// negative; `None` if it is zero.
    fn edges(a: P, b: P, c: P) -> Option<[(P, P); 3]> {
        let area = edge(a, b, c);
        let (b, c) = if area < 0 { (c, b) } else { (b, c) };
        (area != 0).then_some([(b, c), (c, a), (a, b)])
    }

    /// The right rule with the arithmetic done in the type `to` converts to.
    fn covers_in<T>(to: fn(i64) -> T, a: P, b: P, c: P, p: P) -> bool
    where
        T: Copy + Default + PartialOrd + std::ops::Sub<Output = T> + std::ops::Mul<Output = T>,
    {
        let e = |u: P, v: P, q: P| {
            (to(q.0) - to(u.0)) * (to(v.1) - to(u.1)) - (to(q.1) - to(u.1)) * (to(v.0) - to(u.0))
        };
        let zero = T::default();
        let area = e(a, b, c);
        if area == zero {
            return false;
        }
        let (b, c) = if area < zero { (c, b) } else { (b, c) };
        [(b, c), (c, a), (a, b)].into_iter().all(|(u, v)| {
            let e = e(u, v, p);
            e > zero || (e == zero && top_left(u, v))
        })
    }

    #[test]
    fn covers_accepts_the_reference() {
        use render_lessons::raster::rasterize::covers;
        assert_eq!(check_covers(covers), Outcome::Pass);
        // No swap: for a clockwise triangle every edge is turned round, in i128.
        let independent = |a: P, b: P, c: P, p: P| {
            let e = |u: P, v: P, q: P| {
                let w = |x: i64| i128::from(x);
                (w(q.0) - w(u.0)) * (w(v.1) - w(u.1)) - (w(q.1) - w(u.1)) * (w(v.0) - w(u.0))
            };
            let area = e(a, b, c);
            area != 0
                && [(a, b), (b, c), (c, a)].into_iter().all(|(u, v)| {
                    let (u, v) = if area > 0 { (u, v) } else { (v, u) };
                    let e = e(u, v, p);
                    e > 0 || (e == 0 && top_left(u, v))
                })
        };
        assert_eq!(check_covers(independent), Outcome::Pass);
        // On the diagonal the two triangles of the check share, away from its far
        // end, exactly one of them covers each point, whatever their winding.
        let lower = ((0, 0), (0, 8), (8, 8));
        let upper = ((0, 0), (8, 8), (8, 0));
        for i in 0..8 {
            let p = (i, i);
            assert_ne!(
                covers(lower.0, lower.1, lower.2, p),
                covers(upper.0, upper.1, upper.2, p),
                "{p:?}"
            );
            assert_eq!(
                covers(lower.0, lower.1, lower.2, p),
                covers(lower.0, lower.2, lower.1, p)
            );
        }
    }

    #[test]
    fn covers_rejects_mistakes() {
        fails_with(
            check_covers(|a, b, c, p| {
                edges(a, b, c).is_some_and(|es| es.into_iter().all(|(u, v)| edge(u, v, p) >= 0))
            }),
            "double",
        );
        fails_with(
            check_covers(|a, b, c, p| {
                edges(a, b, c).is_some_and(|es| es.into_iter().all(|(u, v)| edge(u, v, p) > 0))
            }),
            "cracks",
        );
        fails_with(
            check_covers(|a, b, c, p| {
                edge(a, b, c) != 0
                    && [(b, c), (c, a), (a, b)].into_iter().all(|(u, v)| {
                        let e = edge(u, v, p);
                        e > 0 || (e == 0 && top_left(u, v))
                    })
            }),
            "nothing is covered",
        );
        fails_with(
            check_covers(|a, b, c, p| {
                let sign = edge(a, b, c).signum();
                sign != 0
                    && [(b, c), (c, a), (a, b)].into_iter().all(|(u, v)| {
                        let e = sign * edge(u, v, p);
                        e > 0 || (e == 0 && top_left(u, v))
                    })
            }),
            "flip the signs",
        );
        fails_with(
            check_covers(|a, b, c, p| covers_in(|x| x as f32, a, b, c, p)),
            "not in floating point",
        );
        fails_with(
            check_covers(|a, b, c, p| covers_in(|x| x as f64, a, b, c, p)),
            "not in floating point",
        );
        fails_with(
            check_covers(|a, b, c, p| covers_in(|x| std::num::Wrapping(x as i32), a, b, c, p)),
            "overflow i32",
        );
        // Plain i32 panics on overflow in a debug build and wraps in a release build:
        // either way the hint says i64.
        fails_with(
            check_covers(|a, b, c, p| covers_in(|x| x as i32, a, b, c, p)),
            "i64",
        );
    }

    #[test]
    fn perspective_weights_accepts_the_reference() {
        use render_lessons::raster::rasterize::perspective_weights;
        let crate_answer = |b, v: &[ScreenVertex; 3]| perspective_weights(b, v.map(|v| v.inv_w));
        assert_eq!(check_perspective_weights(crate_answer), Outcome::Pass);
        // Independently, with w itself and in f64: (b_k / w_k) / sum_j (b_j / w_j).
        let with_w = |b: [f32; 3], v: &[ScreenVertex; 3]| {
            let over = [0, 1, 2].map(|k| f64::from(b[k]) * f64::from(v[k].inv_w));
            let sum: f64 = over.iter().sum();
            over.map(|o| (o / sum) as f32)
        };
        assert_eq!(check_perspective_weights(with_w), Outcome::Pass);
        // The chapter's exercise 4: halfway from w = 1 to w = 4 on the screen, the far
        // end weighs 0.2, not 0.5.
        let weights = perspective_weights([0.5, 0.5, 0.0], [1.0, 0.25, 1.0]);
        assert!(weights.close(&[0.8, 0.2, 0.0]), "{weights:?}");
    }

    #[test]
    fn perspective_weights_rejects_mistakes() {
        let inv_w = |v: &[ScreenVertex; 3]| v.map(|v| v.inv_w);
        fails_with(
            check_perspective_weights(|b, _: &[ScreenVertex; 3]| b),
            "screen weights",
        );
        fails_with(
            check_perspective_weights(move |b, v: &[ScreenVertex; 3]| {
                let w = inv_w(v).map(|i| 1.0 / i);
                let sum: f32 = (0..3).map(|k| b[k] * w[k]).sum();
                [0, 1, 2].map(|k| b[k] * w[k] / sum)
            }),
            "multiply by it",
        );
        fails_with(
            check_perspective_weights(move |b, v: &[ScreenVertex; 3]| {
                let i = inv_w(v);
                [0, 1, 2].map(|k| b[k] * i[k])
            }),
            "sum to 1",
        );
        fails_with(
            check_perspective_weights(move |b, v: &[ScreenVertex; 3]| {
                let i = inv_w(v);
                let sum: f32 = i.iter().sum();
                [0, 1, 2].map(|k| b[k] * i[k] / sum)
            }),
            "not by the sum of the vertices' 1/w",
        );
        assert_eq!(
            check_perspective_weights(|_, _| todo!()),
            Outcome::NotStarted
        );
    }

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
    fn malley(u: Vec2, r: fn(f32) -> f32, z: fn(f32) -> f32, pdf: fn(Vec3) -> f32) -> (Vec3, f32) {
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
        // The pdf without its 1/pi.
        fails_with(
            check_cosine_sample(move |u| malley(u, sqrt, lift, |w| w.z)),
            "misses 1/pi",
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
            check_cosine_sample(move |u| malley(Vec2::new(u.y, u.x), sqrt, lift, cos_over_pi)),
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
            (BounceMistakes { no_pi: true, ..no }, "albedo / pi"),
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
        /// Swapped when t_near > t_far.
        Comparing,
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
                    Order::Comparing if a > b => (b, a),
                    Order::Comparing => (a, b),
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
        // The exercise's old text and solution: sorted by comparing the ends. It
        // passes every case but the -0 component in a face's plane.
        fails_with(
            check_slab(slab_with(Order::Comparing, true, true)),
            "Decide by the sign of inv_d_i",
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
        let crate_answer = |node: &Aabb, left: &Aabb, nl: usize, right: &Aabb, nr: usize| {
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
        let measured = |measure: fn(&Aabb) -> f32, c_trav: f32, divide: bool, count: bool| {
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

    // The machinery.

    #[test]
    fn a_todo_is_not_started_and_other_panics_fail() {
        assert_eq!(
            check_pixel_to_plane(|_, _, _| todo!("Coding exercise 3.1")),
            Outcome::NotStarted
        );
        assert_eq!(check_closest(|_, _, _| todo!()), Outcome::NotStarted);
        assert_eq!(check_covers(|_, _, _, _| todo!()), Outcome::NotStarted);
        match check_point_at(|_, _, _| panic!("oops")) {
            Outcome::Fail { got, .. } => assert!(got.contains("a panic: oops"), "{got}"),
            other => panic!("expected a failure, got {other}"),
        }
    }

    #[test]
    fn a_failure_names_the_case_expected_got_and_hint() {
        let outcome = check_pixel_to_plane(|_, _, _| Vec2::ZERO);
        let report = PIXEL_TO_PLANE.report(&outcome);
        for part in [
            "Coding exercise 3.1",
            "pixel_to_plane",
            "src/course/exercises/ch03.rs",
            "case:",
            "pixel (0, 0)",
            "expected: (-6, 4)",
            "got:      (0, 0)",
            "hint:",
        ] {
            assert!(report.contains(part), "{part:?} missing from\n{report}");
        }
        let report = PIXEL_TO_PLANE.report(&Outcome::NotStarted);
        assert!(
            report.contains("NOT STARTED") && report.contains("todo!()"),
            "{report}"
        );
        assert!(PIXEL_TO_PLANE.row(&Outcome::Pass).contains("PASS"));
    }

    #[test]
    fn every_check_reports_not_started_for_a_todo() {
        let outcomes = [
            check_rotation_y(|_| todo!()),
            check_compose(|_, _| todo!()),
            check_point_at(|_, _, _| todo!()),
            check_t_closest(|_, _| todo!()),
            check_pixel_to_plane(|_, _, _| todo!()),
            check_plane_to_pixel(|_, _| todo!()),
            check_to_world(|_, _, _, _| todo!()),
            check_to_local(|_, _, _, _| todo!()),
            check_camera_basis(|_, _| todo!()),
            check_ortho_ray(|_, _, _, _| todo!()),
            check_pinhole_ray(|_, _, _, _, _| todo!()),
            check_project(|_, _, _, _| todo!()),
            check_ray_plane_t(|_, _, _, _| todo!()),
            check_ray_sphere_roots(|_, _, _, _| todo!()),
            check_moller_trumbore(|_, _, _, _, _| todo!()),
            check_closest(|_, _, _| todo!()),
            check_lambert(|_, _, _, _, _| todo!()),
            check_covers(|_, _, _, _| todo!()),
            check_perspective_weights(|_, _| todo!()),
            check_cosine_sample(|_| todo!()),
            check_bounce_weight(|_, _, _, _| todo!()),
            check_slab(|_, _, _, _, _| todo!()),
            check_sah_cost(|_, _, _, _, _| todo!()),
        ];
        for (exercise, outcome) in ALL.iter().zip(outcomes) {
            assert_eq!(outcome, Outcome::NotStarted, "exercise {}", exercise.number);
        }
    }

    /// Set once the test below has its outcome: the "endless" loop then ends, so that
    /// it does not keep a core busy for the rest of the test run.
    static STOP_LOOPING: AtomicBool = AtomicBool::new(false);

    #[test]
    fn an_endless_loop_fails_its_case_within_the_time_limit() {
        // 1 s instead of the default 5 s: the test waits for the whole limit.
        set_case_time_limit(Duration::from_secs(1));
        let limit = Duration::from_secs(1);
        let start = Instant::now();
        let outcome = check_point_at(|o, _, _| {
            while !STOP_LOOPING.load(Ordering::Relaxed) {
                std::hint::spin_loop();
            }
            o
        });
        let waited = start.elapsed();
        STOP_LOOPING.store(true, Ordering::Relaxed);
        assert!(
            waited >= limit && waited < limit + Duration::from_secs(3),
            "{waited:?}"
        );
        match &outcome {
            Outcome::Fail {
                case, got, hint, ..
            } => {
                assert!(case.contains("o = (1, 1, 0)"), "{case}");
                assert_eq!(got, "no answer within 1 s");
                assert!(
                    hint.contains(&format!(
                        "case 1 ({case}) did not finish within 1 s: an infinite loop?"
                    )),
                    "{hint}"
                );
            }
            other => panic!("expected a failure, got {other}"),
        }
        let report = POINT_AT.report(&outcome);
        assert!(
            report.contains("FAIL") && report.contains("infinite loop"),
            "{report}"
        );
    }

    /// The message of the panic a failing outcome reports.
    #[track_caller]
    fn panic_message(outcome: Outcome) -> String {
        match outcome {
            Outcome::Fail { got, hint, .. } => {
                assert!(hint.contains("must not panic"), "{hint}");
                got
            }
            other => panic!("expected a failure, got {other}"),
        }
    }

    #[test]
    fn an_unwrap_of_none_an_index_out_of_bounds_and_a_panic_in_rayon_fail() {
        let start = Instant::now();
        // A search that finds nothing: the first NaN coordinate of p.
        let got = panic_message(check_t_closest(|_, p: Vec3| {
            p.to_array().into_iter().find(|x| x.is_nan()).unwrap()
        }));
        assert!(
            got.starts_with("a panic: ") && got.contains("`Option::unwrap()` on a `None`"),
            "{got}"
        );
        let got = panic_message(check_rotation_y(|theta| {
            let angles: Vec<f32> = Vec::new();
            Mat4::from_rotation_y(angles[theta as usize])
        }));
        assert!(got.contains("index out of bounds"), "{got}");
        // A panic inside a parallel iterator reaches the check through rayon.
        let got = panic_message(check_rotation_y(|theta| {
            use rayon::prelude::*;
            let sum: f32 = (0..4)
                .into_par_iter()
                .map(|i| {
                    if i == 3 {
                        panic!("in a rayon closure")
                    } else {
                        theta
                    }
                })
                .sum();
            Mat4::from_rotation_y(sum)
        }));
        assert!(got.contains("in a rayon closure"), "{got}");
        assert!(start.elapsed() < CASE_TIME_LIMIT, "{:?}", start.elapsed());
    }

    #[test]
    fn every_lesson_has_two_exercises_or_more_numbered_in_book_order() {
        for chapter in 1..=11 {
            let chapter = format!("{chapter:02}");
            let numbers: Vec<&str> = ALL
                .iter()
                .filter(|e| e.chapter == chapter)
                .map(|e| e.number)
                .collect();
            assert!(numbers.len() >= 2, "chapter {chapter}: {numbers:?}");
            let first = chapter.trim_start_matches('0');
            let expected: Vec<String> = (1..=numbers.len())
                .map(|i| format!("{first}.{i}"))
                .collect();
            assert_eq!(numbers, expected, "chapter {chapter}");
        }
        assert!(ALL.len() >= 22);
    }

    #[test]
    fn every_exercise_is_listed_once_with_its_file() {
        for (i, e) in ALL.iter().enumerate() {
            assert!(
                ALL[..i].iter().all(|o| o.number != e.number),
                "{} twice",
                e.number
            );
            assert_eq!(e.file, format!("src/course/exercises/ch{}.rs", e.chapter));
            let stub = std::fs::read_to_string(e.file).unwrap();
            // Only what stays true once the student has written the body: the
            // function's name and the exercise's number in the file.
            let number = format!("Coding exercise {}", e.number);
            assert!(stub.contains(&number), "{number} not in {}", e.file);
            assert!(
                stub.contains(&format!("pub fn {}(", e.function)),
                "{} not in {}",
                e.function,
                e.file
            );
        }
    }
}

#[cfg(feature = "exercises")]
mod student {
    use render_lessons::course::exercises::{
        ch01, ch02, ch03, ch04, ch05, ch06, ch07, ch08, ch09, ch10, ch11, check_all,
    };

    use super::*;

    #[track_caller]
    fn expect_pass(exercise: Exercise, outcome: Outcome) {
        let report = exercise.report(&outcome);
        assert!(outcome == Outcome::Pass, "\n{report}\n");
    }

    #[test]
    fn ch01_rotation_y() {
        expect_pass(ROTATION_Y, check_rotation_y(ch01::rotation_y));
    }

    #[test]
    fn ch01_compose() {
        expect_pass(COMPOSE, check_compose(ch01::compose));
    }

    #[test]
    fn ch02_point_at() {
        expect_pass(POINT_AT, check_point_at(ch02::point_at));
    }

    #[test]
    fn ch02_t_closest() {
        expect_pass(T_CLOSEST, check_t_closest(ch02::t_closest));
    }

    #[test]
    fn ch03_pixel_to_plane() {
        expect_pass(PIXEL_TO_PLANE, check_pixel_to_plane(ch03::pixel_to_plane));
    }

    #[test]
    fn ch03_plane_to_pixel() {
        expect_pass(PLANE_TO_PIXEL, check_plane_to_pixel(ch03::plane_to_pixel));
    }

    #[test]
    fn ch04_to_world() {
        expect_pass(TO_WORLD, check_to_world(ch04::to_world));
    }

    #[test]
    fn ch04_to_local() {
        expect_pass(TO_LOCAL, check_to_local(ch04::to_local));
    }

    #[test]
    fn ch05_camera_basis() {
        expect_pass(CAMERA_BASIS, check_camera_basis(ch05::camera_basis));
    }

    #[test]
    fn ch05_ortho_ray() {
        expect_pass(ORTHO_RAY, check_ortho_ray(ch05::ortho_ray));
    }

    #[test]
    fn ch06_pinhole_ray() {
        expect_pass(PINHOLE_RAY, check_pinhole_ray(ch06::pinhole_ray));
    }

    #[test]
    fn ch06_project() {
        expect_pass(PROJECT, check_project(ch06::project));
    }

    #[test]
    fn ch07_ray_plane_t() {
        expect_pass(RAY_PLANE_T, check_ray_plane_t(ch07::ray_plane_t));
    }

    #[test]
    fn ch07_ray_sphere_roots() {
        expect_pass(
            RAY_SPHERE_ROOTS,
            check_ray_sphere_roots(ch07::ray_sphere_roots),
        );
    }

    #[test]
    fn ch07_moller_trumbore() {
        expect_pass(
            MOLLER_TRUMBORE,
            check_moller_trumbore(ch07::moller_trumbore),
        );
    }

    #[test]
    fn ch08_closest() {
        expect_pass(CLOSEST, check_closest(ch08::closest));
    }

    #[test]
    fn ch08_lambert() {
        expect_pass(LAMBERT, check_lambert(ch08::lambert));
    }

    #[test]
    fn ch09_covers() {
        expect_pass(COVERS, check_covers(ch09::covers));
    }

    #[test]
    fn ch09_perspective_weights() {
        expect_pass(
            PERSPECTIVE_WEIGHTS,
            check_perspective_weights(ch09::perspective_weights),
        );
    }

    #[test]
    fn ch10_cosine_sample() {
        expect_pass(COSINE_SAMPLE, check_cosine_sample(ch10::cosine_sample));
    }

    #[test]
    fn ch10_bounce_weight() {
        expect_pass(BOUNCE_WEIGHT, check_bounce_weight(ch10::bounce_weight));
    }

    #[test]
    fn ch11_slab() {
        expect_pass(SLAB, check_slab(ch11::slab));
    }

    #[test]
    fn ch11_sah_cost() {
        expect_pass(SAH_COST, check_sah_cost(ch11::sah_cost));
    }

    /// The table of every exercise's status; never fails on the student's answers.
    /// See it with
    /// `cargo test --features exercises --test exercises summary -- --nocapture`.
    #[test]
    fn summary() {
        let results = check_all();
        let listed: Vec<&str> = results.iter().map(|(e, _)| e.number).collect();
        let all: Vec<&str> = ALL.iter().map(|e| e.number).collect();
        assert_eq!(
            listed, all,
            "check_all must run every exercise, in book order"
        );
        let passed = results.iter().filter(|(_, o)| *o == Outcome::Pass).count();
        println!("\nCoding exercises: {passed} of {} pass", results.len());
        for (exercise, outcome) in &results {
            println!("  {}", exercise.row(outcome));
        }
        println!();
    }
}
