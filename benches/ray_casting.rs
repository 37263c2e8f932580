//! Primary rays per second: lesson 08's scene, shadowless, 1920 x 1080, pinhole
//! camera, on one thread and on every core.
//!
//!     cargo bench --bench ray_casting

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec3;
use render_lessons::raycast::shadowless;
use render_lessons::render::render;
use render_lessons::scenes::{lesson08, lesson08_pinhole};

fn bench(c: &mut Criterion) {
    let scene = lesson08(Vec3::ZERO).expect("the lesson's scene");
    let pinhole = lesson08_pinhole(1920, 1080).expect("the lesson's camera");
    let mut group = c.benchmark_group("primary rays, lesson 08 scene, 1920x1080");
    group.sample_size(10);
    group.throughput(Throughput::Elements(1920 * 1080));
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    for threads in [1, cores] {
        group.bench_function(format!("{threads} thread(s)"), |b| {
            b.iter(|| render(&pinhole, Some(threads), |r| shadowless(&scene, r)).expect("render"))
        });
    }
    group.bench_function("camera rays only, 1 thread", |b| {
        b.iter(|| render(&pinhole, Some(1), |r| r.direction()).expect("render"))
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
