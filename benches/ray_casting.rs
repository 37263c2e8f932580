//! Primary rays per second: lesson 08's scene, shadowless, 1920 x 1080, pinhole
//! camera; the crate's robust caster on one thread and on every core, the plain
//! reference (textbook tests, `course::measure::plain`) on one thread, and the same
//! plain caster written in C (`anchors/plain_caster.c`, the anchor) when a C
//! compiler was there at build time.
//!
//!     cargo bench -p render-benches --bench ray_casting
//!
//! After criterion's figures, one run measures every variant interleaved (the
//! fastest of 7 rounds each) and prints the ratios: the Rust casters against the C
//! anchor, what robustness costs, what the second core buys, and what
//! `render::render`'s set-up (the framebuffer and a progress bar, made on every
//! call; the thread pool is made once, by the caller) adds to a frame. First it checks
//! that the C anchor computes the plain caster's image and camera rays bit for bit.
//! Last, the machine and whether the CPU was quiet.
//!
//! With `RENDER_BENCHES_FIGURES=chapters/figures` the run also writes lesson 11's
//! chart 10, the C anchor against the plain and the robust Rust casters
//! (`11_10_c_anchor.svg`, `.csv`, and `.md` with the numbers the book quotes).

use std::path::{Path, PathBuf};

use criterion::{Criterion, Throughput, criterion_group};
use glam::Vec3;
use rayon::ThreadPool;
use render_benches::anchor;
use render_benches::frame::FrameLoop;
use render_lessons::Result;
use render_lessons::camera::Camera;
use render_lessons::course::bars::Bars;
use render_lessons::course::measure::machine::{
    CpuWatch, benchmarking, interleaved_min,
};
use render_lessons::course::measure::plain::PlainScene;
use render_lessons::course::report::{BookNumbers, Quoted, Run};
use render_lessons::files::write_atomically;
use render_lessons::raycast::shadowless;
use render_lessons::render::{render, thread_pool};
use render_lessons::scene::Scene;
use render_lessons::scenes::{still_life, still_life_pinhole};

const WIDTH: u32 = 1920;
const HEIGHT: u32 = 1080;
const PIXELS: usize = WIDTH as usize * HEIGHT as usize;

fn setup() -> (Scene, PlainScene, Camera) {
    let scene = still_life(Vec3::ZERO).expect("the lesson's scene");
    let plain = PlainScene::new(&scene).expect("spheres, a plane, a box, a triangle");
    let pinhole = still_life_pinhole(WIDTH, HEIGHT).expect("the lesson's camera");
    (scene, plain, pinhole)
}

fn cores() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

fn bench(c: &mut Criterion) {
    let (scene, plain, pinhole) = setup();
    let mut group = c.benchmark_group("primary rays, lesson 08 scene, 1920x1080");
    group.sample_size(10);
    group.throughput(Throughput::Elements(PIXELS as u64));
    let one = thread_pool(1).expect("a thread pool");
    for threads in [1, cores()] {
        let pool = thread_pool(threads).expect("a thread pool");
        group.bench_function(format!("robust, {threads} thread(s)"), |b| {
            b.iter(|| {
                pool.install(|| {
                    render(&pinhole, |r| shadowless(&scene, r)).expect("render")
                })
            })
        });
    }
    group.bench_function("plain (textbook tests), 1 thread", |b| {
        b.iter(|| {
            one.install(|| render(&pinhole, |r| plain.shadowless(r)).expect("render"))
        })
    });
    let mut rgb = vec![Vec3::ZERO; PIXELS];
    if anchor::available() {
        group.bench_function("C anchor (textbook tests), 1 thread", |b| {
            b.iter(|| anchor::frame(WIDTH, HEIGHT, &mut rgb))
        });
    }
    group.bench_function("camera rays only, 1 thread", |b| {
        b.iter(|| one.install(|| render(&pinhole, |r| r.direction()).expect("render")))
    });
    group.finish();
}

/// How many pixels of `a` and `b` differ in any bit.
fn differ(a: &[Vec3], b: &[Vec3]) -> usize {
    let bits = |v: &Vec3| v.to_array().map(f32::to_bits);
    a.iter().zip(b).filter(|(a, b)| bits(a) != bits(b)).count()
}

/// One timed variant of the interleaved run.
struct Variant<'a> {
    name: &'static str,
    threads: usize,
    /// "frame": buffer made once; "render()": `render::render` as it is, on a pool
    /// made once.
    timed: &'static str,
    work: Box<dyn FnMut() + 'a>,
}

/// The C anchor against the plain caster, bit for bit, image and camera rays.
fn check_anchor(plain: &PlainScene, pinhole: &Camera) {
    let mut rgb = vec![Vec3::ZERO; PIXELS];
    let mut xyz = vec![Vec3::ZERO; PIXELS];
    if anchor::frame(WIDTH, HEIGHT, &mut rgb).is_none()
        || anchor::camera(WIDTH, HEIGHT, &mut xyz).is_none()
    {
        println!("  {}", anchor::MISSING);
        return;
    }
    let mut frame = FrameLoop::new(pinhole, 1);
    frame.run(pinhole, |r| plain.shadowless(r));
    let image = differ(&rgb, frame.pixels());
    frame.run(pinhole, |r| r.direction());
    let rays = differ(&xyz, frame.pixels());
    println!(
        "  C anchor ({}) against the Rust plain caster: {image} of {PIXELS} pixels and \
         {rays} camera rays differ in any bit",
        anchor::COMPILER.unwrap_or("?")
    );
}

