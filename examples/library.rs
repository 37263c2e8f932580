//! The crate as a library: a scene of your own, with one `use`, ray cast and path
//! traced. Copy it into a project that depends on `render-lessons`.
//!
//!     cargo run --release --example library -- out

use render_lessons::prelude::*;

fn main() -> Result<()> {
    let out = std::path::PathBuf::from(std::env::args().nth(1).unwrap_or("out".into()));
    let _ = std::fs::create_dir_all(&out); // if it fails, save_png says so
    // Two balls and the Newell teapot (read from the crate's assets) on a floor.
    let teapot = Mesh::from_obj(asset_path(TEAPOT_OBJ))?.mesh;
    let yellow = Vec3::new(0.9, 0.8, 0.3);
    let placed = Model::new(teapot, yellow).placed(Transform::scale(0.3, 0.3, 0.3));
    let mut objects = vec![placed.object()?]; // one shape, with a tree of its own
    for (x, colour) in [
        (-1.3, Vec3::new(0.8, 0.2, 0.2)),
        (1.3, Vec3::new(0.2, 0.3, 0.8)),
    ] {
        let ball = Sphere::new(Vec3::new(x, 0.5, 0.3), 0.5)?;
        objects.push(Object::diffuse(ball, colour));
    }
    let floor = Plane::new(Vec3::ZERO, Vec3::Y)?;
    objects.push(Object::diffuse(floor, Vec3::splat(0.7)));
    // Both images are lit by the point light, with shadows; the path tracer also by
    // the sky (the background), which the ray caster only shows where rays miss.
    let (sky, lamp) = (Vec3::new(0.6, 0.7, 0.9), Vec3::new(2.0, 5.0, 4.0));
    let light = PointLight::new(lamp, Vec3::splat(40.0));
    let scene = Scene::new(objects, sky)?.with_light(light)?;
    let (eye, target) = (Vec3::new(0.0, 2.0, 5.0), Vec3::new(0.0, 0.6, 0.0));
    let camera = Camera::look_at(eye, target, Vec3::Y, 40.0, 480, 270)?;
    ray_cast(&scene, &camera)?.save_png(out.join("library_ray_cast.png"))?;
    path_trace(&scene, &camera, 16)?.save_png(out.join("library_path_traced.png"))
}
