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

use glam::{Mat4, Vec2, Vec3};
use render_lessons::basis::Basis;
use render_lessons::camera::{Film, Frame, PinholeCamera, camera_basis, camera_basis_as_on_slide};
use render_lessons::course::exercises::check::*;
use render_lessons::ray::{Interval, Ray};
use render_lessons::scene::{Object, Scene, SceneHit};
use render_lessons::shapes::{Plane, Shape, Sphere};

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

    // Chapter 02.

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

    // Chapter 03.

    /// The slide's formula, written out independently of `Film`.
    fn slide_pixel_to_plane(
        x: (f32, f32),
        y: (f32, f32),
        w: u32,
        h: u32,
        px: u32,
        py: u32,
    ) -> Vec2 {
        let y_pixel = (h - 1 - py) as f32;
        Vec2::new(
            (px as f32 + 0.5) / w as f32 * (x.1 - x.0) + x.0,
            (y_pixel + 0.5) / h as f32 * (y.1 - y.0) + y.0,
        )
    }

    #[test]
    fn pixel_to_plane_accepts_the_reference() {
        let reference = |x, y, w, h, px, py| Film::new(w, h, x, y).unwrap().pixel_to_plane(px, py);
        assert_eq!(
            reference((-8.0, 8.0), (-6.0, 6.0), 4, 3, 0, 0),
            Vec2::new(-6.0, 4.0)
        );
        assert_eq!(check_pixel_to_plane(reference), Outcome::Pass);
        assert_eq!(check_pixel_to_plane(slide_pixel_to_plane), Outcome::Pass);
    }

    #[test]
    fn pixel_to_plane_rejects_mistakes() {
        fails_with(
            check_pixel_to_plane(|x, y, w, h, px, py| {
                Vec2::new(
                    (px as f32 + 0.5) / w as f32 * (x.1 - x.0) + x.0,
                    (py as f32 + 0.5) / h as f32 * (y.1 - y.0) + y.0,
                )
            }),
            "row flip",
        );
        fails_with(
            check_pixel_to_plane(|x, y, w, h, px, py| {
                Vec2::new(
                    px as f32 / w as f32 * (x.1 - x.0) + x.0,
                    (h - 1 - py) as f32 / h as f32 * (y.1 - y.0) + y.0,
                )
            }),
            "centre",
        );
        fails_with(
            check_pixel_to_plane(|x, y, w, h, px, py| {
                Vec2::new(
                    (px as f32 + 0.5) / w as f32 * (x.1 - x.0) + x.0,
                    ((h - py) as f32 + 0.5) / h as f32 * (y.1 - y.0) + y.0,
                )
            }),
            "off by one",
        );
    }

    // Chapter 04.

    #[test]
    fn to_world_and_to_local_accept_the_reference() {
        let basis = |u, v, w| Basis::new(u, v, w).unwrap();
        assert_eq!(
            check_to_world(|u, v, w, b| basis(u, v, w).to_world(b)),
            Outcome::Pass
        );
        assert_eq!(
            check_to_local(|u, v, w, a| basis(u, v, w).to_local(a)),
            Outcome::Pass
        );
        let matrix = glam::Mat3::from_cols;
        assert_eq!(
            check_to_world(|u, v, w, b| matrix(u, v, w) * b),
            Outcome::Pass
        );
        assert_eq!(
            check_to_local(|u, v, w, a| matrix(u, v, w).transpose() * a),
            Outcome::Pass
        );
    }

    #[test]
    fn to_world_and_to_local_reject_mistakes() {
        let matrix = glam::Mat3::from_cols;
        fails_with(
            check_to_world(|u, v, w, b| matrix(u, v, w).transpose() * b),
            "to_local",
        );
        fails_with(check_to_local(|u, v, w, a| matrix(u, v, w) * a), "to_world");
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
            check_ray_sphere_roots(|o, d, c, r| sphere(c, r).roots_stable(&ray(o, d)).pair()),
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
            check_ray_sphere_roots(|o, d, c, r| {
                sphere(c, r)
                    .roots_stable(&ray(o, d))
                    .pair()
                    .map(|(a, b)| (b, a))
            }),
            "ascending",
        );
        fails_with(
            check_ray_sphere_roots(|o, d, c, r| {
                sphere(c, r)
                    .roots_stable(&ray(o, d))
                    .pair()
                    .map(|(a, b)| (-b, -a))
            }),
            "f = o - c",
        );
        fails_with(
            check_ray_sphere_roots(|o, d, c, r| {
                sphere(c, r)
                    .roots_stable(&ray(o, d))
                    .pair()
                    .filter(|&(t0, _)| t0 >= 0.0)
            }),
            "negative",
        );
        // The school formula: right near the origin, wrong on the far sphere (S1).
        fails_with(
            check_ray_sphere_roots(|o, d, c, r| sphere(c, r).roots_textbook(&ray(o, d)).pair()),
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
            check_ray_sphere_roots(|o, d, c, r| textbook_disc(o, d, c, r, false)),
            "4 (r^2 - |f - (f . d) d|^2)",
        );
        // The stable roots alone do not repair a discriminant of the wrong sign.
        fails_with(
            check_ray_sphere_roots(|o, d, c, r| textbook_disc(o, d, c, r, true)),
            "STABILITY S1",
        );
    }

    /// Moller-Trumbore written out, with switches for the typical mistakes.
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
            check_moller_trumbore(|o, d, v0, v1, v2| {
                triangle(v0, v1, v2).moller_trumbore(&ray(o, d), Interval::AHEAD)
            }),
            Outcome::Pass
        );
        assert_eq!(
            check_moller_trumbore(moller_trumbore_with(MtMistakes::default())),
            Outcome::Pass
        );
        // The watertight test gives the same answers on these exact cases.
        assert_eq!(
            check_moller_trumbore(|o, d, v0, v1, v2| {
                triangle(v0, v1, v2)
                    .watertight(&ray(o, d), Interval::AHEAD)
                    .map(|(t, _, b1, b2)| (t, b1, b2))
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
            check_moller_trumbore(|o, d, v0, v1, v2| {
                swapped(o, d, v0, v1, v2).map(|(t, b1, b2)| (t, b2, b1))
            }),
            "swapped",
        );
    }

    // Chapter 08.

    /// Every shape's hit within `range`, in list order.
    fn every_hit<'a>(
        ray: &'a Ray,
        shapes: &'a [Shape],
        range: Interval,
    ) -> impl DoubleEndedIterator<Item = SceneHit> + 'a {
        shapes
            .iter()
            .enumerate()
            .filter_map(move |(object, s)| s.hit(ray, range).map(|hit| SceneHit { hit, object }))
    }

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
            every_hit(ray, shapes, range).min_by(|a, b| a.hit.t.total_cmp(&b.hit.t))
        };
        assert_eq!(check_closest(min_of_all), Outcome::Pass);
    }

    #[test]
    fn closest_rejects_mistakes() {
        fails_with(
            check_closest(|ray: &Ray, shapes: &[Shape], range| {
                every_hit(ray, shapes, range).next()
            }),
            "first hit",
        );
        fails_with(
            check_closest(|ray: &Ray, shapes: &[Shape], range| {
                every_hit(ray, shapes, range).next_back()
            }),
            "shrink range.max",
        );
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
            check_cosine_sample(|u| {
                malley(u, |x| (1.0 - x * x).max(0.0).sqrt(), |x| x, cos_over_pi)
            }),
            "uniform hemisphere",
        );
        // The pdf without its 1/pi.
        fails_with(
            check_cosine_sample(|u| malley(u, sqrt, lift, |w| w.z)),
            "misses 1/pi",
        );
        // The uniform density for cosine directions.
        fails_with(
            check_cosine_sample(|u| malley(u, sqrt, lift, |_| 1.0 / TAU)),
            "uniform hemisphere's density",
        );
        // The square root on the radius only: z = 1 - u.x is not unit length.
        fails_with(
            check_cosine_sample(|u| malley(u, sqrt, |x| 1.0 - x, cos_over_pi)),
            "unit length",
        );
        // No square root on the radius: r = u.x, lifted to unit length.
        fails_with(
            check_cosine_sample(|u| {
                malley(u, |x| x, |x| (1.0 - x * x).max(0.0).sqrt(), cos_over_pi)
            }),
            "r = sqrt(u.x)",
        );
        // A right sampler, u.x and u.y swapped.
        fails_with(
            check_cosine_sample(|u| malley(Vec2::new(u.y, u.x), sqrt, lift, cos_over_pi)),
            "swapped",
        );
    }

    // Chapter 11.

    /// The slab test as a student might write it, with its parts chosen by the flags:
    /// `swap` sorts t_near and t_far (`by_min_max`: with f32::min/max), `keep_nan`
    /// writes the updates so that a NaN changes nothing, `closed` accepts t0 == t1.
    fn slab_with(
        swap: bool,
        by_min_max: bool,
        keep_nan: bool,
        closed: bool,
    ) -> impl Fn(Vec3, Vec3, Vec3, Vec3, Interval) -> Option<(f32, f32)> {
        move |o, inv_d, min, max, range: Interval| {
            let (mut t0, mut t1) = (range.min, range.max);
            for i in 0..3 {
                let a = (min[i] - o[i]) * inv_d[i];
                let b = (max[i] - o[i]) * inv_d[i];
                let (near, far) = match (swap, by_min_max) {
                    (false, _) => (a, b),
                    (true, true) => (a.min(b), a.max(b)),
                    (true, false) if a > b => (b, a),
                    (true, false) => (a, b),
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
            Some((t0, t1))
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
            check_slab(slab_with(true, false, true, true)),
            Outcome::Pass
        );
    }

    #[test]
    fn slab_rejects_mistakes() {
        fails_with(
            check_slab(slab_with(false, false, true, true)),
            "swap t_near and t_far",
        );
        fails_with(
            check_slab(slab_with(true, false, true, false)),
            "the box is closed",
        );
        fails_with(
            check_slab(slab_with(true, true, true, true)),
            "f32::min and f32::max",
        );
        fails_with(
            check_slab(slab_with(true, false, false, true)),
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

    // The machinery.

    #[test]
    fn a_todo_is_not_started_and_other_panics_fail() {
        assert_eq!(
            check_pixel_to_plane(|_, _, _, _, _, _| todo!("Coding exercise 3.1")),
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
        let outcome = check_pixel_to_plane(|_, _, _, _, _, _| Vec2::ZERO);
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
    fn ch02_point_at() {
        expect_pass(POINT_AT, check_point_at(ch02::point_at));
    }

    #[test]
    fn ch03_pixel_to_plane() {
        expect_pass(PIXEL_TO_PLANE, check_pixel_to_plane(ch03::pixel_to_plane));
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
    fn ch06_pinhole_ray() {
        expect_pass(PINHOLE_RAY, check_pinhole_ray(ch06::pinhole_ray));
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
    fn ch09_covers() {
        expect_pass(COVERS, check_covers(ch09::covers));
    }

    #[test]
    fn ch10_cosine_sample() {
        expect_pass(COSINE_SAMPLE, check_cosine_sample(ch10::cosine_sample));
    }

    #[test]
    fn ch11_slab() {
        expect_pass(SLAB, check_slab(ch11::slab));
    }

    /// The table of every exercise's status; never fails. See it with
    /// `cargo test --features exercises --test exercises summary -- --nocapture`.
    #[test]
    fn summary() {
        let results = check_all();
        let passed = results.iter().filter(|(_, o)| *o == Outcome::Pass).count();
        println!("\nCoding exercises: {passed} of {} pass", results.len());
        for (exercise, outcome) in &results {
            println!("  {}", exercise.row(outcome));
        }
        println!();
    }
}
