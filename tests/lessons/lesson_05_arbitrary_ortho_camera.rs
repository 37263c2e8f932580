//! Lesson 05: the arbitrary orthographic camera, its basis, the slide erratum and S10.

use crate::common::{self, slide_film};
use crate::examples::arbitrary_ortho_camera as lesson;

use clap::Parser;
use glam::{Mat3, Vec3};
use render_lessons::Error;
use render_lessons::basis::Basis;
use render_lessons::camera::{
    Frame, OrthoCamera, camera_basis, camera_basis_as_on_slide,
};
use render_lessons::error::Problem;

/// The example's camera, from its default flags.
fn default_camera() -> (OrthoCamera, lesson::Args) {
    let args = lesson::Args::parse_from(["05_arbitrary_ortho_camera"]);
    let (p, d, k) = (args.position, args.direction, args.up);
    (
        lesson::camera(args.width, args.height, p, d, k).unwrap(),
        args,
    )
}

#[test]
fn numbers() {
    let (cam, args) = default_camera();
    insta::assert_snapshot!("numbers", lesson::numbers(&cam, args.direction, args.up));
}

#[test]
fn origin_looking_down_minus_z_with_up_y_is_the_identity() {
    let b = camera_basis(Vec3::NEG_Z, Vec3::Y).unwrap();
    assert_eq!(b.matrix(), Mat3::IDENTITY);
}

#[test]
fn erratum_the_slides_w_makes_the_camera_look_backwards() {
    let d = Vec3::new(-1.0, 0.0, -1.0);
    let film = slide_film();
    let slide = camera_basis_as_on_slide(d, Vec3::Y).unwrap();
    let slide_camera = OrthoCamera::new(film, Frame::from_basis(Vec3::ZERO, slide));
    let ours = OrthoCamera::new(film, Frame::look(Vec3::ZERO, d, Vec3::Y).unwrap());
    // With w = d/|d| the local direction (0, 0, -1) becomes -d: the camera looks
    // backwards.
    assert!((slide_camera.ray(1, 1).direction() + d.normalize()).length() < 1e-6);
    assert!((ours.ray(1, 1).direction() - d.normalize()).length() < 1e-6);
    // And at the origin looking down -Z, the slide's basis is not the identity.
    assert_ne!(
        camera_basis_as_on_slide(Vec3::NEG_Z, Vec3::Y)
            .unwrap()
            .matrix(),
        Mat3::IDENTITY
    );
}

#[test]
fn camera_basis_is_orthonormal_right_handed_and_looks_along_d() {
    common::for_cases(5, 256, |rng| {
        let (d, k) = (rng.direction(), rng.direction());
        if d.normalize().cross(k.normalize()).length() <= 1e-3 {
            return;
        }
        let b = camera_basis(d, k).unwrap();
        assert!(b.orthonormality_error() < 1e-5);
        assert!(b.is_right_handed());
        assert!((b.u().cross(b.v()) - b.w()).length() < 1e-5);
        assert!((b.to_world(Vec3::NEG_Z) - d.normalize()).length() < 1e-5);
        assert!(b.v().dot(k) > 0.0, "up stays up");
        assert!(b.u().dot(k).abs() < 1e-5, "u is horizontal");
    });
}

#[test]
fn every_world_ray_is_parallel_to_d() {
    common::for_cases(55, 256, |rng| {
        let (d, k) = (rng.direction(), rng.direction());
        let (px, py) = (rng.below(0, 4), rng.below(0, 3));
        if d.normalize().cross(k.normalize()).length() <= 1e-3 {
            return;
        }
        let film = slide_film();
        let cam = OrthoCamera::new(
            film,
            Frame::look(Vec3::new(1.0, 2.0, 3.0), d, k).unwrap(),
        );
        let ray = cam.ray(px, py);
        assert!((ray.direction() - d.normalize()).length() < 1e-5);
        // The origin lies on the camera's plane through p, perpendicular to d.
        assert!(
            (ray.origin() - Vec3::new(1.0, 2.0, 3.0))
                .dot(d.normalize())
                .abs()
                < 1e-4
        );
    });
}