/// Every variant in one run, interleaved, and the ratios between them.
fn one_run(watch: &CpuWatch) {
    let (scene, plain, pinhole) = setup();
    let cores = cores();
    println!("\none run, 1920x1080 primary rays of lesson 08:");
    check_anchor(&plain, &pinhole);
    let pools = [1, cores].map(|t| (t, thread_pool(t).expect("a thread pool")));
    let a = render(&pinhole, |r| shadowless(&scene, r)).expect("render");
    let b = render(&pinhole, |r| plain.shadowless(r)).expect("render");
    let differ = (0..HEIGHT)
        .flat_map(|y| (0..WIDTH).map(move |x| (x, y)))
        .filter(|&(x, y)| a.get(x, y) != b.get(x, y))
        .count();

    let mut variants = variants(&scene, &plain, &pinhole, &pools);
    let times = interleaved_min(
        7,
        &mut variants
            .iter_mut()
            .map(|v| &mut *v.work as &mut dyn FnMut())
            .collect::<Vec<_>>(),
    );
    let rate = |name: &str, threads: usize, timed: &str| {
        variants
            .iter()
            .zip(&times)
            .find(|(v, _)| v.name == name && v.threads == threads && v.timed == timed)
            .map(|(_, t)| PIXELS as f64 / t.as_secs_f64() / 1e6)
    };
    let c = rate(C, 1, "frame");
    println!("  fastest of 7 interleaved rounds; frame = buffer made once,");
    println!(
        "  render() = render::render as it is (buffer and progress bar per call),"
    );
    println!("  both on a thread pool made once:");
    println!(
        "  {:<36} {:>7} {:>9} {:>10} {:>9}",
        "caster", "threads", "timed", "M rays/s", "/ C"
    );
    for (v, t) in variants.iter().zip(&times) {
        let r = PIXELS as f64 / t.as_secs_f64() / 1e6;
        let base = if v.name.contains("camera") {
            rate(C_CAMERA, 1, "frame")
        } else {
            c
        };
        let of_c = base.map_or("".into(), |c| format!("{:.2}x", r / c));
        println!(
            "  {:<36} {:>7} {:>9} {:>10.1} {:>9}",
            v.name, v.threads, v.timed, r, of_c
        );
    }
    let ratio = |what: &str, a: Option<f64>, b: Option<f64>| {
        if let (Some(a), Some(b)) = (a, b) {
            println!("  {what} {:.2}x", a / b);
        }
    };
    let plain1 = rate(PLAIN, 1, "frame");
    let robust1 = rate(ROBUST, 1, "frame");
    ratio("C anchor / Rust plain (frame, 1 thread):", c, plain1);
    ratio("C anchor / Rust robust (frame, 1 thread):", c, robust1);
    ratio(
        "robustness costs (plain / robust, frame, 1 thread):",
        plain1,
        robust1,
    );
    ratio(
        "C camera / Rust camera (frame, 1 thread):",
        rate(C_CAMERA, 1, "frame"),
        rate(CAMERA, 1, "frame"),
    );
    ratio(
        &format!("{cores} threads give (robust, frame):"),
        rate(ROBUST, cores, "frame"),
        robust1,
    );
    ratio(
        "render() set-up costs (robust, 1 thread, frame / render()):",
        robust1,
        rate(ROBUST, 1, "render()"),
    );
    ratio(
        &format!("render() set-up costs (robust, {cores} threads, frame / render()):"),
        rate(ROBUST, cores, "frame"),
        rate(ROBUST, cores, "render()"),
    );
    if let Some(camera) = rate(CAMERA, 1, "frame") {
        println!(
            "  camera rays: {:.2} ns each (frame, 1 thread)",
            1e3 / camera
        );
    }
    println!("  robust and plain images differ in {differ} of {PIXELS} pixels");
    if let (Some(dir), Some(c), Some(plain), Some(robust)) =
        (std::env::var_os(FIGURES), c, plain1, robust1)
    {
        // A relative folder is the repository's (cargo runs a bench in its package).
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(dir);
        let written = figure(&dir, [c, plain, robust], watch);
        match written {
            Ok(paths) => paths
                .iter()
                .for_each(|p| println!("  wrote {}", p.display())),
            Err(e) => println!("  could not write the chart: {e}"),
        }
    }
}

/// Set to a folder (`chapters/figures`, relative to the repository's root) to have
/// the run write lesson 11's chart of the C anchor against the Rust casters there.
const FIGURES: &str = "RENDER_BENCHES_FIGURES";

/// The chart's file stem, and the command that writes it.
const STEM: &str = "11_10_c_anchor";
const COMMAND: &str = "`RENDER_BENCHES_FIGURES=chapters/figures cargo bench -p render-benches --bench ray_casting`";

