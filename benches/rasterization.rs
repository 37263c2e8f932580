//! Lesson 09's measurements: the rasterizer's frame time and triangles per second
//! for a mesh of about 100 000 triangles at 1920 x 1080; the same frame ray cast
//! through lesson 11's BVH; and a frame ray cast by brute force (every ray against
//! every triangle) on lesson 09's 1024-triangle torus. One thread for all, so the
//! comparison is per core, and the same per-pixel Lambert shading for all.
//!
//!     cargo bench -p render-benches --bench rasterization
//!
//! Brute-force ray casting of a whole 1080p frame takes tens of seconds, too long to
//! repeat ten times; it is measured on every 30th row (36 rows, 69 120 rays) and
//! reported per ray. Frame time = 2 073 600 rays / (rays per second).

use criterion::{Criterion, Throughput, criterion_group};
use glam::Vec3;
use render_lessons::camera::{Camera, Film, Frame, PinholeCamera};
use render_lessons::course::measure::machine::CpuWatch;
use render_lessons::mesh::{Mesh, Model};
use render_lessons::raster::{Cull, RasterSettings, rasterize};
use render_lessons::raycast::lit_unshadowed;
use render_lessons::render::{render, thread_pool};
use render_lessons::scene::BvhScene;
use render_lessons::scene::{PointLight, Scene};
use render_lessons::scenes::TORUS_OBJ;

const WIDTH: u32 = 1920;
const HEIGHT: u32 = 1080;
const ROW_STEP: u32 = 30;

const LIGHT: PointLight = PointLight {
    position: Vec3::new(3.0, 5.0, 6.0),
    intensity: Vec3::splat(60.0),
};

/// A camera 4 units in front of the origin framing a 2-unit-radius sphere.
fn camera() -> Camera {
    let half = 0.6;
    let film = Film::new(
        WIDTH,
        HEIGHT,
        (-half * 16.0 / 9.0, half * 16.0 / 9.0),
        (-half, half),
    )
    .expect("film");
    let frame = Frame::look(
        Vec3::new(0.0, 0.5, 4.0),
        Vec3::new(0.0, -0.12, -1.0),
        Vec3::Y,
    )
    .expect("frame");
    PinholeCamera::new(film, 1.0, frame).expect("camera").into()
}

fn torus() -> Mesh {
    Mesh::from_obj(std::path::Path::new(TORUS_OBJ))
        .expect("the lesson's torus")
        .mesh
}

/// The mesh as a list of triangle primitives, for the ray caster.
fn triangle_scene(mesh: &Mesh) -> Scene {
    let objects = mesh.objects(Vec3::new(0.8, 0.5, 0.3)).expect("triangles");
    Scene::new(objects, Vec3::ZERO)
        .and_then(|s| s.with_light(LIGHT))
        .expect("scene")
}

fn raster(c: &mut Criterion) {
    let one = thread_pool(1).expect("a thread pool");
    let camera = camera();
    let sphere = Mesh::uv_sphere(Vec3::ZERO, 1.0, 224, 224).expect("sphere");
    let meshes = [("uv sphere", sphere), ("torus.obj", torus())];
    let mut group =
        c.benchmark_group("rasterize 1920x1080, per-pixel shading, 1 thread");
    group.sample_size(10);
    for (name, mesh) in meshes {
        let triangles = mesh.triangles.len() as u64;
        let instances = [Model::new(mesh, Vec3::new(0.8, 0.5, 0.3))];
        group.throughput(Throughput::Elements(triangles));
        // Both faces, as the lessons draw open meshes; then with back faces culled, as
        // a rasterizer draws a closed mesh (the hidden half is never rasterized).
        for cull in [Cull::None, Cull::Back] {
            let settings = RasterSettings {
                cull,
                ..RasterSettings::default()
            };
            group.bench_function(
                format!("{name}, {triangles} triangles, {cull:?}"),
                |b| {
                    b.iter(|| {
                        one.install(|| {
                            rasterize(&instances, &camera, &LIGHT, &settings)
                        })
                    })
                },
            );
        }
    }
    group.finish();
}

fn ray_cast(c: &mut Criterion) {
    let camera = camera();
    let scene = triangle_scene(&torus());
    let rows: Vec<u32> = (0..HEIGHT).step_by(ROW_STEP as usize).collect();
    let mut group = c.benchmark_group("ray cast 1920x1080, brute force, 1 thread");
    group.sample_size(10);
    group.throughput(Throughput::Elements(u64::from(WIDTH) * rows.len() as u64));
    group.bench_function("torus.obj, 1024 triangles, every 30th row", |b| {
        b.iter(|| {
            let mut sum = Vec3::ZERO;
            for &y in &rows {
                for x in 0..WIDTH {
                    sum += lit_unshadowed(&scene, &camera.ray(x, y));
                }
            }
            sum
        })
    });
    group.finish();
}

fn bvh_ray_cast(c: &mut Criterion) {
    let one = thread_pool(1).expect("a thread pool");
    let camera = camera();
    let scene =
        triangle_scene(&Mesh::uv_sphere(Vec3::ZERO, 1.0, 224, 224).expect("sphere"));
    let tree = BvhScene::new(scene);
    let mut group = c.benchmark_group("ray cast 1920x1080, BVH, 1 thread");
    group.sample_size(10);
    group.throughput(Throughput::Elements(u64::from(WIDTH) * u64::from(HEIGHT)));
    group.bench_function("uv sphere, 99904 triangles", |b| {
        b.iter(|| one.install(|| render(&camera, |r| lit_unshadowed(&tree, r))))
    });
    group.finish();
}

criterion_group!(benches, raster, bvh_ray_cast, ray_cast);

/// criterion's figures, then the machine and whether the CPU was quiet meanwhile.
fn main() {
    let watch = CpuWatch::start();
    benches();
    Criterion::default().configure_from_args().final_summary();
    println!("{}", watch.report());
}
