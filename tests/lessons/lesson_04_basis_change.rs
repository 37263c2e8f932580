//! Lesson 04: a vector in two orthonormal bases.

use crate::common;
use crate::examples::basis_change as lesson;

use clap::Parser;
use glam::Vec3;
use render_lessons::Error;
use render_lessons::basis::Basis;
use render_lessons::error::Problem;

/// The example's defaults: the basis turned 30 degrees, b = (2, 1, 0).
const ANGLE: f32 = 30.0;
const B: Vec3 = Vec3::new(2.0, 1.0, 0.0);

#[test]
fn defaults_are_the_books_values() {
    let args = lesson::Args::parse_from(["04_basis_change"]);
    assert_eq!((args.angle, args.b), (ANGLE, B));
}

#[test]
fn numbers() {
    insta::assert_snapshot!("numbers", lesson::numbers(ANGLE, B).unwrap());
}

#[test]
fn standard_basis_changes_nothing() {
    let s = Vec3::new(3.0, -1.0, 2.5);
    assert_eq!(Basis::STANDARD.to_world(s), s);
    assert_eq!(Basis::STANDARD.to_local(s), s);
}

#[test]
fn a_equals_b_times_b_by_hand() {
    // u = (0, 1, 0), v = (-1, 0, 0), w = (0, 0, 1): a quarter turn about z.
    let basis = Basis::new(Vec3::Y, Vec3::NEG_X, Vec3::Z).unwrap();
    // b = (2, 1, 3) means 2u + 1v + 3w = (0, 2, 0) + (-1, 0, 0) + (0, 0, 3).
    assert_eq!(
        basis.to_world(Vec3::new(2.0, 1.0, 3.0)),
        Vec3::new(-1.0, 2.0, 3.0)
    );
    assert_eq!(
        basis.to_local(Vec3::new(-1.0, 2.0, 3.0)),
        Vec3::new(2.0, 1.0, 3.0)
    );
    assert_eq!(
        basis.matrix() * Vec3::new(2.0, 1.0, 3.0),
        Vec3::new(-1.0, 2.0, 3.0)
    );
}

#[test]
fn not_orthonormal_is_refused() {
    let skew = Basis::new(Vec3::X, Vec3::new(0.5, 1.0, 0.0).normalize(), Vec3::Z);
    assert_eq!(skew.unwrap_err().param(), "basis");
    assert_eq!(
        Basis::new(Vec3::X, Vec3::Y * 2.0, Vec3::Z)
            .unwrap_err()
            .param(),
        "basis"
    );
    assert_eq!(
        Basis::new(Vec3::NAN, Vec3::Y, Vec3::Z),
        Err(Error::Value {
            param: "u",
            problem: Problem::NotFinite
        })
    );
}

#[test]
fn a_mirrored_basis_is_orthonormal_but_left_handed() {
    let left = Basis::new(Vec3::X, Vec3::Y, Vec3::NEG_Z).unwrap();
    assert!(!left.is_right_handed());
    assert!(Basis::STANDARD.is_right_handed());
}

#[test]
fn round_trip_and_length_hold_for_any_rotated_basis() {
    common::for_cases(4, 256, |rng| {
        let q = rng.rotation();
        let b = rng.point(10.0);
        let basis = Basis::new(q * Vec3::X, q * Vec3::Y, q * Vec3::Z).unwrap();
        let a = basis.to_world(b);
        assert!((basis.to_local(a) - b).length() <= 1e-5 * (1.0 + b.length()));
        assert!((a.length() - b.length()).abs() <= 1e-5 * (1.0 + b.length()));
        assert!(basis.orthonormality_error() < 1e-5);
        assert!(basis.is_right_handed());
        assert!((basis.u().cross(basis.v()) - basis.w()).length() < 1e-5);
    });
}

#[test]
fn lesson_round_trip_is_exact_enough() {
    let basis = lesson::turned_basis(ANGLE).unwrap();
    let back = basis.to_local(basis.to_world(B));
    assert!((back - B).length() < 1e-6);
}

#[test]
fn figure_draws() {
    let rgba = lesson::bases_figure(ANGLE, B).unwrap().rgba();
    assert!(common::blue_pixels(&rgba) > 300);
}

