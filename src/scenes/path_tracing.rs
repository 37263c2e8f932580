//! The lesson's scenes: smallpt's Cornell box, the two furnaces of STABILITY S16 and
//! S17, and a floor under a small and a large light (where MIS earns its keep).

use glam::Vec3;

use std::path::Path;

use super::{TEAPOT_OBJ, asset_path};
use crate::camera::{Camera, Film, Frame, PinholeCamera};
use crate::error::Result;
use crate::material::Material;
use crate::mesh::Mesh;
use crate::scene::{Object, Scene};
use crate::shapes::{Plane, Quad, Shape, Sphere};
use crate::transform::Transform;

/// A scene and the camera that frames it, as every scene builder here returns them:
/// the camera is the scene's own (placed and sized for it), so the two travel
/// together.
#[derive(Clone, Debug)]
pub struct Staged {
    /// The objects, their materials and the background.
    pub scene: Scene,
    /// The pinhole camera the lesson renders `scene` through, at the size asked for.
    pub camera: Camera,
}

/// The lesson's scenes, by the names its `--scene` flag takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneName {
    /// smallpt's Cornell box, walls as planes, a square ceiling light.
    Cornell,
    /// A floor under a small and a large spherical light.
    TwoLights,
    /// Inside a glowing sphere of albedo 0.5 (STABILITY S16).
    Furnace,
    /// A grey sphere in a white environment (STABILITY S17).
    GreyFurnace,
    /// The Cornell box with the Newell teapot (4032 triangles) for the mirror ball.
    Teapot,
}

impl SceneName {
    /// Every scene, in the order `--help` lists them.
    pub const ALL: [SceneName; 5] = [
        SceneName::Cornell,
        SceneName::TwoLights,
        SceneName::Furnace,
        SceneName::GreyFurnace,
        SceneName::Teapot,
    ];

    /// The scene at `width` x `height` pixels, and its pinhole camera.
    pub fn build(self, width: u32, height: u32) -> Result<Staged> {
        match self {
            SceneName::Cornell => cornell(width, height),
            SceneName::TwoLights => two_lights(width, height),
            SceneName::Furnace => interior_furnace(width, height),
            SceneName::GreyFurnace => grey_furnace(width, height, Vec3::ZERO),
            SceneName::Teapot => cornell_teapot(width, height),
        }
    }
}

/// A pinhole camera at `eye` looking along `direction` (up +Y), its screen at distance
/// 1 spanning `half_height` above and below the centre, width by the aspect ratio.
pub fn look_camera(
    width: u32,
    height: u32,
    eye: Vec3,
    direction: Vec3,
    half_height: f32,
) -> Result<Camera> {
    let film = Film::centred(width, height, half_height)?;
    let frame = Frame::look(eye, direction, Vec3::Y)?;
    Ok(PinholeCamera::new(film, 1.0, frame)?.into())
}

/// The side of the Cornell box's square light: its area equals the disc smallpt's
/// light sphere (radius 600, centre 0.27 above 600 over the ceiling) cuts out of the
/// ceiling, pi (2 * 600 * 0.27 - 0.27^2) = 1017.6, so with smallpt's radiance 12 it
/// emits the same power downwards, pi * 12 * 1017.6 = 38 362 (flux of a Lambertian
/// emitter: pi L A).
pub const CORNELL_LIGHT_SIDE: f32 = 31.900_2;

/// How far below the ceiling the lamp hangs, so that it and the ceiling plane never
/// coincide. The lamp shines downwards only ([`Object::lamp`]): a two-sided panel
/// this close to the ceiling lit the ceiling beside its edges from 0.05 away, and
/// next event estimation turned that 1/r^2 into fireflies whose error grew with
/// time.
pub const CORNELL_LIGHT_GAP: f32 = 0.05;

// ANCHOR: cornell
/// smallpt's Cornell box (Kevin Beason, 2008) with planes for walls instead of
/// spheres of radius 1e5, and a square ceiling light instead of the radius-600
/// sphere that pokes through the ceiling (see [`CORNELL_LIGHT_SIDE`]).
///
/// smallpt's front wall is black (albedo 0, no emission): a ray that hits it gets
/// the same radiance, 0, as a ray that escapes, so it is left out.
pub fn cornell(width: u32, height: u32) -> Result<Staged> {
    let grey = Material::diffuse(Vec3::splat(0.75))?;
    let wall = |point: (f32, f32, f32), normal: Vec3, material| -> Result<Object> {
        let plane = Plane::new(Vec3::from(point), normal)?;
        Ok(Object::new(Shape::Plane(plane), material))
    };
    let ball = |centre: Vec3, material| -> Result<Object> {
        Ok(Object::new(
            Shape::Sphere(Sphere::new(centre, 16.5)?),
            material,
        ))
    };
    let s = CORNELL_LIGHT_SIDE;
    let light = Quad::new(
        Vec3::new(50.0 - s / 2.0, 81.6 - CORNELL_LIGHT_GAP, 81.6 - s / 2.0),
        Vec3::new(s, 0.0, 0.0),
        Vec3::new(0.0, 0.0, s),
    )?;
    let objects = vec![
        wall(
            (1.0, 0.0, 0.0),
            Vec3::X,
            Material::diffuse(Vec3::new(0.75, 0.25, 0.25))?,
        )?,
        wall(
            (99.0, 0.0, 0.0),
            -Vec3::X,
            Material::diffuse(Vec3::new(0.25, 0.25, 0.75))?,
        )?,
        wall((0.0, 0.0, 0.0), Vec3::Z, grey)?,
        wall((0.0, 0.0, 0.0), Vec3::Y, grey)?,
        wall((0.0, 81.6, 0.0), -Vec3::Y, grey)?,
        ball(
            Vec3::new(27.0, 16.5, 47.0),
            Material::mirror(Vec3::splat(0.999))?,
        )?,
        ball(Vec3::new(73.0, 16.5, 78.0), Material::glass(1.5)?)?,
        Object::lamp(Shape::Quad(light), Vec3::splat(12.0)),
    ];
    let scene = Scene::new(objects, Vec3::ZERO)?;
    // smallpt: cy has length 0.5135 and spans [-0.5, 0.5] of it, so the screen at
    // distance 1 is 0.5135 high in all; cx = w * 0.5135 / h wide.
    let camera = look_camera(
        width,
        height,
        Vec3::new(50.0, 52.0, 295.6),
        Vec3::new(0.0, -0.042_612, -1.0),
        0.5135 / 2.0,
    )?;
    Ok(Staged { scene, camera })
}
// ANCHOR_END: cornell

