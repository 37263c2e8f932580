//! The checks of chapter 05's coding exercises: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's functions
//! are in `ch05.rs`, beside this file; the harness is `harness.rs`.

use glam::Vec3;

use super::harness::{
    Answer, Case, Exercise, Mistake, Outcome, gives, run, run_compared, v,
};
use crate::camera::{Film, Frame, OrthoCamera, camera_basis};

/// Coding exercise 5.4.
pub const CAMERA_BASIS: Exercise = Exercise {
    number: "5.4",
    chapter: "05",
    chapter_title: "An arbitrary orthographic camera",
    function: "camera_basis",
    file: "src/course/exercises/ch05.rs",
};
/// Coding exercise 5.5.
pub const ORTHO_RAY: Exercise = Exercise {
    number: "5.5",
    chapter: "05",
    chapter_title: "An arbitrary orthographic camera",
    function: "ortho_ray",
    file: "src/course/exercises/ch05.rs",
};

type Uvw = (Vec3, Vec3, Vec3);

/// STABILITY S10's case: the view direction (1, 2, -3) and an up vector 1e-5 rad
/// from it (`k` as the f32 nearest the unit vector turned by 1e-5 rad towards
/// (2, -1, 0)/sqrt(5)). The three formulas of lesson 05's step 1 give a basis
/// 4e-4 from orthonormal here; one Gram-Schmidt step (step 3) brings it to 1e-7.
const S10: (Vec3, Vec3) = (
    Vec3::new(1.0, 2.0, -3.0),
    Vec3::new(0.267_270_18, 0.534_518, -0.801_783_74),
);

/// How far `(u, v, w)` is from orthonormal: the largest entry of B^T B - I.
fn off_orthonormal(&(u, v, w): &Uvw) -> f32 {
    let b = [u, v, w];
    let mut worst = 0.0f32;
    for (i, x) in b.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            let identity = if i == j { 1.0 } else { 0.0 };
            worst = worst.max((x.dot(*y) - identity).abs());
        }
    }
    worst
}

/// Is `got` right for the camera `(d, k)`? Within the tolerance of the reference, but
/// for S10's nearly parallel up vector: there rounding decides the camera's roll to
/// about 1e-3 whatever the order of the operations, so any basis within 0.02 of the
/// reference is right if it is orthonormal to 1e-5 (the Gram-Schmidt step gives
/// 1e-7, the formulas without it 4e-4).
fn right_basis(&(d, k): &(Vec3, Vec3), expected: &Uvw, got: &Uvw) -> bool {
    if (d, k) != S10 {
        return got.close(expected);
    }
    let near = |a: Vec3, b: Vec3| (a - b).abs().max_element() <= 0.02;
    near(got.0, expected.0)
        && near(got.1, expected.1)
        && near(got.2, expected.2)
        && off_orthonormal(got) <= 1e-5
}

/// Checks `camera_basis(d, k)`: the camera basis (u, v, w) from a view direction `d`
/// and an up vector `k`, neither necessarily of unit length; the last case is
/// STABILITY S10's up vector nearly parallel to `d`.
pub fn check_camera_basis(
    f: impl Fn(Vec3, Vec3) -> Uvw + Send + Sync + 'static,
) -> Outcome {
    camera_basis_checked(Box::new(f))
}

