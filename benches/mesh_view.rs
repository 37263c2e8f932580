//! The BVH bench's view: a UV sphere of triangles, the pinhole camera that looks at
//! it, every pixel's ray, and the same triangles and rays as obvhs takes them
//! (`benches/bvh.rs`, and `bvh-frame` for `scripts/instructions-per-ray --bvh`).

use glam::{Vec3, Vec3A};
use render_lessons::camera::{Camera, Film, Frame, PinholeCamera};
use render_lessons::course::measure::scaling;
use render_lessons::mesh::Mesh;
use render_lessons::ray::Ray;
use render_lessons::scene::Scene;

/// A UV sphere of radius 1 at the origin, n x n segments, as a scene of triangles
/// (the scenes of lesson 11's chart 7).
pub fn sphere_scene(n: u32) -> Scene {
    scaling::sphere_scene(n).expect("scene")
}

/// The same sphere as a mesh (the one `sphere_scene` takes its triangles from, in
/// the same order): what Embree is given.
pub fn sphere_mesh(n: u32) -> Mesh {
    Mesh::uv_sphere(Vec3::ZERO, 1.0, n, n).expect("mesh")
}

/// A pinhole camera at `distance` from the sphere's centre, looking at it, with a
/// screen of half height 0.42 at distance 1.
pub fn camera(width: u32, height: u32, distance: f32) -> Camera {
    let eye = distance * Vec3::new(0.0, 0.4, 3.0).normalize();
    let frame = Frame::look(eye, -eye, Vec3::Y).expect("frame");
    let film = Film::centred(width, height, 0.42).expect("film");
    PinholeCamera::new(film, 1.0, frame).expect("camera").into()
}

/// Every pixel's ray, row by row.
pub fn rays(camera: &Camera) -> Vec<Ray> {
    let (w, h) = (camera.film().width(), camera.film().height());
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| camera.ray(x, y))
        .collect()
}

/// The scene's triangles for obvhs.
pub fn obvhs_triangles(scene: &Scene) -> Vec<obvhs::triangle::Triangle> {
    use render_lessons::shapes::Shape;
    scene
        .objects()
        .iter()
        .filter_map(|o| match &o.shape {
            Shape::Triangle(t) => {
                let [v0, v1, v2] = t.vertices().map(Vec3A::from);
                Some(obvhs::triangle::Triangle { v0, v1, v2 })
            }
            _ => None,
        })
        .collect()
}

/// `r` as obvhs takes it (which computes its 1/d).
pub fn obvhs_ray(r: &Ray) -> obvhs::ray::Ray {
    obvhs::ray::Ray::new_inf(r.origin().into(), r.direction().into())
}

/// The near camera's distance from the sphere's centre: about a third of its rays hit.
pub const NEAR: f32 = 3.03;

/// The far camera's distance: a few percent of its rays hit.
pub const FAR: f32 = 6.5;
