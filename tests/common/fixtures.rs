//! The scenes' small parts that many tests build: rays, shapes, the slides' camera,
//! and the crate's own closest-hit loop in the shape of coding exercise 8.1.

use glam::Vec3;
use render_lessons::camera::{Film, OrthoCamera};
use render_lessons::ray::{Interval, Ray};
use render_lessons::scene::{Object, Scene, SceneHit};
use render_lessons::shapes::{Aabb, Shape, Sphere};

/// The ray from `o` along `d` (not normalised), each a `Vec3` or a `[f32; 3]`.
pub fn ray(o: impl Into<Vec3>, d: impl Into<Vec3>) -> Ray {
    Ray::new(o.into(), d.into()).unwrap()
}

/// The sphere of radius 1 at the origin (`.into()` makes it a `Shape`).
pub fn unit_sphere() -> Sphere {
    Sphere::new(Vec3::ZERO, 1.0).unwrap()
}

/// The box [-1, 1]^3 (`.into()` makes it a `Shape`).
pub fn cube() -> Aabb {
    Aabb::new(Vec3::splat(-1.0), Vec3::ONE).unwrap()
}

/// The slides' film: 4 x 3 pixels over [-8, 8] x [-6, 6], so that pixel (0, 0)'s
/// centre is (-6, 4).
pub fn slide_film() -> Film {
    Film::new(4, 3, (-8.0, 8.0), (-6.0, 6.0)).unwrap()
}

/// The slides' orthographic camera: [`slide_film`] at the origin, looking down -Z.
pub fn slide_camera() -> OrthoCamera {
    OrthoCamera::at_origin(slide_film())
}

/// The crate's own closest hit (`Scene::closest`) in the shape of coding exercise
/// 8.1, `closest(ray, shapes, range)`: the reference a student's loop is held to.
pub fn reference_closest(
    ray: &Ray,
    shapes: &[Shape],
    range: Interval,
) -> Option<SceneHit> {
    let objects = shapes
        .iter()
        .map(|s| Object::diffuse(s.clone(), Vec3::ONE))
        .collect();
    let scene = Scene::new(objects, Vec3::ZERO).unwrap();
    scene.closest(ray, range)
}