/// Lesson 11's chart 10 from one run's M rays/s of the C anchor, the plain and the
/// robust caster (frames, one thread): what structure costs (C against plain Rust,
/// the same tests) and what robustness costs (plain against robust Rust). Writes
/// `STEM.svg`, `.csv` and `.md` (the numbers the book quotes) into `dir`.
fn figure(
    dir: &Path,
    [c, plain, robust]: [f64; 3],
    watch: &CpuWatch,
) -> Result<Vec<PathBuf>> {
    let ns = |rate: f64| 1e3 / rate;
    let bars = Bars::new(
        "10. One ray of lesson 08, three casters (one thread)",
        "ns per primary ray",
    )
    .with("plain C (textbook tests)", ns(c))
    .with("plain Rust (textbook tests)", ns(plain))
    .with("robust Rust (this crate)", ns(robust));
    let mut table = Quoted::new(
        "anchor",
        true,
        &["caster", "ns per ray", "M rays/s", "against the C anchor"],
    );
    for (name, rate) in [
        ("plain C (textbook tests)", c),
        ("plain Rust (textbook tests)", plain),
        ("robust Rust (this crate)", robust),
    ] {
        table = table.row(vec![
            name.to_string(),
            format!("{:.1}", ns(rate)),
            format!("{rate:.1}"),
            format!("{:.2}x", rate / c),
        ]);
    }
    let numbers = BookNumbers::default()
        .table(table)
        .value("structure", true, format!("{:.2}", c / plain))
        .value("robustness", true, format!("{:.2}", plain / robust));
    let load = watch.others_share().map_or("load unknown".into(), |share| {
        format!("other processes used {:.0}% of a core", 100.0 * share)
    });
    let here = Run::here("");
    let run = Run {
        quality: COMMAND,
        machine: format!("{}, {load}", here.machine),
        date: here.date,
    };
    let mut written = bars.save(dir, STEM)?.to_vec();
    let md = dir.join(format!("{STEM}.md"));
    let again = format!("rerun {COMMAND}");
    let text = numbers.markdown_by(STEM, &run, "benches/ray_casting.rs", &again);
    write_atomically(&md, text.as_bytes())?;
    written.push(md);
    Ok(written)
}

const C: &str = "C anchor (textbook tests, -O2)";
const PLAIN: &str = "plain (textbook tests)";
const ROBUST: &str = "robust (this crate)";
const C_CAMERA: &str = "C camera rays only";
const CAMERA: &str = "camera rays only";

/// The variants timed against each other; the C ones only when the anchor is there.
fn variants<'a>(
    scene: &'a Scene,
    plain: &'a PlainScene,
    pinhole: &'a Camera,
    pools: &'a [(usize, ThreadPool); 2],
) -> Vec<Variant<'a>> {
    let frame = |threads| FrameLoop::new(pinhole, threads);
    let variant = |name, threads, timed, work: Box<dyn FnMut() + 'a>| Variant {
        name,
        threads,
        timed,
        work,
    };
    let mut v = Vec::new();
    if anchor::available() {
        let mut rgb = vec![Vec3::ZERO; PIXELS];
        let mut xyz = vec![Vec3::ZERO; PIXELS];
        v.push(variant(
            C,
            1,
            "frame",
            Box::new(move || {
                anchor::frame(WIDTH, HEIGHT, &mut rgb);
            }),
        ));
        v.push(variant(
            C_CAMERA,
            1,
            "frame",
            Box::new(move || {
                anchor::camera(WIDTH, HEIGHT, &mut xyz);
            }),
        ));
    }
    let mut f = frame(1);
    v.push(variant(
        PLAIN,
        1,
        "frame",
        Box::new(move || f.run(pinhole, |r| plain.shadowless(r))),
    ));
    v.push(variant(
        PLAIN,
        1,
        "render()",
        Box::new(move || {
            pools[0]
                .1
                .install(|| drop(render(pinhole, |r| plain.shadowless(r))))
        }),
    ));
    for (threads, pool) in pools {
        let threads = *threads;
        let mut f = frame(threads);
        v.push(variant(
            ROBUST,
            threads,
            "frame",
            Box::new(move || f.run(pinhole, |r| shadowless(scene, r))),
        ));
        v.push(variant(
            ROBUST,
            threads,
            "render()",
            Box::new(move || {
                pool.install(|| drop(render(pinhole, |r| shadowless(scene, r))))
            }),
        ));
    }
    let mut f = frame(1);
    v.push(variant(
        CAMERA,
        1,
        "frame",
        Box::new(move || f.run(pinhole, |r| r.direction())),
    ));
    v.push(variant(
        CAMERA,
        1,
        "render()",
        Box::new(move || {
            pools[0]
                .1
                .install(|| drop(render(pinhole, |r| r.direction())))
        }),
    ));
    v
}

criterion_group!(benches, bench);

fn main() {
    let watch = CpuWatch::start();
    benches();
    Criterion::default().configure_from_args().final_summary();
    if benchmarking() {
        one_run(&watch);
        println!("{}", watch.report());
    }
}
