//! Lesson 01: the slides' transformation matrices.

use crate::common::close;
use crate::examples::transforms as lesson;

use std::f32::consts::{FRAC_1_SQRT_2, FRAC_PI_2, FRAC_PI_4};

use clap::Parser;
use glam::{Mat4, Vec3};
use render_lessons::Error;
use render_lessons::error::Problem;
use render_lessons::transform::{Transform, point, vector};

#[test]
fn numbers() {
    // The example's defaults: 30 degrees, the point (1, 2, 3).
    let numbers = lesson::numbers(30.0, Vec3::new(1.0, 2.0, 3.0)).unwrap();
    insta::assert_snapshot!("numbers", numbers);
}

#[test]
fn defaults_are_the_books_values() {
    let args = lesson::Args::parse_from(["01_transforms"]);
    assert_eq!((args.angle, args.point), (30.0, Vec3::new(1.0, 2.0, 3.0)));
}

#[test]
fn slide_matrices_match_glam() {
    for degrees in [-170.0f32, -45.0, 0.0, 30.0, 90.0, 123.0] {
        let theta = degrees.to_radians();
        let pairs = [
            (Transform::rotation_x(theta), Mat4::from_rotation_x(theta)),
            (Transform::rotation_y(theta), Mat4::from_rotation_y(theta)),
            (Transform::rotation_z(theta), Mat4::from_rotation_z(theta)),
        ];
        for (ours, glam) in pairs {
            assert!(ours.matrix().abs_diff_eq(glam, 1e-6), "{degrees} degrees");
        }
    }
    let s = Transform::scale(2.0, -3.0, 0.5).matrix();
    assert_eq!(s, Mat4::from_scale(Vec3::new(2.0, -3.0, 0.5)));
    let t = Transform::translation(1.0, -2.0, 3.0).matrix();
    assert_eq!(t, Mat4::from_translation(Vec3::new(1.0, -2.0, 3.0)));
}

#[test]
fn translation_sits_in_the_last_column_as_on_the_slide() {
    let t = Transform::translation(4.0, 5.0, 6.0).matrix();
    assert_eq!(t.row(0).w, 4.0);
    assert_eq!(t.row(1).w, 5.0);
    assert_eq!(t.row(2).w, 6.0);
    assert_eq!(t.row(3), glam::Vec4::new(0.0, 0.0, 0.0, 1.0));
}

#[test]
fn rotation_x_of_y_by_a_quarter_turn_over_two() {
    let r = Transform::rotation_x(FRAC_PI_4);
    let expected = Vec3::new(0.0, FRAC_1_SQRT_2, FRAC_1_SQRT_2);
    assert!(close(r.point(Vec3::Y), expected, 1e-6));
}

#[test]
fn quarter_turns_follow_the_cyclic_order_x_y_z() {
    // About X, y goes to z; about Y, z goes to x; about Z, x goes to y.
    let quarter = FRAC_PI_2;
    assert!(close(
        Transform::rotation_x(quarter).vector(Vec3::Y),
        Vec3::Z,
        1e-6
    ));
    assert!(close(
        Transform::rotation_y(quarter).vector(Vec3::Z),
        Vec3::X,
        1e-6
    ));
    assert!(close(
        Transform::rotation_z(quarter).vector(Vec3::X),
        Vec3::Y,
        1e-6
    ));
    // The Y matrix has -sin in the bottom-left corner: x goes to -z.
    assert!(close(
        Transform::rotation_y(quarter).vector(Vec3::X),
        -Vec3::Z,
        1e-6
    ));
}

#[test]
fn translation_moves_points_but_not_vectors() {
    let t = Transform::translation(1.0, 2.0, 3.0);
    assert_eq!(t.apply(point(1.0, 1.0, 1.0)), point(2.0, 3.0, 4.0));
    assert_eq!(t.apply(vector(1.0, 1.0, 1.0)), vector(1.0, 1.0, 1.0));
}

#[test]
fn order_matters_translate_then_scale_vs_scale_then_translate() {
    let t = Transform::translation(1.0, 0.0, 0.0);
    let s = Transform::scale(2.0, 2.0, 2.0);
    // Move the origin to x = 1, then double: x = 2. Double the origin, then move: x =
    // 1.
    assert_eq!(t.then(s).point(Vec3::ZERO), Vec3::new(2.0, 0.0, 0.0));
    assert_eq!(s.then(t).point(Vec3::ZERO), Vec3::new(1.0, 0.0, 0.0));
    // `then` puts the first transformation on the right of the product.
    assert_eq!(t.then(s).matrix(), s.matrix() * t.matrix());
}

#[test]
fn lesson_orders_give_different_points() {
    let [(_, a), (_, b)] = lesson::two_orders(30.0).unwrap();
    let p = Vec3::new(1.0, 2.0, 3.0);
    // Rotating 30 degrees first leaves the translation (3, 0, 0) untouched; translating
    // first lets the rotation turn it too.
    let (s, c) = 30f32.to_radians().sin_cos();
    assert!(close(
        a.point(p),
        Vec3::new(c - 2.0 * s + 3.0, s + 2.0 * c, 3.0),
        1e-6
    ));
    assert!(close(
        b.point(p),
        Vec3::new(4.0 * c - 2.0 * s, 4.0 * s + 2.0 * c, 3.0),
        1e-6
    ));
}