#[test]
fn s12_frisvad_breaks_near_minus_z_and_duff_does_not() {
    // STABILITY S12: a unit normal just outside Frisvad's -Z guard. Its z is given
    // there as -0.99999988079, which is the f32 written here as -0.9999999.
    let n = Vec3::new(0.000_385_273_16, 0.000_384_600_16, -0.999_999_9);
    assert_eq!(n.z, "-0.99999988079".parse::<f32>().unwrap());
    let frisvad = Basis::around_frisvad(n).orthonormality_error();
    let duff = Basis::around(n).orthonormality_error();
    eprintln!("S12: Frisvad error {frisvad:.1e}, Duff et al. {duff:.1e}");
    assert!(
        frisvad > 0.1,
        "Frisvad's basis is far from orthonormal: {frisvad}"
    );
    assert!(duff < 1e-6, "Duff et al.'s stays orthonormal: {duff}");
    // What where_methods_fail_cameras.md prints.
    assert_eq!(format!("{frisvad:.2} {duff}"), "0.61 0");
    // The page's explanation and exercise: |u|^2 - 1 = n_x^2 (|n|^2 - 1) / (1 + n_z)^2,
    // with |n|^2 - 1 computed in f64 from the f32 components.
    let (nx2, len2) = (
        f64::from(n.x).powi(2),
        f64::from(n.x).powi(2) + f64::from(n.y).powi(2) + f64::from(n.z).powi(2) - 1.0,
    );
    let one_plus_nz = 1.0 + f64::from(n.z);
    assert_eq!(one_plus_nz, 2f64.powi(-23));
    let shown = format!("{nx2:.3e} {len2:.2e} {:.2e}", one_plus_nz * one_plus_nz);
    assert_eq!(shown, "1.484e-7 5.79e-8 1.42e-14");
    let shown = format!("{nx2:.1e} {len2:.1e} {one_plus_nz:.2e}");
    assert_eq!(shown, "1.5e-7 5.8e-8 1.19e-7");
    let predicted = nx2 * len2 / (one_plus_nz * one_plus_nz);
    assert_eq!(format!("{predicted:.3}"), "0.605");
    // Duff's denominator (1 + |n_z|)^2 is about 4.
    assert_eq!(format!("{:.0e}", nx2 * len2 / 4.0), "2e-15");
    assert!(Basis::around(n).is_right_handed());
}

#[test]
fn duff_basis_is_orthonormal_and_right_handed_for_any_normal() {
    common::for_cases(44, 256, |rng| {
        let n = rng.rotation() * Vec3::Z;
        let b = Basis::around(n);
        assert!(b.orthonormality_error() < 1e-5);
        assert!(b.is_right_handed());
        assert_eq!(b.w(), n);
    });
}

/// The numbers `04_basis_change.md` works out by hand, computed again with `Basis`.
#[test]
fn lesson_04_worked_numbers() {
    let a = 30f32.to_radians();
    let basis = Basis::new(
        Vec3::new(a.cos(), a.sin(), 0.0),
        Vec3::new(-a.sin(), a.cos(), 0.0),
        Vec3::Z,
    )
    .unwrap();
    let show = |v: Vec3, digits: usize| format!("{:.digits$} {:.digits$}", v.x, v.y);
    // b = (2, 1, 0): a = 2u + v = (1.7321 - 0.5, 1 + 0.8660, 0).
    assert_eq!(format!("{:.4}", 2.0 * basis.u().x), "1.7321");
    assert_eq!(
        show(basis.to_world(Vec3::new(2.0, 1.0, 0.0)), 4),
        "1.2321 1.8660"
    );
    // Exercise 4.6: a = (3, 4, 0) has b = (4.598, 1.964, 0), of length 5.
    let b = basis.to_local(Vec3::new(3.0, 4.0, 0.0));
    assert_eq!(show(b, 3), "4.598 1.964");
    assert!((b.length() - 5.0).abs() < 1e-5);
    // ... and `--b 4.598,1.964,0` takes it back to (3.0000, 3.9999, 0): the input's
    // three decimals, not the basis, lose the last digit.
    let typed = basis.to_world(Vec3::new(4.598, 1.964, 0.0));
    assert_eq!(show(typed, 4), "3.0000 3.9999");
    // Exercise 4.3: the 45° basis, b = (1, 1, 0) gives a = (0, 1.4142, 0).
    let q = 45f32.to_radians();
    let turned = Basis::new(
        Vec3::new(q.cos(), q.sin(), 0.0),
        Vec3::new(-q.sin(), q.cos(), 0.0),
        Vec3::Z,
    )
    .unwrap();
    assert_eq!(
        show(turned.to_world(Vec3::new(1.0, 1.0, 0.0)), 4),
        "0.0000 1.4142"
    );
    // Exercise 4.4: the lesson at `--angle 45 --b 1,1,0` prints |B^T a - b|, "about
    // 8e-8" on the page, from the same basis the lesson makes.
    let b = Vec3::new(1.0, 1.0, 0.0);
    let basis = lesson::turned_basis(45.0).unwrap();
    let error = (basis.to_local(basis.to_world(b)) - b).length();
    eprintln!("exercise 4.4: |B^T a - b| = {error:e}");
    assert_eq!(format!("{error:.0e}"), "8e-8");
    let numbers = lesson::numbers(45.0, b).unwrap();
    assert!(numbers.contains(&format!("{error:.1e}")), "{numbers}");
}
