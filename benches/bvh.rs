//! The BVH of lesson 11: how long it takes to build, how many rays per second it
//! traces on a ~100k-triangle mesh, against a well-kept Rust BVH crate on the same
//! rays, and where it overtakes the plain list.
//!
//!     cargo bench -p render-benches --bench bvh
//!
//! The meshes are UV spheres (`Mesh::uv_sphere`, n x n segments, 2 n (n - 1)
//! triangles) seen by a pinhole camera; every ray asks for the closest hit only, on
//! one thread. The rays are made once, before the clock starts.
//!
//! The anchor is `obvhs` (crates.io): its binary BVH (`Bvh2`) and its compressed
//! 8-wide BVH (`CwBvh`, SIMD traversal), both built with its "medium" preset, both
//! intersecting triangles with its own Möller-Trumbore test (not watertight). The
//! comparison is fair: each side starts from the same `Ray`s and makes its own
//! per-ray data inside the timed loop (obvhs's ray with 1/d; this crate's 1/d,
//! and the watertight test's shear for a ray that meets the root box), and each
//! answers the same question, the nearest triangle and its distance (this crate's
//! `closest_object`, which builds no hit record, as obvhs builds none). After
//! criterion's figures, one run times every builder and every traversal interleaved
//! (the fastest of 5 rounds each) and prints the ratios, how many rays each finds a
//! hit for, and whether the CPU was quiet.
//!
//! The same run times a second anchor when Embree 3 is installed (Debian:
//! `apt-get install libembree-dev`; the bench says so when it is not): Embree's
//! `rtcIntersect1` through a small C shim (`anchors/embree_caster.c`, `embree.rs`),
//! on the same mesh, shared with Embree as vertex and index buffers, and the same
//! rays, its tree built on one thread at quality medium. Before timing, the bench
//! checks that Embree and the crate find the same triangle at the same distance for
//! every ray. `ours / Embree` is Embree's time over ours for the build, and our rays
//! per second over Embree's for the cameras: above 1, the crate is faster.

use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group};
use glam::Vec3;
use obvhs::ray::RayHit;
use render_benches::clock;
use render_benches::embree::{self, Agreement, EmbreeMesh, flat_rays};
use render_benches::mesh_view::{
    FAR, NEAR, camera, obvhs_ray, obvhs_triangles, rays, sphere_mesh, sphere_scene,
};
use render_lessons::bvh::Bvh;
use render_lessons::course::measure::machine::{
    CpuWatch, benchmarking, interleaved_min,
};
use render_lessons::ray::Interval;
use render_lessons::raycast::shadowless;
use render_lessons::scene::BvhScene;
use render_lessons::scene::Intersect;

/// Build time and rays per second on 99 904 triangles (n = 224).
fn big_mesh(c: &mut Criterion) {
    let scene = sphere_scene(224);
    let mut group = c.benchmark_group("bvh, 99904 triangles");
    group.sample_size(10);
    group.warm_up_time(Duration::from_secs(1));
    group.bench_function("build (binned SAH)", |b| {
        b.iter(|| Bvh::build(scene.objects()))
    });
    let bvh = BvhScene::new(scene);
    let rays = rays(&camera(1920, 1080, NEAR));
    group.throughput(Throughput::Elements(rays.len() as u64));
    group.bench_function("closest hit, 1920x1080 rays, 1 thread", |b| {
        b.iter(|| rays.iter().map(|r| shadowless(&bvh, r)).sum::<Vec3>())
    });
    group.finish();
}

/// The plain list against the BVH at about 10, 100, 1k and 10k triangles, on the
/// 5184 rays of a 96 x 54 image. A full HD frame through the 10k-triangle list
/// would take about a minute per sample.
fn crossover(c: &mut Criterion) {
    let rays = rays(&camera(96, 54, NEAR));
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
            b.iter(|| rays.iter().map(|r| shadowless(&bvh, r)).sum::<Vec3>())
        });
    }
    group.finish();
}

