//! The checks of chapter 01's coding exercises: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's functions
//! are in `ch01.rs`, beside this file; the harness is `harness.rs`.

use glam::Mat4;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run};
use crate::transform::Transform;

/// Coding exercise 1.5.
pub const ROTATION_Y: Exercise = Exercise {
    number: "1.5",
    chapter: "01",
    chapter_title: "Geometric transformations",
    function: "rotation_y",
    file: "src/course/exercises/ch01.rs",
};
/// Coding exercise 1.6.
pub const COMPOSE: Exercise = Exercise {
    number: "1.6",
    chapter: "01",
    chapter_title: "Geometric transformations",
    function: "compose",
    file: "src/course/exercises/ch01.rs",
};

/// Checks `rotation_y(theta)`: the slide's 4x4 rotation about Y, `theta` in radians.
pub fn check_rotation_y(f: impl Fn(f32) -> Mat4 + Send + Sync + 'static) -> Outcome {
    rotation_y_checked(Box::new(f))
}

/// [`check_rotation_y`] for the answer as a trait object: compiled once, here, not
/// again for every closure a test passes (see [`super::harness`]).
fn rotation_y_checked(f: Box<dyn Fn(f32) -> Mat4 + Send + Sync>) -> Outcome {
    let cases: Vec<Case<f32>> = [0.5f32, 1.0, -0.3, 2.0, std::f32::consts::FRAC_PI_2]
        .into_iter()
        .map(|theta| (format!("theta = {} rad", theta.show()), theta))
        .collect();
    let reference =
        |theta: f32| crate::transform::Transform::rotation_y(theta).matrix();
    run(
        &cases,
        |&theta| reference(theta),
        f,
        &[
            Mistake {
                looks_like: &gives(&|&theta: &f32| Some(reference(-theta))),
                hint: "the -sin belongs in the bottom-left corner (row 3, column 1) for Y: the rotation \
                       turns z towards x. If you passed the slide's rows to Mat4::from_cols_array_2d, \
                       glam read them as columns: transpose, or use transform::from_rows",
            },
            Mistake {
                looks_like: &gives(&|&theta: &f32| Some(reference(theta.to_radians()))),
                hint: "theta is already in radians: do not convert it",
            },
        ],
        "x' = x cos + z sin, y' = y, z' = -x sin + z cos, written as a 4x4 matrix with w untouched",
    )
}

// ANCHOR: compose
/// A worked solution of exercise 1.6: the first transformation stands on the right,
/// next to the point it acts on first.
pub fn compose_solution(first: &Transform, second: &Transform) -> Mat4 {
    second.matrix() * first.matrix()
}
// ANCHOR_END: compose

/// The arguments of `compose`: first, then second.
type ComposeArgs = (Transform, Transform);

/// Checks `compose(first, second)`: the matrix of "first `first`, then `second`".
pub fn check_compose(
    f: impl Fn(&Transform, &Transform) -> Mat4 + Send + Sync + 'static,
) -> Outcome {
    compose_checked(Box::new(f))
}

/// [`check_compose`] for the answer as a trait object: compiled once, here, not again
/// for every closure a test passes (see [`super::harness`]).
fn compose_checked(
    f: Box<dyn Fn(&Transform, &Transform) -> Mat4 + Send + Sync>,
) -> Outcome {
    let theta = 30f32.to_radians();
    let rotate_z = Transform::rotation_z(theta);
    let rotate_x = Transform::rotation_x(theta);
    let rotate_y = Transform::rotation_y(theta);
    let translate = Transform::translation(3.0, 0.0, 0.0);
    let lift = Transform::translation(0.0, 0.0, 3.0);
    let scale = Transform::scale(2.0, 0.5, 1.0);
    let cases: Vec<Case<ComposeArgs>> = [
        (
            "rotate 30 degrees about Z, then translate by (3, 0, 0)",
            rotate_z,
            translate,
        ),
        (
            "translate by (3, 0, 0), then rotate 30 degrees about Z",
            translate,
            rotate_z,
        ),
        (
            "translate by (0, 0, 3) along the axis, then rotate 30 degrees about Z",
            lift,
            rotate_z,
        ),
        (
            "scale by (2, 0.5, 1), then rotate 30 degrees about Y",
            scale,
            rotate_y,
        ),
        (
            "rotate 30 degrees about X, then 30 degrees about Y",
            rotate_x,
            rotate_y,
        ),
        (
            "the identity, then translate by (3, 0, 0)",
            Transform::IDENTITY,
            translate,
        ),
    ]
    .into_iter()
    .map(|(case, first, second)| (case.to_string(), (first, second)))
    .collect();
    run(
        &cases,
        |&(first, second)| first.then(second).matrix(),
        move |(first, second)| f(&first, &second),
        &[
            Mistake {
                looks_like: &gives(&|&(first, second): &ComposeArgs| {
                    Some(first.matrix() * second.matrix())
                }),
                hint: "that is first `second`, then `first`: a matrix acts on the vector to its \
                       right, so the transformation applied first stands rightmost, \
                       second.matrix() * first.matrix()",
            },
            Mistake {
                looks_like: &gives(&|&(first, second): &ComposeArgs| {
                    Some((second.matrix() * first.matrix()).transpose())
                }),
                hint: "that is the transpose of the right matrix (its translation sits in the \
                       bottom row): glam's Mat4 is stored column by column, so rows written as \
                       they are printed, or an entry [i][j] filled as [j][i], transpose it. \
                       Multiply the matrices with glam's *, second.matrix() * first.matrix()",
            },
            Mistake {
                looks_like: &|&(first, second): &ComposeArgs, got: &Mat4| {
                    got.close(&first.matrix()) || got.close(&second.matrix())
                },
                hint: "the answer is one of the two matrices: multiply them, \
                       second.matrix() * first.matrix()",
            },
        ],
        "first `first`, then `second` is the product second.matrix() * first.matrix(): the \
         first one stands on the right",
    )
}
