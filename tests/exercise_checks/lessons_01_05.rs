//! The checks of the coding exercises of lessons 01 to 05, themselves checked (run by
//! the default test suite): each check must pass the crate's reference and an
//! independent answer, and must fail wrong answers, each with a hint that names the
//! mistake, so that a wrong check fails CI. The mistakes the chapters warn about, as a
//! student writes them, are in `pitfalls_01_05.rs`; the student's own tests in
//! `tests/exercises.rs`.

use glam::{Mat4, Vec2, Vec3};
use render_lessons::basis::Basis;
use render_lessons::camera::{Film, Frame, OrthoCamera, camera_basis};
use render_lessons::course::exercises::check::*;
use render_lessons::ray::Ray;
use render_lessons::transform::Transform;

use crate::common::{fails_with, slide_film};
use crate::pitfalls_01_05::camera_basis_without_gram_schmidt;

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
    fails_with(
        check_rotation_y(|theta| Mat4::from_rotation_y(theta.to_radians())),
        "radians",
    );
    fails_with(check_rotation_y(|_| Mat4::IDENTITY), "x' = x cos + z sin");
}

#[test]
fn compose_accepts_the_reference() {
    assert_eq!(
        check_compose(|first: &Transform, second: &Transform| first
            .then(*second)
            .matrix()),
        Outcome::Pass
    );
    assert_eq!(check_compose(compose_solution), Outcome::Pass);
    // `*` on transforms is written in the paper's order: `b * a` is "first a, then b".
    assert_eq!(
        check_compose(
            |first: &Transform, second: &Transform| (*second * *first).matrix()
        ),
        Outcome::Pass
    );
}

#[test]
fn compose_rejects_mistakes() {
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
    // Rescaled by the largest component first, as lesson 02's last pitfall asks.
    assert_eq!(
        check_point_at(|o, d: Vec3, t| {
            let d = d / d.abs().max_element();
            o + t * d / d.length()
        }),
        Outcome::Pass
    );
}

#[test]
fn point_at_rejects_mistakes() {
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
    let slide = slide_film();
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
    let one_off: fn(&Film, u32) -> f32 = |film, py| (film.height() - py) as f32;
    fails_with(
        check_pixel_to_plane(pixel_to_plane_with(one_off, 0.5)),
        "off by one",
    );
}

/// `plane_to_pixel` written out, with the row as `row(height, sy)` and `shift`
/// added to both coordinates.
fn plane_to_pixel_with(
    row: fn(f32, f32) -> f32,
    shift: f32,
) -> impl Fn(&Film, Vec2) -> Vec2 {
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
    fails_with(check_to_world(|_, _, _, b| b), "columns of B");
    fails_with(check_to_local(|_, _, _, a| a), "B^T a");
}

// Chapter 05.

pub(crate) fn uvw(b: Basis) -> (Vec3, Vec3, Vec3) {
    (b.u(), b.v(), b.w())
}

#[test]
fn camera_basis_accepts_the_reference() {
    assert_eq!(
        check_camera_basis(|d, k| uvw(camera_basis(d, k).unwrap())),
        Outcome::Pass
    );
    // Step 1's formulas and step 3's Gram-Schmidt step, with k normalised first: the
    // roll of S10's case differs from the crate's by rounding, and passes.
    let with_gram_schmidt = |d: Vec3, k: Vec3| {
        let w = -d.normalize();
        let u = k.normalize().cross(w).normalize();
        let u = (u - u.dot(w) * w).normalize();
        (u, w.cross(u), w)
    };
    assert_eq!(check_camera_basis(with_gram_schmidt), Outcome::Pass);
}

#[test]
fn camera_basis_rejects_mistakes() {
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

/// The exercise's S10 case, as `05_1_coding_exercises.md` quotes it: step 1's formulas
/// leave the basis about 4e-4 from orthonormal, the Gram-Schmidt step 1e-7.
#[test]
fn s10_case_the_formulas_alone_are_4e_4_from_orthonormal() {
    let (d, k) = (
        Vec3::new(1.0, 2.0, -3.0),
        Vec3::new(0.267_270_18, 0.534_518, -0.801_783_74),
    );
    let angle = k
        .as_dvec3()
        .normalize()
        .angle_between(d.as_dvec3().normalize());
    assert!((angle - 1e-5).abs() < 1e-7, "{angle:e}");
    let off = |(u, v, w): (Vec3, Vec3, Vec3)| {
        let b = glam::Mat3::from_cols(u, v, w);
        (b.transpose() * b - glam::Mat3::IDENTITY)
            .abs()
            .to_cols_array()
            .into_iter()
            .fold(0.0, f32::max)
    };
    let plain = off(camera_basis_without_gram_schmidt(d, k));
    assert!((plain - 4e-4).abs() < 0.5e-4, "{plain:e}");
    let robust = off(uvw(camera_basis(d, k).unwrap()));
    assert!(robust < 2e-7, "{robust:e}");
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
