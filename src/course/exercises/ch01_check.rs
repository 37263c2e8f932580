//! The check of chapter 01's coding exercise: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's function
//! is in `ch01.rs`, beside this file; the harness is `harness.rs`.

use glam::Mat4;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run};

/// Coding exercise 1.1.
pub const ROTATION_Y: Exercise = Exercise {
    number: "1.1",
    chapter: "01",
    chapter_title: "Geometric transformations",
    function: "rotation_y",
    file: "src/course/exercises/ch01.rs",
};

/// Checks `rotation_y(theta)`: the slide's 4x4 rotation about Y, `theta` in radians.
pub fn check_rotation_y(f: impl Fn(f32) -> Mat4) -> Outcome {
    let cases: Vec<Case<f32>> = [0.5f32, 1.0, -0.3, 2.0, std::f32::consts::FRAC_PI_2]
        .into_iter()
        .map(|theta| (format!("theta = {} rad", theta.show()), theta))
        .collect();
    let reference = |theta: f32| crate::transform::Transform::rotation_y(theta).matrix();
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
