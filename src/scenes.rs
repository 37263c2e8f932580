//! The lessons' scenes: what more than one lesson renders, built once. Lesson 08
//! casts rays at its scene; lesson 09 draws the same scene as triangles, seen by the
//! same camera; lesson 11 measures both renderers on it.

use std::path::{Path, PathBuf};

use glam::Vec3;

use crate::camera::{Camera, Film, Frame, OrthoCamera, PinholeCamera};
use crate::error::{Error, Result};
use crate::raster::{Mesh, Model, Shadows};
use crate::scene::{Object, PointLight, Scene};
use crate::shapes::{Aabb, Plane, Shape, Sphere, Triangle};
use crate::transform::Transform;

/// The objects of [`lesson08`], in scene order, by name.
pub const LESSON08_OBJECTS: [&str; 6] = [
    "floor",
    "red sphere",
    "blue sphere",
    "green sphere",
    "box",
    "triangle",
];

// ANCHOR: scene
/// Lesson 08's scene, moved by `shift`: a floor, three spheres, a box and a
/// triangle, in a plain list, lit by one point light.
pub fn lesson08(shift: Vec3) -> Result<Scene> {
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
/// Lesson 08's two cameras, `width` x `height` pixels, moved by `shift` with the
/// scene: orthographic and pinhole at the same place, looking at the same point.
/// The pinhole's screen sits at the distance of that point, so both frame the same
/// rectangle there.
pub fn lesson08_cameras(width: u32, height: u32, shift: Vec3) -> Result<[Camera; 2]> {
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

/// Lesson 08's pinhole camera, the one lessons 09 and 11 look through.
pub fn lesson08_pinhole(width: u32, height: u32) -> Result<Camera> {
    let [_, pinhole] = lesson08_cameras(width, height, Vec3::ZERO)?;
    Ok(pinhole)
}

// ANCHOR: shadows
/// A shadow map of `size` x `size` texels and `bias` for lesson 08's scene: the
/// light's camera frames every object and the shadows they throw on the floor.
pub fn lesson08_shadows(size: u32, bias: f32) -> Shadows {
    Shadows {
        size,
        bias,
        centre: Vec3::new(0.0, 0.5, -0.5),
        radius: 6.0,
    }
}
// ANCHOR_END: shadows

/// The mesh lesson 09 draws by default: a torus of 1024 triangles, relative to the
/// repository's root (see [`asset_path`] for other folders).
pub const TORUS_OBJ: &str = "assets/meshes/torus.obj";

/// `path` as given if it exists or is absolute; else, for a relative path, the same
/// path under the repository this program was built from, if the file is there. So a
/// default such as [`TORUS_OBJ`] reads as `assets/...` in `--help` and still works
/// from another folder, while a path the user gives is read where they say.
pub fn asset_path(path: &Path) -> PathBuf {
    let built = Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    if path.is_relative() && !path.exists() && built.exists() {
        built
    } else {
        path.to_path_buf()
    }
}

/// The mesh of the OBJ file at `path`, placed in lesson 08's scene where lesson 09
/// draws it: standing on the floor at the front right, tilted towards the camera,
/// flat shaded (one normal per triangle, as the ray caster sees triangles).
pub fn lesson09_mesh(path: &Path) -> Result<Model> {
    let mesh = Mesh::from_obj(&asset_path(path))?.flat_shaded()?;
    if mesh.degenerate() == mesh.triangles.len() {
        return Err(Error::Invalid {
            param: "mesh",
            reason: "has no triangle with an area: every one is degenerate",
        });
    }
    let model = Transform::rotation_x(-0.5)?.then(Transform::translation(2.2, 0.75, 1.6)?);
    Ok(Model {
        mesh,
        model,
        colour: Vec3::new(0.8, 0.55, 0.3),
    })
}

/// The floor of `scene` (its first object) with `mesh` standing on it, as the ray
/// caster sees them: the mesh's triangles as primitives, the same background and
/// light.
pub fn lesson09_mesh_scene(scene: &Scene, mesh: &Model) -> Result<Scene> {
    let mut objects = scene.objects()[..1].to_vec();
    objects.extend(mesh.objects()?);
    let floor_and_mesh = Scene::new(objects, scene.background())?;
    match scene.light() {
        Some(light) => floor_and_mesh.with_light(light),
        None => Ok(floor_and_mesh),
    }
}
