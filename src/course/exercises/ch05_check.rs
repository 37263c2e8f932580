//! The check of chapter 05's coding exercise: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's function
//! is in `ch05.rs`, beside this file; the harness is `harness.rs`.

use glam::Vec3;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run, v};
use crate::camera::camera_basis;

/// Coding exercise 5.1.
pub const CAMERA_BASIS: Exercise = Exercise {
    number: "5.1",
    chapter: "05",
    chapter_title: "An arbitrary orthographic camera",
    function: "camera_basis",
    file: "src/course/exercises/ch05.rs",
};

type Uvw = (Vec3, Vec3, Vec3);

/// Checks `camera_basis(d, k)`: the camera basis (u, v, w) from a view direction `d`
/// and an up vector `k`, neither necessarily of unit length.
pub fn check_camera_basis(f: impl Fn(Vec3, Vec3) -> Uvw) -> Outcome {
    let cases: Vec<Case<(Vec3, Vec3)>> = [
        (v(0.0, 0.0, -1.0), Vec3::Y),
        (v(-1.0, 0.0, -1.0), Vec3::Y),
        (v(0.0, -1.0, 0.0), v(0.0, 0.0, -1.0)),
        (v(0.0, -1.0, -2.0), Vec3::Y),
        (v(0.0, 0.0, -5.0), v(0.0, 3.0, 0.0)),
        (v(1.0, 1.0, 1.0), v(0.0, 0.0, 1.0)),
    ]
    .into_iter()
    .map(|(d, k)| (format!("d = {}, k = {}", d.show(), k.show()), (d, k)))
    .collect();
    let wrong = |slide: bool| {
        move |&(d, k): &(Vec3, Vec3)| -> Option<Uvw> {
            let w = if slide { d.normalize() } else { -d.normalize() };
            let u = k.cross(w).normalize();
            Some((u, w.cross(u), w))
        }
    };
    run(
        &cases,
        |&(d, k)| {
            let b = camera_basis(d, k).expect("valid camera");
            (b.u(), b.v(), b.w())
        },
        |(d, k)| f(d, k),
        &[
            Mistake {
                looks_like: &gives(&wrong(true)),
                hint: "w must point from the scene back to the eye, w = -d/|d|. With the slides' \
                       w = d/|d| the local direction (0, 0, -1) becomes -d: the camera looks \
                       backwards",
            },
            Mistake {
                looks_like: &|&(d, k): &(Vec3, Vec3), got: &Uvw| {
                    got.1.close(&k.normalize()) && !got.1.close(&wrong(false)(&(d, k)).unwrap().1)
                },
                hint: "v is not the up vector: k need not be perpendicular to d. Take v = w x u",
            },
            Mistake {
                looks_like: &|&(d, k): &(Vec3, Vec3), got: &Uvw| {
                    let (u, v, w) = wrong(false)(&(d, k)).unwrap();
                    got.close(&(-u, v, w)) || got.close(&(-u, -v, w))
                },
                hint: "the order of a cross product matters: u = k x w (w x k points the other \
                       way and mirrors the image), then v = w x u",
            },
            Mistake {
                looks_like: &|_: &(Vec3, Vec3), got: &Uvw| {
                    !(got.0.length().close(&1.0)
                        && got.1.length().close(&1.0)
                        && got.2.length().close(&1.0))
                },
                hint: "u, v and w must have length 1: normalise d (for w) and k x w (for u)",
            },
        ],
        "w = -d/|d|, u = (k x w)/|k x w|, v = w x u",
    )
}
