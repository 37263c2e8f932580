//! The BVH of lesson 11: how long it takes to build, how many primary rays per
//! second it traces on a ~100k-triangle mesh, and where it overtakes the plain list.
//!
//!     cargo bench --bench bvh
//!
//! The meshes are UV spheres (`Mesh::uv_sphere`, n x n segments, 2 n (n - 1)
//! triangles) seen by a pinhole camera; every ray asks for the closest hit only
//! (the shading is the object's colour, as in lesson 08's shadowless casting), on
//! one thread.

use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec3;
use render_lessons::bvh::{Bvh, BvhScene};
use render_lessons::camera::{Camera, Film, Frame, PinholeCamera};
use render_lessons::course::measure::scaling;
use render_lessons::ray::Ray;
use render_lessons::raycast::shadowless;
use render_lessons::render::render;
use render_lessons::scene::Scene;

/// A UV sphere of radius 1 at the origin, n x n segments, as a scene of triangles
/// (the scenes of lesson 11's chart 7).
fn sphere_scene(n: u32) -> Scene {
    scaling::sphere_scene(n).expect("scene")
}

/// A pinhole camera 3 units from the sphere, which fills most of the frame's height.
fn camera(width: u32, height: u32) -> Camera {
    let eye = Vec3::new(0.0, 0.4, 3.0);
    let frame = Frame::look(eye, -eye, Vec3::Y).expect("frame");
    let film = Film::centred(width, height, 0.42).expect("film");
    PinholeCamera::new(film, 1.0, frame).expect("camera").into()
}

fn shade(scene: &BvhScene, ray: &Ray) -> Vec3 {
    match scene.closest_hit(ray, 0.0, f32::INFINITY) {
        Some((_, object)) => object.colour(),
        None => scene.scene().background(),
    }
}

/// Build time and primary rays per second on 99 904 triangles (n = 224).
fn big_mesh(c: &mut Criterion) {
    let scene = sphere_scene(224);
    let mut group = c.benchmark_group("bvh, 99904 triangles");
    group.sample_size(10);
    group.warm_up_time(Duration::from_secs(1));
    group.bench_function("build (binned SAH)", |b| {
        b.iter(|| Bvh::build(scene.objects()))
    });
    let bvh = BvhScene::new(scene);
    let camera = camera(1920, 1080);
    group.throughput(Throughput::Elements(1920 * 1080));
    group.bench_function("primary rays 1920x1080, 1 thread", |b| {
        b.iter(|| render(&camera, Some(1), |r| shade(&bvh, r)).expect("render"))
    });
    group.finish();
}

/// The plain list against the BVH at about 10, 100, 1k and 10k triangles, on the
/// 5184 rays of a 96 x 54 image, made once and traced in a plain loop (`render` would
/// set up a thread pool per call, which costs more than a small scene's rays). A full
/// HD frame through the 10k-triangle list would take about a minute per sample.
fn crossover(c: &mut Criterion) {
    let camera = camera(96, 54);
    let rays: Vec<Ray> = (0..54)
        .flat_map(|y| (0..96).map(move |x| (x, y)))
        .map(|(x, y)| camera.ray(x, y))
        .collect();
    let mut group = c.benchmark_group("list vs bvh, 96x54 rays");
    group.sample_size(10);
    group.warm_up_time(Duration::from_secs(1));
    group.measurement_time(Duration::from_secs(5));
    group.throughput(Throughput::Elements(rays.len() as u64));
    for n in [3, 8, 23, 71] {
        let scene = sphere_scene(n);
        let count = scene.objects().len();
        group.bench_function(format!("list, {count} triangles"), |b| {
            b.iter(|| rays.iter().map(|r| shadowless(&scene, r)).sum::<Vec3>())
        });
        let bvh = BvhScene::new(scene);
        group.bench_function(format!("bvh, {count} triangles"), |b| {
            b.iter(|| rays.iter().map(|r| shade(&bvh, r)).sum::<Vec3>())
        });
    }
    group.finish();
}

criterion_group!(benches, big_mesh, crossover);
criterion_main!(benches);
