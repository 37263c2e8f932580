//! The pitfalls lessons 01 to 05 warn about, as a student writes them: each a plain
//! function in an exercise's shape, which the exercise's check must fail with a hint
//! naming the mistake, so that a check that lets a warned mistake through fails CI.
//! The checks' references and their other wrong answers are in `lessons_01_05.rs`.

use glam::{Mat4, Vec2, Vec3};
use render_lessons::camera::{Film, Frame, camera_basis_as_on_slide};
use render_lessons::course::exercises::check::*;
use render_lessons::ray::Ray;
use render_lessons::transform::Transform;

use crate::common::fails_with;
use crate::lessons_01_05::uvw;

/// Lesson 01's pitfall "transposing by accident": the slide's rows handed to glam's
/// `from_cols_array_2d`, which takes columns, so -sin lands top-right.
fn rotation_y_rows_as_columns(theta: f32) -> Mat4 {
    let (s, c) = theta.sin_cos();
    Mat4::from_cols_array_2d(&[
        [c, 0.0, s, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [-s, 0.0, c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// Lesson 01: "the order of a product is the reverse of the order of events".
fn compose_in_the_order_of_events(first: &Transform, second: &Transform) -> Mat4 {
    first.matrix() * second.matrix()
}

/// Lesson 01, "row-major thinking in a column-major library": the product written
/// entry by entry as rows, then handed to glam as columns, a transposed matrix.
fn compose_row_by_row(first: &Transform, second: &Transform) -> Mat4 {
    let (a, b) = (second.matrix(), first.matrix());
    let mut rows = [[0.0; 4]; 4];
    for (i, row) in rows.iter_mut().enumerate() {
        for (j, entry) in row.iter_mut().enumerate() {
            *entry = (0..4).map(|k| a.row(i)[k] * b.col(j)[k]).sum();
        }
    }
    Mat4::from_cols_array_2d(&rows)
}

/// Lesson 02, "a direction that is not unit": t then counts lengths of d.
fn point_at_along_d(o: Vec3, d: Vec3, t: f32) -> Vec3 {
    o + t * d
}

/// Lesson 02, "lengths outside f32's range": d / |d| for a d whose |d|^2 overflows
/// or underflows.
fn point_at_normalising_d(o: Vec3, d: Vec3, t: f32) -> Vec3 {
    o + t * d.normalize()
}

/// Lesson 02, "forgetting t < 0": the line goes on behind the origin.
fn t_closest_clamped(ray: &Ray, p: Vec3) -> f32 {
    (p - ray.origin()).dot(ray.direction()).max(0.0)
}

/// Lesson 03, "rows from the bottom, rows from the top": the slide's formula with
/// the image's row.
fn pixel_to_plane_unflipped(film: &Film, px: u32, py: u32) -> Vec2 {
    let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
    let (w, h) = (film.width() as f32, film.height() as f32);
    Vec2::new(
        (px as f32 + 0.5) / w * (x1 - x0) + x0,
        (py as f32 + 0.5) / h * (y1 - y0) + y0,
    )
}

/// Lesson 03, "forgetting the +0.5": the pixel's corner, not its centre.
fn pixel_to_plane_corner(film: &Film, px: u32, py: u32) -> Vec2 {
    let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
    let (w, h) = (film.width() as f32, film.height() as f32);
    let y_pixel = (film.height() - 1 - py) as f32;
    Vec2::new(px as f32 / w * (x1 - x0) + x0, y_pixel / h * (y1 - y0) + y0)
}

/// Lesson 03, "non-square pixels": both axes scaled by the columns' pixel size.
fn pixel_to_plane_square_pixels(film: &Film, px: u32, py: u32) -> Vec2 {
    let ((x0, x1), (_, y1)) = (film.x_extent(), film.y_extent());
    let size = (x1 - x0) / film.width() as f32;
    Vec2::new(x0 + (px as f32 + 0.5) * size, y1 - (py as f32 + 0.5) * size)
}

/// Lesson 03's "+0.5" undone on the way back: a centre lands on a whole number.
fn plane_to_pixel_half_pixel_off(film: &Film, p: Vec2) -> Vec2 {
    film.plane_to_pixel(p) - 0.5
}

/// Lesson 04, "columns, not rows": B built from rows is B^T.
fn to_world_by_rows(u: Vec3, v: Vec3, w: Vec3, b: Vec3) -> Vec3 {
    glam::Mat3::from_cols(u, v, w).transpose() * b
}

/// Lesson 04: the way back taken with B itself, not B^T.
fn to_local_by_columns(u: Vec3, v: Vec3, w: Vec3, a: Vec3) -> Vec3 {
    glam::Mat3::from_cols(u, v, w) * a
}

/// Lesson 05's erratum: the slides' w = d/|d|, a camera looking backwards.
fn camera_basis_slides(d: Vec3, k: Vec3) -> (Vec3, Vec3, Vec3) {
    uvw(camera_basis_as_on_slide(d, k).unwrap())
}

/// Lesson 05, step 3 (STABILITY S10): step 1's formulas alone, no Gram-Schmidt step.
pub(crate) fn camera_basis_without_gram_schmidt(
    d: Vec3,
    k: Vec3,
) -> (Vec3, Vec3, Vec3) {
    let w = -d.normalize();
    let u = k.cross(w).normalize();
    (u, w.cross(u), w)
}

/// Lesson 05, "translating directions": the direction moved by p like a point.
fn ortho_ray_direction_translated(
    film: &Film,
    frame: &Frame,
    px: u32,
    py: u32,
) -> (Vec3, Vec3) {
    let o = film.pixel_to_plane(px, py).extend(0.0);
    (frame.point_to_world(o), frame.point_to_world(-Vec3::Z))
}

#[test]
fn every_exercise_of_lessons_01_to_05_fails_what_its_chapter_warns_about() {
    for (outcome, hint) in [
        (check_rotation_y(rotation_y_rows_as_columns), "bottom-left"),
        (
            check_compose(compose_in_the_order_of_events),
            "stands rightmost",
        ),
        (
            check_compose(compose_row_by_row),
            "the transpose of the right matrix",
        ),
        (check_point_at(point_at_along_d), "unit direction"),
        (
            check_point_at(point_at_normalising_d),
            "divide d by its largest component",
        ),
        (check_t_closest(t_closest_clamped), "do not clamp"),
        (check_pixel_to_plane(pixel_to_plane_unflipped), "row flip"),
        (check_pixel_to_plane(pixel_to_plane_corner), "add 0.5"),
        (
            check_pixel_to_plane(pixel_to_plane_square_pixels),
            "not square",
        ),
        (
            check_plane_to_pixel(plane_to_pixel_half_pixel_off),
            "half pixel",
        ),
        (check_to_world(to_world_by_rows), "to_local"),
        (check_to_local(to_local_by_columns), "to_world"),
        (check_camera_basis(camera_basis_slides), "backwards"),
        (
            check_camera_basis(camera_basis_without_gram_schmidt),
            "STABILITY S10",
        ),
        (
            check_ortho_ray(ortho_ray_direction_translated),
            "an arrow, not a point",
        ),
    ] {
        fails_with(outcome, hint);
    }
}
