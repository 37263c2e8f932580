//! The lessons' scenes: what more than one lesson renders, built once. Lesson 08
//! casts rays at its scene; lesson 09 draws the same scene as triangles, seen by the
//! same camera; lesson 11 measures both renderers on it.

use std::path::{Path, PathBuf};

use glam::Vec3;

use crate::bvh::BvhScene;
use crate::camera::{Camera, Film, Frame, OrthoCamera, PinholeCamera};
use crate::error::{Error, Result, finite};
use crate::raster::{FaceCounts, LoadedMesh, Mesh, Model, Shadows};
use crate::raster::{check_subdivisions, subdivided_count};
use crate::ray::{Interval, Ray};
use crate::scene::{Intersect, Object, PointLight, Scene, SceneHit};
use crate::shapes::{Aabb, Plane, Shape, Sphere, Triangle};
use crate::transform::Transform;
use crate::{limits, progress};

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

/// The Newell teapot as 2048 quads (`raster::teapot::teapot_obj(8)`), relative to the
/// repository's root: `--mesh assets/meshes/teapot.obj`.
pub const TEAPOT_OBJ: &str = "assets/meshes/teapot.obj";

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

/// The memory a triangle of lesson 09's mesh may take at the lesson's peak: its
/// flat-shaded copy (three vertices), the ray caster's primitive and its place in a
/// BVH, the rasterizer's transformed vertices and screen triangle. Twice what was
/// measured: lesson 09 with the teapot subdivided 4 times (a million triangles)
/// peaks at about 770 MB, some 750 bytes a triangle.
pub const MESH_BYTES_PER_TRIANGLE: u64 = 1536;

/// Lesson 09's mesh, and what reading it did.
#[derive(Clone, Debug, PartialEq)]
pub struct LessonMesh {
    /// The mesh, placed on the floor and coloured.
    pub model: Model,
    /// What reading the file did to its faces.
    pub counts: FaceCounts,
    /// How many times every triangle was split in four.
    pub subdivisions: u32,
}

// ANCHOR: lesson09_mesh
/// The mesh of the OBJ file at `path`, every triangle split in four `subdivisions`
/// times, placed in lesson 08's scene where lesson 09 draws it: standing on the
/// floor at the front right, tilted towards the camera, flat shaded (one normal per
/// triangle, as the ray caster sees triangles). A mesh of any size is scaled to fit
/// the box of the default torus (half a side: 1.4), which leaves the torus as it is.
/// Before the work, the triangles it would make are checked against the memory
/// ([`MESH_BYTES_PER_TRIANGLE`] each).
pub fn lesson09_mesh(path: &Path, subdivisions: u32) -> Result<LessonMesh> {
    let subdivisions = check_subdivisions("subdivide", subdivisions)?;
    let LoadedMesh { mesh, counts } = Mesh::from_obj(&asset_path(path))?;
    let triangles = subdivided_count(mesh.triangles.len(), subdivisions);
    let param = if subdivisions == 0 {
        "mesh"
    } else {
        "subdivide"
    };
    limits::memory(param, triangles.saturating_mul(MESH_BYTES_PER_TRIANGLE))?;
    let mesh = match subdivisions {
        0 => mesh,
        n => progress::spinner(format!("subdividing into {triangles} triangles"), || {
            mesh.subdivided(n)
        })?,
    };
    let mesh = mesh.flat_shaded()?;
    if mesh.degenerate() == mesh.triangles.len() {
        return Err(Error::Invalid {
            param: "mesh",
            reason: "has no triangle with an area: every one is degenerate",
        });
    }
    let placed = Transform::rotation_x(-0.5).then(Transform::translation(2.2, 0.75, 1.6));
    let model = match fit(&mesh, 1.4)? {
        Some(fit) => fit.then(placed),
        None => placed,
    };
    Ok(LessonMesh {
        model: Model {
            mesh,
            model,
            colour: Vec3::new(0.8, 0.55, 0.3),
        },
        counts,
        subdivisions,
    })
}
// ANCHOR_END: lesson09_mesh

