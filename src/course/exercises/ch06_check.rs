//! The checks of chapter 06's coding exercises: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's functions
//! are in `ch06.rs`, beside this file; the harness is `harness.rs`.

use glam::{Vec2, Vec3};

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run, v};
use crate::camera::{Film, Frame, PinholeCamera};

/// Coding exercise 6.3.
pub const PINHOLE_RAY: Exercise = Exercise {
    number: "6.3",
    chapter: "06",
    chapter_title: "The pinhole camera",
    function: "pinhole_ray",
    file: "src/course/exercises/ch06.rs",
};
/// Coding exercise 6.4.
pub const PROJECT: Exercise = Exercise {
    number: "6.4",
    chapter: "06",
    chapter_title: "The pinhole camera",
    function: "project",
    file: "src/course/exercises/ch06.rs",
};

type PinholeArgs = (Film, f32, Frame, u32, u32);

/// Checks `pinhole_ray(film, s, frame, px, py)`: the world-space (origin, unit
/// direction) of the pinhole ray of pixel (`px`, `py`), screen at distance `s`.
pub fn check_pinhole_ray(
    f: impl Fn(&Film, f32, &Frame, u32, u32) -> (Vec3, Vec3) + Send + Sync + 'static,
) -> Outcome {
    pinhole_ray_checked(Box::new(f))
}

/// [`check_pinhole_ray`] for the answer as a trait object: compiled once, here, not
/// again for every closure a test passes (see [`super::harness`]).
fn pinhole_ray_checked(
    f: Box<dyn Fn(&Film, f32, &Frame, u32, u32) -> (Vec3, Vec3) + Send + Sync>,
) -> Outcome {
    let film = Film::new(4, 3, (-8.0, 8.0), (-6.0, 6.0)).expect("valid film");
    let placed = Frame::look(v(0.0, 3.0, 6.0), v(0.0, -1.0, -2.0), Vec3::Y)
        .expect("valid frame");
    let origin = Frame::AT_ORIGIN;
    let cases: Vec<Case<PinholeArgs>> = [
        (origin, 8.0, 0, 0, "at the origin"),
        (origin, 8.0, 2, 1, "at the origin"),
        (origin, 8.0, 3, 2, "at the origin"),
        (origin, 4.0, 2, 1, "at the origin"),
        (
            placed,
            8.0,
            0,
            0,
            "at (0, 3, 6) looking along (0, -1, -2), up (0, 1, 0)",
        ),
        (
            placed,
            8.0,
            3,
            2,
            "at (0, 3, 6) looking along (0, -1, -2), up (0, 1, 0)",
        ),
        (
            placed,
            2.0,
            1,
            1,
            "at (0, 3, 6) looking along (0, -1, -2), up (0, 1, 0)",
        ),
    ]
    .into_iter()
    .map(|(frame, s, px, py, where_)| {
        (
            format!(
                "pixel ({px}, {py}), 4x3 film over [-8, 8] x [-6, 6], s = {}, camera {where_}",
                s.show()
            ),
            (film, s, frame, px, py),
        )
    })
    .collect();
    let screen =
        |&(film, s, _, px, py): &PinholeArgs| film.pixel_to_plane(px, py).extend(-s);
    run(
        &cases,
        |&(film, s, frame, px, py)| {
            let ray = PinholeCamera::new(film, s, frame)
                .expect("valid camera")
                .ray(px, py);
            (ray.origin(), ray.direction())
        },
        move |(film, s, frame, px, py)| f(&film, s, &frame, px, py),
        &[
            Mistake {
                looks_like: &gives(&|a: &PinholeArgs| {
                    let frame = a.2;
                    let p = a.0.pixel_to_plane(a.3, a.4).extend(0.0);
                    Some((frame.point_to_world(p), frame.vector_to_world(-Vec3::Z)))
                }),
                hint: "that is the orthographic ray (the slides' erratum). A pinhole ray starts at \
                       the eye e and goes through the screen point s = (x, y, -s): direction \
                       (s - e)/|s - e|",
            },
            Mistake {
                looks_like: &|_: &PinholeArgs, got: &(Vec3, Vec3)| {
                    !got.1.length().close(&1.0)
                },
                hint: "the direction must have length 1: (s - e)/|s - e|",
            },
            Mistake {
                looks_like: &|a: &PinholeArgs, got: &(Vec3, Vec3)| {
                    let d = a.2.vector_to_world(screen(a).normalize());
                    got.1.close(&d) && !got.0.close(&a.2.position())
                },
                hint: "the direction is right, the origin is not: the ray starts at the eye, the \
                       camera position p (the camera-space origin carried to the world)",
            },
            Mistake {
                looks_like: &gives(&|a: &PinholeArgs| {
                    Some((a.2.position(), screen(a).normalize()))
                }),
                hint: "carry the camera-space direction to the world with the basis: B d \
                       (frame.vector_to_world), not the camera-space direction itself",
            },
            Mistake {
                looks_like: &|a: &PinholeArgs, got: &(Vec3, Vec3)| {
                    let mut s = screen(a);
                    s.y = -s.y;
                    got.1.close(&a.2.vector_to_world(s.normalize()))
                },
                hint: "the image is upside down (STABILITY S11: up must be up): pixel row 0 is \
                       the top row of the image, whose rays go up, but the slides' formula counts \
                       rows from the bottom. film.pixel_to_plane flips the rows once, in one \
                       place: use its (x, y)",
            },
            Mistake {
                looks_like: &|a: &PinholeArgs, got: &(Vec3, Vec3)| {
                    let mut s = screen(a);
                    s.z = -s.z;
                    got.1.close(&a.2.vector_to_world(s.normalize()))
                },
                hint: "the screen lies in front of the eye, on the plane z = -s (the camera looks \
                       down its -Z)",
            },
        ],
        "screen point s = (x, y, -s) with (x, y) the pixel centre on the film; eye e = 0; \
         direction (s - e)/|s - e|; then origin B e + p, direction B d",
    )
}