#[test]
fn s10_up_parallel_to_direction_is_an_error_not_nan() {
    assert_eq!(
        camera_basis(Vec3::Y, Vec3::Y),
        Err(Error::Value {
            param: "up",
            problem: Problem::UpParallelToDirection
        })
    );
    assert_eq!(
        camera_basis(Vec3::NEG_Y, Vec3::Y),
        Err(Error::Value {
            param: "up",
            problem: Problem::UpParallelToDirection
        })
    );
    let nearly = Vec3::new(0.0, 1.0, 1e-8);
    assert_eq!(
        camera_basis(nearly, Vec3::Y),
        Err(Error::Value {
            param: "up",
            problem: Problem::UpParallelToDirection
        })
    );
    assert_eq!(
        Frame::look(Vec3::ZERO, Vec3::Y * 3.0, Vec3::Y * 0.5),
        Err(Error::Value {
            param: "up",
            problem: Problem::UpParallelToDirection
        })
    );
}

/// The worst orthonormality error over many nearly-parallel (d, k) pairs at angle
/// `angle`.
fn worst_error(
    angle: f32,
    build: fn(Vec3, Vec3) -> render_lessons::Result<Basis>,
) -> f32 {
    (0..200)
        .map(|i| {
            let phi = i as f32 * 0.1;
            let k = Vec3::new(0.3 * phi.cos(), 1.0, 0.3 * phi.sin()).normalize();
            let side = k.any_orthonormal_vector();
            let d = (k * angle.cos() + side * angle.sin()).normalize();
            build(d, k).map(|b| b.orthonormality_error()).unwrap_or(0.0)
        })
        .fold(0.0, f32::max)
}

#[test]
fn s10_nearly_parallel_up_keeps_the_basis_orthonormal() {
    let mut printed = Vec::new();
    for angle in [3e-6f32, 1e-5] {
        let naive = worst_error(angle, camera_basis_as_on_slide);
        let ours = worst_error(angle, camera_basis);
        assert!(
            naive > 1e-4,
            "the slide's cross products lose orthonormality at {angle} rad: {naive}"
        );
        assert!(
            ours < 1e-6,
            "one Gram-Schmidt step keeps it at {angle} rad: {ours}"
        );
        eprintln!(
            "S10 at {angle:e} rad: slide basis error {naive:.1e}, ours {ours:.1e}"
        );
        printed.push(format!("{naive:.1e} {ours:.1e}"));
    }
    // The numbers where_methods_fail_cameras.md prints (cross products and square
    // roots only: the same on every machine).
    assert_eq!(printed, ["1.9e-3 4.8e-7", "6.8e-4 4.8e-7"]);
    // Both are about 6e-9 / theta (the page's fit of epsilon / sin theta).
    for (error, theta) in [(1.9e-3f64, 3e-6), (6.8e-4, 1e-5)] {
        assert!(
            (error * theta / 6e-9 - 1.0).abs() < 0.15,
            "{}",
            error * theta
        );
    }
}

#[test]
fn bad_camera_input_names_the_parameter() {
    assert_eq!(
        camera_basis(Vec3::ZERO, Vec3::Y),
        Err(Error::Value {
            param: "direction",
            problem: Problem::ZeroLength
        })
    );
    assert_eq!(
        camera_basis(Vec3::NEG_Z, Vec3::ZERO),
        Err(Error::Value {
            param: "up",
            problem: Problem::ZeroLength
        })
    );
    assert_eq!(
        Frame::look(Vec3::new(f32::NAN, 0.0, 0.0), Vec3::NEG_Z, Vec3::Y),
        Err(Error::Value {
            param: "position",
            problem: Problem::NotFinite
        })
    );
    assert_eq!(
        camera_basis(Vec3::new(0.0, 0.0, f32::INFINITY), Vec3::Y),
        Err(Error::Value {
            param: "direction",
            problem: Problem::NotFinite
        })
    );
}

#[test]
fn figure_draws() {
    let rgba = lesson::top_figure(&default_camera().0).unwrap().rgba();
    assert!(common::blue_pixels(&rgba) > 300);
}