// ANCHOR: cornell_teapot
/// The Cornell box with the Newell teapot (`assets/meshes/teapot.obj`, 4032
/// triangles once its quads are split) standing where the mirror ball was, white and
/// diffuse. A scene a plain list renders slowly: lesson 10 draws it through lesson
/// 11's BVH ([`crate::scene::ListOrTree`]).
pub fn cornell_teapot(width: u32, height: u32) -> Result<Staged> {
    let Staged {
        scene: box_scene,
        camera,
    } = cornell(width, height)?;
    let teapot = Mesh::from_obj(asset_path(Path::new(TEAPOT_OBJ)))?.mesh;
    // The teapot's y starts at 0, so it stands on the floor (y = 0); seven times its
    // size is about as wide as the ball was.
    let placed =
        Transform::scale(7.0, 7.0, 7.0).then(Transform::translation(30.0, 0.0, 50.0));
    let mut world = teapot;
    for p in &mut world.positions {
        *p = placed.point(*p);
    }
    let mirror_ball = 5;
    let mut objects: Vec<Object> = box_scene.objects().to_vec();
    objects.remove(mirror_ball);
    objects.extend(world.objects(Vec3::splat(0.75))?);
    let scene = Scene::new(objects, box_scene.background())?;
    Ok(Staged { scene, camera })
}
// ANCHOR_END: cornell_teapot

// ANCHOR: furnaces
/// STABILITY S16 (pbrt-v4's interior furnace): a unit sphere of albedo 0.5 that
/// emits 0.5, seen from its centre. Every path sees 0.5 + 0.5 * 0.5 + ...: depth d
/// gives 0.5 (1 - 0.5^(d+1)) / (1 - 0.5), infinite depth exactly 1.
pub fn interior_furnace(width: u32, height: u32) -> Result<Staged> {
    let sphere = Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0)?);
    let objects = vec![Object::emitting(
        sphere,
        Material::diffuse(Vec3::splat(0.5))?,
        Vec3::splat(0.5),
    )];
    let camera = look_camera(width, height, Vec3::ZERO, -Vec3::Z, 0.5)?;
    let scene = Scene::new(objects, Vec3::ZERO)?;
    Ok(Staged { scene, camera })
}

/// STABILITY S17: a unit sphere of albedo 0.5 centred at `centre`, in an environment
/// of radiance 1. A ray that hits it sees exactly 0.5 (one bounce, then the
/// environment); each wrong self-hit multiplies by 0.5 again. The camera, 3 units in
/// front along +Z, sees only the sphere.
pub fn grey_furnace(width: u32, height: u32, centre: Vec3) -> Result<Staged> {
    let sphere = Shape::Sphere(Sphere::new(centre, 1.0)?);
    let objects = vec![Object::new(sphere, Material::diffuse(Vec3::splat(0.5))?)];
    let camera = look_camera(width, height, centre + 3.0 * Vec3::Z, -Vec3::Z, 0.2)?;
    let scene = Scene::new(objects, Vec3::ONE)?;
    Ok(Staged { scene, camera })
}
// ANCHOR_END: furnaces

// ANCHOR: two_lights
/// A grey floor under two spherical lights of equal power (L r^2 = 1): a small hot
/// one (radius 0.05, radiance 400) on the left, a large dim one (radius 1, radiance 1)
/// on the right: Veach's (1997, fig. 9.2) lesson with a Lambertian floor.
///
/// Direct light only: the standard deviation of one sample under each light, per
/// estimator, is measured by `tests/lessons/lesson_10_path_tracing.rs`
/// (`two_lights_sigmas` snapshot). Cosine sampling fails under the small hot light;
/// under the large one cosine and area sampling are both poor (area sampling's points
/// on the sphere seen at wide angles); MIS keeps area sampling's sigma under the small
/// light and beats both under the large one; and cone sampling of the spheres leaves
/// MIS little to add on a Lambertian floor.
pub fn two_lights(width: u32, height: u32) -> Result<Staged> {
    let floor = Plane::new(Vec3::ZERO, Vec3::Y)?;
    let small = Sphere::new(Vec3::new(-1.5, 1.0, 0.0), 0.05)?;
    let large = Sphere::new(Vec3::new(1.5, 1.5, 0.0), 1.0)?;
    let objects = vec![
        Object::new(Shape::Plane(floor), Material::diffuse(Vec3::splat(0.5))?),
        Object::emitting(Shape::Sphere(small), Material::BLACK, Vec3::splat(400.0)),
        Object::emitting(Shape::Sphere(large), Material::BLACK, Vec3::splat(1.0)),
    ];
    let eye = Vec3::new(0.0, 4.0, 6.0);
    let camera = look_camera(width, height, eye, Vec3::new(0.0, 0.5, 0.0) - eye, 0.5)?;
    let scene = Scene::new(objects, Vec3::ZERO)?;
    Ok(Staged { scene, camera })
}
// ANCHOR_END: two_lights
