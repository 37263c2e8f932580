//! Primary rays per second: lesson 08's scene, shadowless, 1920 x 1080, pinhole
//! camera; the crate's robust caster on one thread and on every core, and the plain
//! reference (textbook tests, `course::measure::plain`) on one thread.
//!
//!     cargo bench --bench ray_casting
//!
//! After criterion's figures, one run measures every variant interleaved (the
//! fastest of 7 rounds each) and prints the ratios: what robustness costs, and what
//! the second core buys. Last, the machine and whether the CPU was quiet.

use criterion::{Criterion, Throughput, criterion_group};
use glam::Vec3;
use render_lessons::camera::Camera;
use render_lessons::course::measure::machine::{CpuWatch, benchmarking, interleaved_min};
use render_lessons::course::measure::plain::PlainScene;
use render_lessons::raycast::shadowless;
use render_lessons::render::render;
use render_lessons::scene::Scene;
use render_lessons::scenes::{lesson08, lesson08_pinhole};

const WIDTH: u32 = 1920;
const HEIGHT: u32 = 1080;

fn setup() -> (Scene, PlainScene, Camera) {
    let scene = lesson08(Vec3::ZERO).expect("the lesson's scene");
    let plain = PlainScene::new(&scene).expect("spheres, a plane, a box, a triangle");
    let pinhole = lesson08_pinhole(WIDTH, HEIGHT).expect("the lesson's camera");
    (scene, plain, pinhole)
}

fn cores() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

fn bench(c: &mut Criterion) {
    let (scene, plain, pinhole) = setup();
    let mut group = c.benchmark_group("primary rays, lesson 08 scene, 1920x1080");
    group.sample_size(10);
    group.throughput(Throughput::Elements(u64::from(WIDTH * HEIGHT)));
    for threads in [1, cores()] {
        group.bench_function(format!("robust, {threads} thread(s)"), |b| {
            b.iter(|| render(&pinhole, Some(threads), |r| shadowless(&scene, r)).expect("render"))
        });
    }
    group.bench_function("plain (textbook tests), 1 thread", |b| {
        b.iter(|| render(&pinhole, Some(1), |r| plain.shadowless(r)).expect("render"))
    });
    group.bench_function("camera rays only, 1 thread", |b| {
        b.iter(|| render(&pinhole, Some(1), |r| r.direction()).expect("render"))
    });
    group.finish();
}

/// Every variant in one run, interleaved, and the ratios between them.
fn one_run() {
    let (scene, plain, pinhole) = setup();
    let cores = cores();
    let robust = |t| render(&pinhole, Some(t), |r| shadowless(&scene, r)).expect("render");
    let textbook = || render(&pinhole, Some(1), |r| plain.shadowless(r)).expect("render");
    let (a, b) = (robust(1), textbook());
    let differ = (0..HEIGHT)
        .flat_map(|y| (0..WIDTH).map(move |x| (x, y)))
        .filter(|&(x, y)| a.get(x, y) != b.get(x, y))
        .count();
    let times = interleaved_min(
        7,
        &mut [
            &mut || drop(textbook()),
            &mut || drop(robust(1)),
            &mut || drop(robust(cores)),
            &mut || drop(render(&pinhole, Some(1), |r| r.direction()).expect("render")),
        ],
    );
    let rate = |i: usize| f64::from(WIDTH * HEIGHT) / times[i].as_secs_f64() / 1e6;
    println!("\none run, fastest of 7 interleaved rounds, 1920x1080 primary rays:");
    println!(
        "  plain (textbook tests), 1 thread  {:6.1} M rays/s",
        rate(0)
    );
    println!(
        "  robust, 1 thread                  {:6.1} M rays/s",
        rate(1)
    );
    println!(
        "  robust, {cores} threads                 {:6.1} M rays/s",
        rate(2)
    );
    println!(
        "  camera rays only, 1 thread        {:6.1} M rays/s",
        rate(3)
    );
    println!(
        "  robustness costs {:.2}x (plain / robust, 1 thread)",
        rate(0) / rate(1)
    );
    println!("  {cores} threads give {:.2}x one", rate(2) / rate(1));
    println!(
        "  the two images differ in {differ} of {} pixels",
        WIDTH * HEIGHT
    );
}

criterion_group!(benches, bench);

fn main() {
    let watch = CpuWatch::start();
    benches();
    Criterion::default().configure_from_args().final_summary();
    if benchmarking() {
        one_run();
        println!("{}", watch.report());
    }
}
