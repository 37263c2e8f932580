//! The checks of the coding exercises of lessons 01 to 05, themselves checked (run by the
//! default test suite, without the `exercises` feature): each check must pass the
//! crate's reference and an independent answer, and must fail the wrong answers its
//! chapter warns about, each with a hint that names the mistake, so that a wrong check
//! fails CI. The student's own tests are in `tests/exercises.rs`.

use glam::{Mat4, Vec2, Vec3};
use render_lessons::basis::Basis;
use render_lessons::camera::{Film, Frame, OrthoCamera, camera_basis, camera_basis_as_on_slide};
use render_lessons::course::exercises::check::*;
use render_lessons::ray::Ray;
use render_lessons::transform::Transform;

mod exercise_common;
use exercise_common::fails_with;

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