/// Our BVH against obvhs's two and Embree, in one run: build times, then rays per
/// second at two cameras (near: about a third of the rays hit; far: a few percent).
fn one_run() {
    let scene = sphere_scene(224);
    let triangles = obvhs_triangles(&scene);
    let params = obvhs::BvhBuildParams::medium_build();
    let embree_mesh = EmbreeMesh::new(&sphere_mesh(224));
    let mut ours = None;
    let mut bvh2 = None;
    let mut cwbvh = None;
    let mut embree = None;
    let build = interleaved_min(
        5,
        &mut [
            &mut || ours = Some(Bvh::build(scene.objects())),
            &mut || {
                let mut t = Duration::ZERO;
                bvh2 = Some(obvhs::bvh2::builder::build_bvh2_from_tris(
                    &triangles, params, &mut t,
                ))
            },
            &mut || {
                let mut t = Duration::ZERO;
                cwbvh = Some(obvhs::cwbvh::builder::build_cwbvh_from_tris(
                    &triangles, params, &mut t,
                ))
            },
            &mut || embree = embree_mesh.build(),
        ],
    );
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    println!(
        "\none run, {} triangles, 1 thread, fastest of 5 interleaved rounds",
        triangles.len()
    );
    println!(
        "  build: ours (binned SAH) {:.1} ms, obvhs Bvh2 {:.1} ms, obvhs CwBvh {:.1} ms",
        ms(build[0]),
        ms(build[1]),
        ms(build[2])
    );
    println!(
        "         ours / obvhs Bvh2: {:.2}x the time",
        ms(build[0]) / ms(build[1])
    );
    let embree = match embree {
        Some(Ok(scene)) => {
            println!(
                "         Embree {} (quality medium, 1 thread) {:.1} ms: ours / Embree {:.2}x \
                 (Embree's time over ours)",
                embree::version().unwrap_or_default(),
                ms(build[3]),
                ms(build[3]) / ms(build[0])
            );
            Some(scene)
        }
        Some(Err(e)) => {
            println!("         Embree anchor skipped: {e}");
            None
        }
        None => {
            println!("         {}", embree::MISSING);
            None
        }
    };
    let (Some(bvh2), Some(cwbvh)) = (bvh2, cwbvh) else {
        return;
    };
    let ours = BvhScene::new(scene);
    for (label, distance) in [("near camera", NEAR), ("far camera", FAR)] {
        let rays = rays(&camera(1920, 1080, distance));
        let flat = flat_rays(&rays);
        let embree = embree.as_ref().filter(|e| {
            let agreement = Agreement::of(&ours, e, &rays);
            if agreement.differ() > 0 {
                println!("    {agreement}");
            }
            agreement.holds()
        });
        let (mut h0, mut h1, mut h2, mut h3) = (0, 0, 0, 0);
        let times = interleaved_min(
            5,
            &mut [
                &mut || {
                    h0 = rays
                        .iter()
                        .filter(|r| ours.closest_object(r, Interval::AHEAD).is_some())
                        .count()
                },
                &mut || {
                    h1 = rays
                        .iter()
                        .filter(|r| {
                            let mut hit = RayHit::none();
                            bvh2.ray_traverse(obvhs_ray(r), &mut hit, |ray, id| {
                                triangles[bvh2.primitive_indices[id] as usize]
                                    .intersect(ray)
                            })
                        })
                        .count()
                },
                &mut || {
                    h2 = rays
                        .iter()
                        .filter(|r| {
                            let mut hit = RayHit::none();
                            cwbvh.ray_traverse(obvhs_ray(r), &mut hit, |ray, id| {
                                triangles[cwbvh.primitive_indices[id] as usize]
                                    .intersect(ray)
                            })
                        })
                        .count()
                },
                &mut || h3 = embree.map_or(0, |e| e.count_hits(&flat)),
            ],
        );
        let hits = [h0, h1, h2];
        let rate = |i: usize| rays.len() as f64 / times[i].as_secs_f64() / 1e6;
        println!(
            "  {label}, {:.1}% of {} rays hit: ours {:.1} M rays/s, obvhs Bvh2 {:.1}, obvhs CwBvh {:.1}",
            100.0 * hits[0] as f64 / rays.len() as f64,
            rays.len(),
            rate(0),
            rate(1),
            rate(2)
        );
        println!(
            "    ours / Bvh2 {:.2}x, ours / CwBvh {:.2}x; rays hit: ours {}, Bvh2 {}, CwBvh {}",
            rate(0) / rate(1),
            rate(0) / rate(2),
            hits[0],
            hits[1],
            hits[2]
        );
        if embree.is_some() {
            println!(
                "    Embree {:.1} M rays/s: ours / Embree {:.2}x (our rays per second over \
                 Embree's); rays hit: Embree {h3}",
                rate(3),
                rate(0) / rate(3)
            );
        }
    }
}

criterion_group!(benches, big_mesh, crossover);

fn main() {
    let watch = CpuWatch::start();
    benches();
    Criterion::default().configure_from_args().final_summary();
    if benchmarking() {
        let before = clock::cycles_per_second(3);
        one_run();
        println!("{}", clock::line(before, clock::cycles_per_second(3)));
        println!("{}", watch.report());
    }
}