#[test]
fn inverse_undoes_and_singular_is_an_error() {
    let m = Transform::rotation_y(0.7)
        .then(Transform::translation(3.0, -1.0, 2.0))
        .then(Transform::scale(2.0, 3.0, 4.0));
    let p = Vec3::new(0.3, -4.0, 9.0);
    assert!((m.inverse().unwrap().point(m.point(p)) - p).length() < 1e-5);
    let flat = Transform::scale(1.0, 0.0, 1.0);
    assert_eq!(
        flat.inverse(),
        Err(Error::Value {
            param: "transform",
            problem: Problem::Singular
        })
    );
}

#[test]
fn normals_use_the_inverse_transpose() {
    // Squash a 45-degree slope x + y = 0 to half height: the surface normal must stay
    // perpendicular to the squashed surface, which a plain matrix product breaks.
    let squash = Transform::scale(1.0, 0.5, 1.0);
    let n = squash.normal(Vec3::new(1.0, 1.0, 0.0)).unwrap();
    let tangent = squash.vector(Vec3::new(1.0, -1.0, 0.0));
    assert!(n.dot(tangent).abs() < 1e-6);
    assert!(squash.vector(Vec3::new(1.0, 1.0, 0.0)).dot(tangent).abs() > 0.1);
}

#[test]
fn non_finite_parameters_are_named() {
    // The slide constructors cannot fail for finite numbers, so they return the
    // Transform itself; a NaN or infinity is the caller's bug, refused by a panic
    // that names the parameter, never a matrix full of NaN.
    let message = |f: fn() -> Transform| {
        let err = std::panic::catch_unwind(f).expect_err("must panic");
        err.downcast_ref::<String>().cloned().unwrap_or_default()
    };
    assert_eq!(
        message(|| Transform::rotation_x(f32::NAN)),
        "angle_radians must be a finite number (got NaN)"
    );
    assert_eq!(
        message(|| Transform::scale(1.0, f32::INFINITY, 1.0)),
        "sy must be a finite number (got inf)"
    );
    assert_eq!(
        message(|| Transform::translation(1.0, 2.0, f32::NAN)),
        "dz must be a finite number (got NaN)"
    );
    // Any finite angle, however large, gives a finite rotation.
    for angle in [f32::MAX, -f32::MAX, 1e30, f32::MIN_POSITIVE] {
        for r in [
            Transform::rotation_x(angle),
            Transform::rotation_y(angle),
            Transform::rotation_z(angle),
        ] {
            assert!(r.matrix().is_finite(), "{angle}");
        }
    }
    // A matrix built by hand still comes back as an error naming it.
    assert_eq!(
        Transform::from_matrix(Mat4::NAN),
        Err(Error::Value {
            param: "matrix",
            problem: Problem::NotFinite
        })
    );
}

#[test]
fn figure_draws() {
    let rgba = lesson::order_figure(30.0).unwrap().rgba();
    let coloured = rgba.chunks(4).filter(|p| p[0] != p[2]).count();
    assert!(coloured > 1000, "the two moved houses are drawn in colour");
}

/// The numbers `01_transforms.md` and `01_1_rotation_y.md` work out by hand, computed
/// again with the crate's matrices.
#[test]
fn lesson_01_worked_numbers() {
    let a = 30f32.to_radians();
    let p = Vec3::new(1.0, 2.0, 3.0);
    // R_z p = (0.866 - 1, 0.5 + 1.732, 3): the 1.732 is 2 cos 30°.
    let rz = Transform::rotation_z(a).point(p);
    assert!(close(
        rz,
        Vec3::new(a.cos() - 1.0, 0.5 + 2.0 * a.cos(), 3.0),
        1e-6
    ));
    assert_eq!(format!("{:.3}", 2.0 * a.cos()), "1.732");
    // 30.0 handed to a function that takes radians turns by about 1719°.
    assert_eq!(format!("{:.0}", 30f32.to_degrees()), "1719");
    // R_y with the sines' signs swapped is the rotation by -30°: (-0.634, 2, 3.098).
    let wrong = Transform::rotation_y(-a).point(p);
    let shown = format!("{:.3} {:.3} {:.3}", wrong.x, wrong.y, wrong.z);
    assert_eq!(shown, "-0.634 2.000 3.098");
}

#[test]
fn mine_draws_the_order_figure_with_the_given_compose() {
    // The crate's composition, in the shape of exercise 1.6, draws the lesson's figure.
    fn reference(first: &Transform, second: &Transform) -> Mat4 {
        first.then(*second).matrix()
    }
    let mine = lesson::my_order_figure(30.0, reference).unwrap();
    assert_eq!(mine.rgba(), lesson::order_figure(30.0).unwrap().rgba());
    // The product the wrong way round moves the houses: a different picture.
    fn reversed(first: &Transform, second: &Transform) -> Mat4 {
        first.matrix() * second.matrix()
    }
    let wrong = lesson::my_order_figure(30.0, reversed).unwrap();
    assert_ne!(wrong.rgba(), lesson::order_figure(30.0).unwrap().rgba());
}
