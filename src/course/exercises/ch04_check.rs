//! The check of chapter 04's coding exercises: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's function
//! is in `ch04.rs`, beside this file; the harness is `harness.rs`.

use glam::Vec3;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run, v};
use crate::basis::Basis;
use crate::camera::camera_basis;

/// Coding exercise 4.5.
pub const TO_WORLD: Exercise = Exercise {
    number: "4.5",
    chapter: "04",
    chapter_title: "Change of basis",
    function: "to_world",
    file: "src/course/exercises/ch04.rs",
};
/// Coding exercise 4.6.
pub const TO_LOCAL: Exercise = Exercise {
    number: "4.6",
    chapter: "04",
    chapter_title: "Change of basis",
    function: "to_local",
    file: "src/course/exercises/ch04.rs",
};

/// The bases the chapter 04 checks use: standard, turned by 30° and 90° about Z, a
/// camera's basis, and a left-handed one.
fn bases() -> Vec<(&'static str, Basis)> {
    let turned = |deg: f32| {
        let (s, c) = deg.to_radians().sin_cos();
        Basis::new(v(c, s, 0.0), v(-s, c, 0.0), Vec3::Z).expect("orthonormal")
    };
    vec![
        ("the standard basis", Basis::STANDARD),
        ("the basis turned by 30 degrees about Z", turned(30.0)),
        ("the basis turned by 90 degrees about Z", turned(90.0)),
        (
            "the camera basis of d = (-1, 0, -1), k = (0, 1, 0)",
            camera_basis(v(-1.0, 0.0, -1.0), Vec3::Y).expect("valid camera"),
        ),
        (
            "the left-handed basis u = (0, 1, 0), v = (1, 0, 0), w = (0, 0, 1)",
            Basis::new(Vec3::Y, Vec3::X, Vec3::Z).expect("orthonormal"),
        ),
    ]
}

type BasisArgs = (Vec3, Vec3, Vec3, Vec3);

fn basis_cases(name: &str) -> Vec<Case<BasisArgs>> {
    let coords = [
        v(1.0, 0.0, 0.0),
        v(0.0, 1.0, 0.0),
        v(1.0, 2.0, 3.0),
        v(3.0, 4.0, 0.0),
    ];
    bases()
        .into_iter()
        .flat_map(|(what, b)| {
            coords.into_iter().map(move |x| {
                (
                    format!(
                        "{name} = {} in {what}: u = {}, v = {}, w = {}",
                        x.show(),
                        b.u().show(),
                        b.v().show(),
                        b.w().show()
                    ),
                    (b.u(), b.v(), b.w(), x),
                )
            })
        })
        .collect()
}

fn basis(&(u, v, w, _): &BasisArgs) -> Basis {
    Basis::new(u, v, w).expect("orthonormal")
}

/// Checks `to_world(u, v, w, b)`: a = B b, from coordinates in the basis [u v w] to
/// world coordinates.
pub fn check_to_world(
    f: impl Fn(Vec3, Vec3, Vec3, Vec3) -> Vec3 + Send + Sync + 'static,
) -> Outcome {
    to_world_checked(Box::new(f))
}

/// [`check_to_world`] for the answer as a trait object: compiled once, here, not again
/// for every closure a test passes (see [`super::harness`]).
fn to_world_checked(
    f: Box<dyn Fn(Vec3, Vec3, Vec3, Vec3) -> Vec3 + Send + Sync>,
) -> Outcome {
    run(
        &basis_cases("b"),
        |a| basis(a).to_world(a.3),
        move |(u, v, w, b)| f(u, v, w, b),
        &[Mistake {
            looks_like: &gives(&|a: &BasisArgs| Some(basis(a).to_local(a.3))),
            hint: "dot products with u, v, w compute B^T a, the way back (to_local). a = B b \
                   weights the basis vectors: b.x u + b.y v + b.z w",
        }],
        "a = B b = b.x u + b.y v + b.z w, the basis vectors as the columns of B",
    )
}

/// Checks `to_local(u, v, w, a)`: b = B^T a, from world coordinates to coordinates
/// in the orthonormal basis [u v w].
pub fn check_to_local(
    f: impl Fn(Vec3, Vec3, Vec3, Vec3) -> Vec3 + Send + Sync + 'static,
) -> Outcome {
    to_local_checked(Box::new(f))
}

/// [`check_to_local`] for the answer as a trait object: compiled once, here, not again
/// for every closure a test passes (see [`super::harness`]).
fn to_local_checked(
    f: Box<dyn Fn(Vec3, Vec3, Vec3, Vec3) -> Vec3 + Send + Sync>,
) -> Outcome {
    run(
        &basis_cases("a"),
        |a| basis(a).to_local(a.3),
        move |(u, v, w, a)| f(u, v, w, a),
        &[Mistake {
            looks_like: &gives(&|a: &BasisArgs| Some(basis(a).to_world(a.3))),
            hint: "a.x u + a.y v + a.z w is B a, the other direction (to_world). The way back is \
                   B^T a: one dot product per basis vector, (a . u, a . v, a . w)",
        }],
        "b = B^T a = (a . u, a . v, a . w): B is orthonormal, so its inverse is its transpose",
    )
}