/// [`check_camera_basis`] for the answer as a trait object: compiled once, here, not
/// again for every closure a test passes (see [`super::harness`]).
fn camera_basis_checked(f: Box<dyn Fn(Vec3, Vec3) -> Uvw + Send + Sync>) -> Outcome {
    let mut cases: Vec<Case<(Vec3, Vec3)>> = [
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
    cases.push((
        format!(
            "d = {}, k = ({:?}, {:?}, {:?}), 1e-5 rad from d (STABILITY S10: up nearly \
             parallel to the view direction)",
            S10.0.show(),
            S10.1.x,
            S10.1.y,
            S10.1.z
        ),
        S10,
    ));
    let wrong = |slide: bool| {
        move |&(d, k): &(Vec3, Vec3)| -> Option<Uvw> {
            let w = if slide { d.normalize() } else { -d.normalize() };
            let u = k.cross(w).normalize();
            Some((u, w.cross(u), w))
        }
    };
    run_compared(
        &cases,
        |&(d, k)| {
            let b = camera_basis(d, k).expect("valid camera");
            (b.u(), b.v(), b.w())
        },
        move |(d, k)| f(d, k),
        right_basis,
        &[
            Mistake {
                looks_like: &|&(d, k): &(Vec3, Vec3), got: &Uvw| {
                    (d, k) == S10
                        && off_orthonormal(got) > 1e-5
                        && got.2.close(&-d.normalize())
                },
                hint: "k is only 1e-5 rad from d here (STABILITY S10): k x w is tiny, and the \
                       rounding of its components tilts u out of the plane perpendicular to w, \
                       so the basis is not orthonormal. Project u off w once more and normalise \
                       it again, u = (u - (u . w) w) / |u - (u . w) w| (lesson 05, step 3), then \
                       v = w x u",
            },
            Mistake {
                looks_like: &gives(&wrong(true)),
                hint: "w must point from the scene back to the eye, w = -d/|d|. With the slides' \
                       w = d/|d| the local direction (0, 0, -1) becomes -d: the camera looks \
                       backwards",
            },
            Mistake {
                looks_like: &|&(d, k): &(Vec3, Vec3), got: &Uvw| {
                    got.1.close(&k.normalize())
                        && !got.1.close(&wrong(false)(&(d, k)).unwrap().1)
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
        "w = -d/|d|, u = (k x w)/|k x w| projected off w once more and normalised again \
         (u - (u . w) w, for an up vector nearly parallel to d), v = w x u",
    )
}

// ANCHOR: ortho_ray
/// A worked solution of exercise 5.5: the origin is a point, turned by B and moved
/// to p; the direction is an arrow, only turned.
pub fn ortho_ray_solution(
    film: &Film,
    frame: &Frame,
    px: u32,
    py: u32,
) -> (Vec3, Vec3) {
    let origin = film.pixel_to_plane(px, py).extend(0.0);
    let direction = Vec3::new(0.0, 0.0, -1.0);
    let b = frame.basis();
    (b.to_world(origin) + frame.position(), b.to_world(direction))
}
// ANCHOR_END: ortho_ray

type OrthoArgs = (Film, Frame, u32, u32);

/// Checks `ortho_ray(film, frame, px, py)`: the world-space (origin, unit direction)
/// of the orthographic camera's ray of pixel (`px`, `py`).
pub fn check_ortho_ray(
    f: impl Fn(&Film, &Frame, u32, u32) -> (Vec3, Vec3) + Send + Sync + 'static,
) -> Outcome {
    ortho_ray_checked(Box::new(f))
}

/// [`check_ortho_ray`] for the answer as a trait object: compiled once, here, not again
/// for every closure a test passes (see [`super::harness`]).
fn ortho_ray_checked(
    f: Box<dyn Fn(&Film, &Frame, u32, u32) -> (Vec3, Vec3) + Send + Sync>,
) -> Outcome {
    let film = Film::new(4, 3, (-8.0, 8.0), (-6.0, 6.0)).expect("valid film");
    let look = |p, d, k| Frame::look(p, d, k).expect("valid frame");
    let lesson = look(v(6.0, 0.0, 6.0), v(-1.0, 0.0, -1.0), Vec3::Y);
    let tilted = look(v(0.0, 3.0, 6.0), v(0.0, -1.0, -2.0), Vec3::Y);
    let cases: Vec<Case<OrthoArgs>> = [
        (Frame::AT_ORIGIN, 0, 0, "at the origin, looking down -Z"),
        (
            lesson,
            0,
            0,
            "at (6, 0, 6) looking along (-1, 0, -1), up (0, 1, 0)",
        ),
        (
            lesson,
            3,
            2,
            "at (6, 0, 6) looking along (-1, 0, -1), up (0, 1, 0)",
        ),
        (
            tilted,
            1,
            1,
            "at (0, 3, 6) looking along (0, -1, -2), up (0, 1, 0)",
        ),
        (
            tilted,
            2,
            0,
            "at (0, 3, 6) looking along (0, -1, -2), up (0, 1, 0)",
        ),
    ]
    .into_iter()
    .map(|(frame, px, py, where_)| {
        (
            format!(
                "pixel ({px}, {py}), 4x3 film over [-8, 8] x [-6, 6], camera {where_}"
            ),
            (film, frame, px, py),
        )
    })
    .collect();
    let local = |a: &OrthoArgs| (a.0.pixel_to_plane(a.2, a.3).extend(0.0), -Vec3::Z);
    let b = |a: &OrthoArgs| a.1.basis();
    run(
        &cases,
        |&(film, frame, px, py)| {
            let ray = OrthoCamera::new(film, frame).ray(px, py);
            (ray.origin(), ray.direction())
        },
        move |(film, frame, px, py)| f(&film, &frame, px, py),
        &[
            Mistake {
                looks_like: &gives(&|a: &OrthoArgs| {
                    let (o, d) = local(a);
                    Some((b(a).to_world(o), b(a).to_world(d)))
                }),
                hint: "the origin is a point: after turning it with B, move it to the camera's \
                       position, B o + p",
            },
            Mistake {
                looks_like: &gives(&|a: &OrthoArgs| {
                    let (o, d) = local(a);
                    let p = a.1.position();
                    Some((b(a).to_world(o) + p, b(a).to_world(d) + p))
                }),
                hint: "the direction is an arrow, not a point: turn it with B, but do not add p \
                       (the w = 0 of lesson 01)",
            },
            Mistake {
                looks_like: &|_: &OrthoArgs, got: &(Vec3, Vec3)| got.1.close(&-Vec3::Z),
                hint: "(0, 0, -1) is the direction in camera space: carry it to the world with \
                       B, d_world = B (0, 0, -1) = -w",
            },
            Mistake {
                looks_like: &gives(&|a: &OrthoArgs| {
                    let (o, d) = local(a);
                    let p = a.1.position();
                    Some((b(a).to_local(o) + p, b(a).to_local(d)))
                }),
                hint: "to_local computes B^T x, the way from the world into camera space; \
                       camera space to the world is B x (to_world)",
            },
        ],
        "origin B (x, y, 0) + p with (x, y) the pixel centre on the film; direction \
         B (0, 0, -1)",
    )
}