type ProjectArgs = (Film, f32, Frame, Vec3);

/// Checks `project(film, s, frame, x)`: the continuous pixel coordinates where the
/// world point `x` lands, or `None` if it is not in front of the eye.
pub fn check_project(
    f: impl Fn(&Film, f32, &Frame, Vec3) -> Option<Vec2> + Send + Sync + 'static,
) -> Outcome {
    project_checked(Box::new(f))
}

/// [`check_project`] for the answer as a trait object: compiled once, here, not again
/// for every closure a test passes (see [`super::harness`]).
fn project_checked(
    f: Box<dyn Fn(&Film, f32, &Frame, Vec3) -> Option<Vec2> + Send + Sync>,
) -> Outcome {
    let film = Film::new(4, 3, (-8.0, 8.0), (-6.0, 6.0)).expect("valid film");
    let placed = Frame::look(v(0.0, 3.0, 6.0), v(0.0, -1.0, -2.0), Vec3::Y)
        .expect("valid frame");
    let origin = Frame::AT_ORIGIN;
    let at_origin = "at the origin";
    let at_p = "at (0, 3, 6) looking along (0, -1, -2), up (0, 1, 0)";
    let cases: Vec<Case<ProjectArgs>> = [
        (origin, 8.0, v(6.0, 0.0, -8.0), at_origin, "on the screen"),
        (
            origin,
            8.0,
            v(6.0, 0.0, -24.0),
            at_origin,
            "three times as far",
        ),
        (
            origin,
            8.0,
            v(-2.0, 3.0, -4.0),
            at_origin,
            "nearer than the screen",
        ),
        (
            origin,
            4.0,
            v(-2.0, 3.0, -4.0),
            at_origin,
            "on a screen at s = 4",
        ),
        (origin, 8.0, v(1.0, 1.0, 5.0), at_origin, "behind the eye"),
        (
            origin,
            8.0,
            v(1.0, 1.0, 0.0),
            at_origin,
            "level with the eye",
        ),
        (
            placed,
            8.0,
            v(2.0, 0.0, -3.0),
            at_p,
            "on the floor, to the right",
        ),
        (
            placed,
            8.0,
            Vec3::ZERO,
            at_p,
            "the origin, which the camera looks towards",
        ),
        (placed, 8.0, v(0.0, 3.0, 9.0), at_p, "behind the camera"),
        // STABILITY S11: right is right and up is up.
        (
            origin,
            8.0,
            v(1.0, 0.0, -5.0),
            at_origin,
            "right of the view direction, so in the right half (STABILITY S11)",
        ),
        (
            origin,
            8.0,
            v(0.0, 1.0, -5.0),
            at_origin,
            "above the view direction, so in the upper half (STABILITY S11)",
        ),
    ]
    .into_iter()
    .map(|(frame, s, x, camera, what)| {
        (
            format!(
                "x = {} ({what}), 4x3 film over [-8, 8] x [-6, 6], s = {}, camera {camera}",
                x.show(),
                s.show()
            ),
            (film, s, frame, x),
        )
    })
    .collect();
    let local = |a: &ProjectArgs| a.2.point_to_camera(a.3);
    // The screen point by similar triangles from the camera-space point `c`, with the
    // depth `depth` and no test of the side.
    let landing = |a: &ProjectArgs, c: Vec3, depth: f32| {
        let on_screen = c.truncate() * (a.1 / depth);
        Some(Some(a.0.plane_to_pixel(on_screen)))
    };
    run(
        &cases,
        |&(film, s, frame, x)| {
            PinholeCamera::new(film, s, frame)
                .expect("valid camera")
                .project(x)
        },
        move |(film, s, frame, x)| f(&film, s, &frame, x),
        &[
            Mistake {
                looks_like: &|a: &ProjectArgs, got: &Option<Vec2>| {
                    got.is_some() && local(a).z >= 0.0
                },
                hint: "the point is not in front of the eye (Z >= 0 in camera space): it has no \
                       image, return None (dividing by a depth of 0 or less gives infinities or \
                       a mirrored point)",
            },
            Mistake {
                looks_like: &gives(&|a: &ProjectArgs| {
                    Some(Some(a.0.plane_to_pixel(local(a).truncate())))
                }),
                hint: "that is the orthographic projection: a pinhole divides by the depth, \
                       (s X / -Z, s Y / -Z), so that far things look small",
            },
            Mistake {
                looks_like: &gives(&|a: &ProjectArgs| landing(a, local(a), local(a).z)),
                hint: "the depth of a point in front of the eye is -Z (the camera looks down its \
                       -Z): divide by -Z, or the image comes out mirrored",
            },
            Mistake {
                looks_like: &gives(&|a: &ProjectArgs| {
                    let c = local(a);
                    let on_screen = c.truncate() * (a.1 / -c.z);
                    let ((x0, x1), (y0, y1)) = (a.0.x_extent(), a.0.y_extent());
                    let (w, h) = (a.0.width() as f32, a.0.height() as f32);
                    (c.z < 0.0).then(|| {
                        Some(Vec2::new(
                            (on_screen.x - x0) / (x1 - x0) * w,
                            (on_screen.y - y0) / (y1 - y0) * h,
                        ))
                    })
                }),
                hint: "the image is upside down (STABILITY S11: up must be up): rows count from \
                       the top of the image, y grows upwards on the screen. film.plane_to_pixel \
                       flips the rows (height - sy); use it",
            },
            Mistake {
                looks_like: &gives(&|a: &ProjectArgs| {
                    landing(a, local(a), -local(a).z * a.1)
                }),
                hint: "scale by s / -Z: the screen lies at distance s from the eye",
            },
            Mistake {
                looks_like: &gives(&|a: &ProjectArgs| landing(a, a.3, -a.3.z)),
                hint: "x is a world point: take it to camera space first, \
                       frame.point_to_camera(x) = B^T (x - p)",
            },
        ],
        "in camera space (X, Y, Z) = B^T (x - p); None unless Z < 0; the screen point \
         (s X / -Z, s Y / -Z), in pixels by film.plane_to_pixel",
    )
}
