//! ns per intersection test, for every method of lesson 07, naive and robust.
//!
//!     cargo bench -p render-benches --bench intersections

use std::hint::black_box;

use criterion::{Criterion, criterion_group};
use glam::Vec3;
use render_lessons::course::measure::machine::CpuWatch;
use render_lessons::ray::{Interval, Ray};
use render_lessons::shapes::{Aabb, Plane, Quadric, Sphere, Triangle};

/// 1024 rays from around (0, 0, 5) towards the unit cube, some hitting, some missing.
fn rays() -> Vec<Ray> {
    (0..1024)
        .map(|i| {
            let a = i as f32 * 0.618_034;
            let target = Vec3::new((a * 7.0).sin() * 1.5, (a * 5.0).cos() * 1.5, 0.0);
            let origin = Vec3::new(a.sin() * 0.3, a.cos() * 0.3, 5.0);
            Ray::new(origin, target - origin).expect("finite, non-zero")
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let rays = rays();
    let sphere = Sphere::new(Vec3::ZERO, 1.0).expect("valid sphere");
    let plane = Plane::new(Vec3::ZERO, Vec3::new(0.2, 0.3, 1.0)).expect("valid plane");
    let aabb = Aabb::new(Vec3::splat(-1.0), Vec3::splat(1.0)).expect("valid box");
    let triangle = Triangle::new(
        Vec3::new(-1.0, -1.0, 0.0),
        Vec3::new(1.0, -1.0, 0.0),
        Vec3::new(0.0, 1.0, 0.2),
    )
    .expect("valid triangle");
    let quadric =
        Quadric::ellipsoid(Vec3::new(1.0, 0.8, 0.6)).expect("valid ellipsoid");
    let mut group = c.benchmark_group("intersection (1024 rays per iteration)");
    let n = f32::INFINITY;
    macro_rules! case {
        ($name:expr, $body:expr) => {
            group.bench_function($name, |b| {
                b.iter(|| {
                    let mut hits = 0u32;
                    for ray in &rays {
                        hits += u32::from($body(black_box(ray)));
                    }
                    hits
                })
            });
        };
    }
    case!("sphere textbook", |r: &Ray| !sphere
        .roots_textbook(r)
        .is_empty());
    case!("sphere stable (Hearn-Baker)", |r: &Ray| !sphere
        .roots_stable(r)
        .is_empty());
    case!("sphere hit", |r: &Ray| sphere
        .hit(r, Interval::new(0.0, n))
        .is_some());
    case!("plane hit", |r: &Ray| plane
        .hit(r, Interval::new(0.0, n))
        .is_some());
    case!("box slab", |r: &Ray| aabb
        .slab(r, Interval::new(0.0, n))
        .is_some());
    case!("box slab conservative", |r: &Ray| aabb
        .slab_conservative(r, Interval::new(0.0, n))
        .is_some());
    case!("box hit", |r: &Ray| aabb
        .hit(r, Interval::new(0.0, n))
        .is_some());
    case!("triangle Möller-Trumbore", |r: &Ray| triangle
        .moller_trumbore(r, Interval::new(0.0, n))
        .is_some());
    case!("triangle watertight", |r: &Ray| triangle
        .watertight(r, Interval::new(0.0, n))
        .is_some());
    case!("triangle hit", |r: &Ray| triangle
        .hit(r, Interval::new(0.0, n))
        .is_some());
    case!("quadric textbook", |r: &Ray| quadric
        .roots_textbook(r)
        .first_in(Interval::new(0.0, n))
        .is_some());
    case!("quadric stable", |r: &Ray| quadric
        .roots_stable(r)
        .first_in(Interval::new(0.0, n))
        .is_some());
    case!("quadric hit", |r: &Ray| quadric
        .hit(r, Interval::new(0.0, n))
        .is_some());
    group.finish();
}

criterion_group!(benches, bench);

/// criterion's figures, then the machine and whether the CPU was quiet meanwhile.
fn main() {
    let watch = CpuWatch::start();
    benches();
    Criterion::default().configure_from_args().final_summary();
    println!("{}", watch.report());
}
