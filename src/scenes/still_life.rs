//! Lesson 08's still life, the scene more than one lesson renders: a floor, three
//! spheres, a box and a triangle, lit by one point light. Lesson 08 casts rays at it;
//! lesson 09 draws it as triangles, seen by the same camera; lesson 11 measures both
//! renderers on it.

use glam::Vec3;

use crate::camera::{Camera, Film, Frame, OrthoCamera, PinholeCamera};
use crate::error::Result;
use crate::raster::Shadows;
use crate::scene::{Object, PointLight, Scene};
use crate::shapes::{Aabb, Plane, Shape, Sphere, Triangle};

/// The objects of [`still_life`], in scene order, by name.
pub const STILL_LIFE_OBJECTS: [&str; 6] = [
    "floor",
    "red sphere",
    "blue sphere",
    "green sphere",
    "box",
    "triangle",
];

// ANCHOR: scene
/// Lesson 08's still life, moved by `shift`: a floor, three spheres, a box and a
/// triangle, in a plain list, lit by one point light.
pub fn still_life(shift: Vec3) -> Result<Scene> {
    let object = |shape, (r, g, b)| Object::diffuse(shape, Vec3::new(r, g, b));
    let sphere = |c: Vec3, r| Sphere::new(c + shift, r).map(Shape::Sphere);
    let objects = vec![
        object(Shape::Plane(Plane::new(shift, Vec3::Y)?), (0.75, 0.75, 0.7)),
        object(sphere(Vec3::new(-1.6, 1.0, 0.0), 1.0)?, (0.85, 0.2, 0.15)),
        object(sphere(Vec3::new(1.3, 0.7, 1.2), 0.7)?, (0.2, 0.35, 0.85)),
        object(sphere(Vec3::new(0.2, 0.4, 2.4), 0.4)?, (0.2, 0.7, 0.3)),
        object(
            Shape::Aabb(Aabb::new(
                Vec3::new(-0.3, 0.0, -2.0) + shift,
                Vec3::new(0.9, 1.6, -0.8) + shift,
            )?),
            (0.9, 0.75, 0.2),
        ),
        object(
            Shape::Triangle(Triangle::new(
                Vec3::new(2.0, 0.0, -2.0) + shift,
                Vec3::new(3.4, 0.0, -1.2) + shift,
                Vec3::new(2.7, 2.2, -1.6) + shift,
            )?),
            (0.6, 0.3, 0.75),
        ),
    ];
    let light = PointLight {
        position: Vec3::new(3.0, 6.0, 4.0) + shift,
        intensity: Vec3::splat(60.0),
    };
    Scene::new(objects, Vec3::new(0.6, 0.75, 0.95)).and_then(|s| s.with_light(light))
}
// ANCHOR_END: scene

// ANCHOR: cameras
/// The still life's two cameras (lesson 08), `width` x `height` pixels, moved by
/// `shift` with the scene: orthographic and pinhole at the same place, looking at the
/// same point. The pinhole's screen sits at the distance of that point, so both frame
/// the same rectangle there.
pub fn still_life_cameras(width: u32, height: u32, shift: Vec3) -> Result<[Camera; 2]> {
    let eye = Vec3::new(0.0, 3.0, 9.0) + shift;
    let target = Vec3::new(0.0, 0.8, 0.0) + shift;
    let frame = Frame::look(eye, target - eye, Vec3::Y)?;
    let film = Film::centred(width, height, 2.6)?;
    Ok([
        OrthoCamera::new(film, frame).into(),
        PinholeCamera::new(film, (target - eye).length(), frame)?.into(),
    ])
}
// ANCHOR_END: cameras

/// The still life's pinhole camera, the one lessons 09 and 11 look through.
pub fn still_life_pinhole(width: u32, height: u32) -> Result<Camera> {
    let [_, pinhole] = still_life_cameras(width, height, Vec3::ZERO)?;
    Ok(pinhole)
}

// ANCHOR: shadows
/// A shadow map of `size` x `size` texels and `bias` for lesson 08's scene: the
/// light's camera frames every object and the shadows they throw on the floor.
pub fn still_life_shadows(size: u32, bias: f32) -> Shadows {
    Shadows {
        size,
        bias,
        centre: Vec3::new(0.0, 0.5, -0.5),
        radius: 6.0,
    }
}
// ANCHOR_END: shadows