/// The transform that centres `mesh`'s bounding box on the origin and scales it
/// so that its longest half side is `half`; `None` for a mesh that fits so already
/// (the torus: centred, half a side 1.4), which is then left exactly as it is.
fn fit(mesh: &Mesh, half: f32) -> Result<Option<Transform>> {
    let (min, max) = mesh
        .positions
        .iter()
        .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &p| {
            (lo.min(p), hi.max(p))
        });
    let centre = (min + max) * 0.5;
    let scale = half / ((max - min) * 0.5).max_element();
    if centre == Vec3::ZERO && scale == 1.0 {
        return Ok(None);
    }
    // A mesh whose size is 0 or overflows has no fit (the transforms take finite numbers).
    for (param, value) in [
        ("dx", centre.x),
        ("dy", centre.y),
        ("dz", centre.z),
        ("sx", scale),
    ] {
        finite(param, value)?;
    }
    let to_origin = Transform::translation(-centre.x, -centre.y, -centre.z);
    Ok(Some(to_origin.then(Transform::scale(scale, scale, scale))))
}

/// The floor of `scene` (its first object) with `mesh` standing on it, as the ray
/// caster sees them: the mesh's triangles as primitives, the same background and
/// light.
pub fn lesson09_mesh_scene(scene: &Scene, mesh: &Model) -> Result<Scene> {
    let mut objects = scene.objects()[..1].to_vec();
    objects.extend(mesh.objects()?);
    let floor_and_mesh = Scene::new(objects, scene.background())?;
    match scene.point_light() {
        Some(light) => floor_and_mesh.with_light(light),
        None => Ok(floor_and_mesh),
    }
}

/// Above this many ray-primitive tests (pixels times primitives) lesson 09's ray
/// caster stops testing every primitive on every ray and goes through lesson 11's
/// BVH: 2^28, about 2.7 x 10^8 tests, a few seconds of brute force. The torus at
/// 480 x 270 (1.3 x 10^8 tests) stays below; the teapot (5.2 x 10^8) goes above.
pub const BRUTE_FORCE_TESTS: u64 = 1 << 28;

/// Lesson 09's floor and mesh as the ray caster sees them: the plain list of
/// lesson 08 while every ray may test every primitive (at most
/// [`BRUTE_FORCE_TESTS`] tests in all), else the same list through lesson 11's
/// BVH, which answers every ray as the list does, so the image is the same, bit
/// for bit.
#[derive(Clone, Debug, PartialEq)]
pub enum MeshScene {
    /// Every ray tests every primitive.
    List(Scene),
    /// Rays walk a BVH over the same primitives.
    Tree(BvhScene),
}

impl MeshScene {
    /// `scene` as a plain list, or through a BVH (built under a spinner) when a
    /// render of `pixels` rays would make more than [`BRUTE_FORCE_TESTS`] tests.
    pub fn new(scene: Scene, pixels: u64) -> MeshScene {
        let primitives = scene.objects().len();
        if pixels.saturating_mul(primitives as u64) <= BRUTE_FORCE_TESTS {
            return MeshScene::List(scene);
        }
        let message = format!("building a BVH over {primitives} primitives");
        MeshScene::Tree(progress::spinner(message, || BvhScene::new(scene)))
    }
}

/// The list's or the tree's answers.
impl Intersect for MeshScene {
    fn scene(&self) -> &Scene {
        match self {
            MeshScene::List(scene) => scene,
            MeshScene::Tree(tree) => tree.scene(),
        }
    }

    fn closest(&self, ray: &Ray, range: Interval) -> Option<SceneHit> {
        match self {
            MeshScene::List(scene) => scene.closest(ray, range),
            MeshScene::Tree(tree) => tree.closest(ray, range),
        }
    }

    fn occluded(&self, ray: &Ray, range: Interval) -> bool {
        match self {
            MeshScene::List(scene) => scene.occluded(ray, range),
            MeshScene::Tree(tree) => tree.occluded(ray, range),
        }
    }
}
