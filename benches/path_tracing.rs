//! Lesson 10's path tracer, measured twice.
//!
//! 1. Samples per second (criterion): smallpt's Cornell box at 1024 x 768, one pass
//!    of 1 sample per pixel per iteration, with MIS (the lesson's default) and with
//!    cosine sampling and no light sampling (smallpt's algorithm), on one thread and
//!    on every core.
//! 2. The equal-time comparison (not criterion; run after it): the image error (RMSE)
//!    against a converged reference after the same rendering time, for smallpt's
//!    algorithm and for the estimators that sample the light, at 256 x 192.
//! 3. Against Mitsuba 3 (not criterion): time per path sample on one thread, the
//!    crate against Mitsuba's `scalar_rgb` and `llvm_ad_rgb` on the same scene
//!    (lesson 10's Cornell box, 128 x 96, MIS, at most 8 bounces, no Russian
//!    roulette), each line saying so when Mitsuba or libLLVM is missing
//!    (`mitsuba.rs`).
//!
//! ```text
//! cargo bench -p render-benches --bench path_tracing                  # all three
//! cargo bench -p render-benches --bench path_tracing -- "1024x768"    # samples per second only
//! cargo bench -p render-benches --bench path_tracing -- equal-time    # the comparison only
//! cargo bench -p render-benches --bench path_tracing -- mitsuba       # against Mitsuba only
//! ```
//!
//! The comparisons run only under `cargo bench` (not when `cargo test --benches`
//! runs this file once as a test). Its reference is cached in `target/` as PFM
//! files named by the source of `src/pathtrace/`, so editing the path tracer renders
//! it again; `PT_FRESH_REFERENCE=1` forces that too.

use std::fs;
use std::path::PathBuf;
use std::time::{Duration, Instant};

use criterion::{Criterion, SamplingMode, Throughput, criterion_group};
use render_benches::mitsuba;
use render_lessons::camera::Camera;
use render_lessons::course::measure::machine::{CpuWatch, benchmarking};
use render_lessons::course::measure::variance::{Seen, pixel_variance};
use render_lessons::framebuffer::Framebuffer;
use render_lessons::framebuffer::pfm::{load_pfm, save_pfm};
use render_lessons::pathtrace::progressive::rmse;
use render_lessons::pathtrace::{Accumulator, PixelSampling, Sampling};
use render_lessons::pathtrace::{Settings, SphereSampling};
use render_lessons::scene::Scene;
use render_lessons::scenes::path_tracing::{self, Staged};

/// The lesson's settings (examples/10_path_tracing.rs with its defaults) with
/// `sampling`: depth at most 8, Russian roulette, cone-sampled spheres.
fn settings(sampling: Sampling) -> Settings {
    Settings {
        sampling,
        sphere_lights: SphereSampling::Cone,
        max_depth: Some(8),
        russian_roulette: true,
        ..Settings::default()
    }
}

fn cores() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

// ANCHOR: samples_per_second
fn samples_per_second(c: &mut Criterion) {
    let (width, height) = (1024, 768);
    let Staged { scene, camera } =
        path_tracing::cornell(width, height).expect("the Cornell box");
    let mut group =
        c.benchmark_group("path tracing, smallpt's Cornell box, 1024x768, 1 spp");
    group.sample_size(10);
    // One iteration takes a second or more: the same number in every sample.
    group.sampling_mode(SamplingMode::Flat);
    group.warm_up_time(Duration::from_secs(1));
    group.measurement_time(Duration::from_secs(20));
    group.throughput(Throughput::Elements(u64::from(width * height)));
    for (name, sampling) in [("MIS", Sampling::Mis), ("cosine", Sampling::Cosine)] {
        let settings = settings(sampling);
        for threads in [1, cores()] {
            let pool =
                render_lessons::render::thread_pool(threads).expect("a thread pool");
            let mut acc = Accumulator::new(&camera, 1);
            group.bench_function(format!("{name}, {threads} thread(s)"), |b| {
                b.iter(|| {
                    pool.install(|| {
                        acc.render_pass(
                            &scene,
                            &camera,
                            &settings,
                            PixelSampling::Independent,
                            1,
                        )
                    })
                    .expect("pass")
                })
            });
            assert_eq!(acc.non_finite(), 0, "NaN or infinite samples");
        }
    }
    group.finish();
}
// ANCHOR_END: samples_per_second

criterion_group!(benches, samples_per_second);

/// The comparison's image size.
const WIDTH: u32 = 256;
const HEIGHT: u32 = 192;
/// Samples per pixel of each half of the reference (MIS, two seeds).
const REFERENCE_HALF_SPP: u32 = 2048;
/// Rendering time each method gets.
const SECONDS: f64 = 30.0;
/// The times at which the errors are compared.
const CHECKPOINTS: [f64; 6] = [0.5, 1.0, 2.0, 5.0, 10.0, 30.0];
/// The seed of the compared runs; the reference's halves use other seeds.
const SEED: u64 = 1;
const REFERENCE_SEEDS: [u64; 2] = [0x5eed_0001, 0x5eed_0002];

/// The path tracer's source, hashed: the reference cache is valid for this code only.
fn source_hash() -> u64 {
    use std::hash::{Hash, Hasher};
    let sources = [
        include_str!("../src/pathtrace/estimator.rs"),
        include_str!("../src/camera/thin_lens.rs"),
        include_str!("../src/pathtrace/light.rs"),
        include_str!("../src/material.rs"),
        include_str!("../src/pathtrace/mis.rs"),
        include_str!("../src/pathtrace/next_event.rs"),
        include_str!("../src/pathtrace/progressive.rs"),
        include_str!("../src/rng.rs"),
        include_str!("../src/pathtrace/roulette.rs"),
        include_str!("../src/scene/mod.rs"),
        include_str!("../src/scenes/path_tracing.rs"),
        include_str!("../src/pathtrace/settings.rs"),
        include_str!("../src/sampling.rs"),
        include_str!("../src/spawn.rs"),
    ];
    // A fixed FNV-1a, so the name does not change with the std hasher.
    struct Fnv(u64);
    impl Hasher for Fnv {
        fn finish(&self) -> u64 {
            self.0
        }
        fn write(&mut self, bytes: &[u8]) {
            for &b in bytes {
                self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
            }
        }
    }
    let mut h = Fnv(0xcbf2_9ce4_8422_2325);
    sources.hash(&mut h);
    h.finish()
}

/// The mean of two images of the same size.
fn average(a: &Framebuffer, b: &Framebuffer) -> Framebuffer {
    Framebuffer::from_fn(a.width(), a.height(), |x, y| {
        (a.get(x, y).unwrap_or_default() + b.get(x, y).unwrap_or_default()) / 2.0
    })
    .expect("image")
}

/// One half of the reference: MIS, `REFERENCE_HALF_SPP` samples, seed `seed`, read
/// from the cache if it is there.
fn reference_half(scene: &Scene, camera: &Camera, seed: u64) -> Framebuffer {
    // The repository's target/ (this bench's package is the folder benches/).
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target");
    let path = dir.join(format!(
        "path_tracing_reference_{WIDTH}x{HEIGHT}_mis_{REFERENCE_HALF_SPP}spp_seed{seed:x}_{:016x}.pfm",
        source_hash()
    ));
    let fresh = std::env::var_os("PT_FRESH_REFERENCE").is_some();
    if !fresh && let Ok(image) = load_pfm(&path) {
        println!(
            "reference half (seed {seed:#x}) read from {}",
            path.display()
        );
        return image;
    }
    let start = Instant::now();
    let mut acc = Accumulator::new(camera, seed);
    let settings = settings(Sampling::Mis);
    let mut image = None;
    while acc.samples() < REFERENCE_HALF_SPP {
        let spp = 64.min(REFERENCE_HALF_SPP - acc.samples());
        let pass =
            acc.render_pass(scene, camera, &settings, PixelSampling::Independent, spp);
        image = Some(pass.expect("reference pass"));
    }
    assert_eq!(
        acc.non_finite(),
        0,
        "NaN or infinite samples in the reference"
    );
    let image = image.expect("at least one pass");
    println!(
        "reference half (seed {seed:#x}): {REFERENCE_HALF_SPP} spp in {:.0} s",
        start.elapsed().as_secs_f64()
    );
    if fs::create_dir_all(&dir).is_ok()
        && let Err(e) = save_pfm(&path, &image)
    {
        println!("could not cache the reference: {e}");
    }
    image
}

/// A method being compared: its accumulator and its (seconds, RMSE, spp) history.
struct Run {
    name: &'static str,
    settings: Settings,
    acc: Accumulator,
    seconds: f64,
    history: Vec<(f64, f64, u32)>,
    last: Option<Framebuffer>,
}

impl Run {
    /// The RMSE at time `t`: that of the last image finished by then.
    fn rmse_at(&self, t: f64) -> Option<(f64, u32)> {
        let i = self.history.partition_point(|&(s, _, _)| s <= t);
        if i == 0 {
            return None;
        }
        let (_, e, spp) = self.history[i - 1];
        Some((e, spp))
    }

    /// The first time its RMSE is at most `e`.
    fn time_to(&self, e: f64) -> Option<(f64, u32)> {
        self.history
            .iter()
            .find(|&&(_, r, _)| r <= e)
            .map(|&(s, _, spp)| (s, spp))
    }
}

/// Formats an RMSE measured against a reference with error `e_ref`, and the same
/// with the reference's share taken out: measured^2 = e_method^2 + e_ref^2 when the
/// two are independent.
fn corrected(measured: f64, e_ref: f64) -> f64 {
    (measured * measured - e_ref * e_ref).max(0.0).sqrt()
}

// ANCHOR: equal_time
/// The equal-time comparison. Every method renders 1 sample per pixel per pass on
/// the same thread pool (every core); the passes of the methods take turns, so a
/// change in the machine's load falls on all of them alike, and each method's clock
/// counts only its own passes (the RMSE after each pass is computed off the clock).
fn equal_time() {
    let threads = cores();
    println!(
        "\nEqual-time comparison: smallpt's Cornell box, {WIDTH}x{HEIGHT}, {threads} thread(s)"
    );
    let Staged { scene, camera } =
        path_tracing::cornell(WIDTH, HEIGHT).expect("the Cornell box");
    let halves = REFERENCE_SEEDS.map(|seed| reference_half(&scene, &camera, seed));
    let reference = average(&halves[0], &halves[1]);
    // The halves are independent, each with error e_half; their difference has
    // RMSE sqrt(2) e_half, their mean error e_half / sqrt(2) = RMSE(halves) / 2.
    let e_ref = rmse(&halves[0], &halves[1]) / 2.0;
    println!(
        "reference: MIS, 2 x {REFERENCE_HALF_SPP} spp (seeds {:#x}, {:#x}), mean {:.5}, \
         its own RMSE about {e_ref:.5}",
        REFERENCE_SEEDS[0],
        REFERENCE_SEEDS[1],
        reference.mean()
    );
    let pool = render_lessons::render::thread_pool(threads).expect("a thread pool");
    let methods = [
        ("(a) cosine, no light sampling (smallpt)", Sampling::Cosine),
        ("(b1) next event estimation", Sampling::NextEvent),
        ("(b2) MIS", Sampling::Mis),
    ];
    let mut runs: Vec<Run> = methods
        .iter()
        .map(|&(name, sampling)| Run {
            name,
            settings: settings(sampling),
            acc: Accumulator::new(&camera, SEED),
            seconds: 0.0,
            history: Vec::new(),
            last: None,
        })
        .collect();
    pool.install(|| {
        while runs.iter().any(|r| r.seconds < SECONDS) {
            for run in runs.iter_mut().filter(|r| r.seconds < SECONDS) {
                let start = Instant::now();
                let image = run
                    .acc
                    .render_pass(
                        &scene,
                        &camera,
                        &run.settings,
                        PixelSampling::Independent,
                        1,
                    )
                    .expect("pass");
                run.seconds += start.elapsed().as_secs_f64();
                let e = rmse(&image, &reference);
                run.history.push((run.seconds, e, run.acc.samples()));
                run.last = Some(image);
            }
        }
    });
    for run in &runs {
        assert_eq!(run.acc.non_finite(), 0, "NaN or infinite samples");
    }
    report(&runs, e_ref);
}
// ANCHOR_END: equal_time

fn report(runs: &[Run], e_ref: f64) {
    println!("\nRMSE against the reference at equal times (spp reached in brackets):");
    print!("| seconds |");
    for run in runs {
        print!(" {} |", run.name);
    }
    println!();
    println!("|---|{}", "---|".repeat(runs.len()));
    for t in CHECKPOINTS {
        print!("| {t} |");
        for run in runs {
            match run.rmse_at(t) {
                Some((e, spp)) => print!(" {e:.5} ({spp}) |"),
                None => print!(" - |"),
            }
        }
        println!();
    }
    println!("\nAt the end of each run:");
    println!(
        "| method | seconds | spp | spp per second | RMSE | RMSE without the reference's share | image mean |"
    );
    println!("|---|---|---|---|---|---|---|");
    for run in runs {
        let (s, e, spp) = *run.history.last().expect("at least one pass");
        let m = run.last.as_ref().map_or(0.0, Framebuffer::mean);
        println!(
            "| {} | {s:.2} | {spp} | {:.1} | {e:.5} | {:.5} | {m:.5} |",
            run.name,
            f64::from(spp) / s,
            corrected(e, e_ref)
        );
    }
    let (a_seconds, a_error, a_spp) =
        *runs[0].history.last().expect("at least one pass");
    println!(
        "\nTime to reach (a)'s final RMSE {a_error:.5} ((a) took {a_seconds:.2} s, {a_spp} spp):"
    );
    println!("| method | seconds | spp | speed-up over (a) |");
    println!("|---|---|---|---|");
    for run in runs {
        match run.time_to(a_error) {
            Some((s, spp)) => {
                println!("| {} | {s:.3} | {spp} | {:.1}x |", run.name, a_seconds / s)
            }
            None => println!("| {} | not reached | | |", run.name),
        }
    }
    // How much of (a)'s final error is the reference's own.
    println!(
        "\nThe reference's own RMSE {e_ref:.5} is {:.0}% of (a)'s final RMSE \
         (in squares: {:.1}% of its mean squared error).",
        100.0 * e_ref / a_error,
        100.0 * (e_ref * e_ref) / (a_error * a_error)
    );
}

/// Whether to run the part named `name` after criterion: only under `cargo bench`
/// (which passes `--bench`), and only with no name filter or the filter `name`.
fn wants(name: &str) -> bool {
    if !benchmarking() {
        return false;
    }
    let args: Vec<String> = std::env::args().skip(1).collect();
    let filters: Vec<&String> = args.iter().filter(|a| !a.starts_with('-')).collect();
    filters.is_empty() || filters.iter().any(|f| f.as_str() == name)
}

fn main() {
    let watch = CpuWatch::start();
    benches();
    Criterion::default().configure_from_args().final_summary();
    let (equal, anchor) = (wants("equal-time"), wants("mitsuba"));
    if equal {
        equal_time();
        variance_analysis();
    }
    if anchor {
        against_mitsuba();
    }
    if equal || anchor {
        println!("\n{}", watch.report());
    }
}

/// The Mitsuba comparison's image, depth and samples per pixel.
const MITSUBA_VIEW: mitsuba::View = mitsuba::View {
    width: 128,
    height: 96,
    max_depth: 8,
};
const MITSUBA_SPP: u32 = 64;
/// Interleaved rounds: the crate, then each Mitsuba variant, three times.
const MITSUBA_ROUNDS: u32 = 3;
/// The largest |z| of the difference of the image means for which the two
/// renderers count as rendering the same image (`mitsuba::z_of_means`).
const MITSUBA_Z: f64 = 5.0;

// ANCHOR: against_mitsuba
/// Time per path sample on one thread against Mitsuba 3 on the same scene: the
/// fastest of `MITSUBA_ROUNDS` interleaved rounds each, the crate rendering with
/// the settings of `cross-check render` (the scene Mitsuba is given is built from
/// the crate's own description of it). The ratio is Mitsuba's time per sample
/// over ours, as the BVH bench's ratios are ours over the anchor's speed: above
/// 1, the crate is faster. A variant whose image has another mean (|z| above
/// `MITSUBA_Z`) rendered something else and is left out.
fn against_mitsuba() {
    let mitsuba::View {
        width,
        height,
        max_depth,
    } = MITSUBA_VIEW;
    println!(
        "\nAgainst Mitsuba 3: lesson 10's Cornell box, {width}x{height}, MIS, at most \
         {max_depth} bounces (Mitsuba max_depth {}), no Russian roulette, {MITSUBA_SPP} spp, \
         1 thread, fastest of {MITSUBA_ROUNDS} interleaved rounds",
        max_depth + 1
    );
    let Staged { scene, camera } =
        path_tracing::cornell(width, height).expect("the Cornell box");
    let settings = Settings {
        sampling: Sampling::Mis,
        max_depth: Some(max_depth),
        russian_roulette: false,
        ..Settings::default()
    };
    let pool = render_lessons::render::thread_pool(1).expect("a thread pool");
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target");
    let mut ours = (f64::INFINITY, None);
    let mut theirs: Vec<Result<(mitsuba::Render, f64), String>> = mitsuba::VARIANTS
        .iter()
        .map(|_| Err(String::new()))
        .collect();
    for round in 0..MITSUBA_ROUNDS {
        let mut acc = Accumulator::new(&camera, SEED);
        let start = Instant::now();
        let image = pool.install(|| {
            acc.render_pass(
                &scene,
                &camera,
                &settings,
                PixelSampling::Independent,
                MITSUBA_SPP,
            )
        });
        let seconds = start.elapsed().as_secs_f64();
        assert_eq!(acc.non_finite(), 0, "NaN or infinite samples");
        if seconds < ours.0 {
            ours = (seconds, Some(image.expect("pass")));
        }
        for (variant, best) in mitsuba::VARIANTS.iter().zip(&mut theirs) {
            if round > 0 && best.is_err() {
                continue;
            }
            let out = dir.join(format!("mitsuba_anchor_{variant}.pfm"));
            match mitsuba::render(variant, MITSUBA_VIEW, MITSUBA_SPP, SEED, &out) {
                Ok(r) => {
                    let per_sample = r.seconds / r.samples as f64;
                    if best.as_ref().map_or(true, |(_, p)| per_sample < *p) {
                        *best = Ok((r, per_sample));
                    }
                }
                Err(e) => *best = Err(e),
            }
        }
    }
    let (seconds, Some(image)) = ours else {
        return;
    };
    let samples = f64::from(width * height * MITSUBA_SPP);
    let per_sample = seconds / samples;
    println!(
        "  ours {:.2} us per path sample ({samples} samples in {seconds:.2} s)",
        per_sample * 1e6
    );
    for (variant, best) in mitsuba::VARIANTS.iter().zip(&theirs) {
        match best {
            Ok((render, theirs)) => {
                let z = mitsuba::z_of_means(&image, &render.image);
                if z.abs() > MITSUBA_Z {
                    println!(
                        "  ours / Mitsuba {variant}: skipped, its image's mean differs from \
                         ours by z = {z:.1}: not the same work"
                    );
                    continue;
                }
                println!(
                    "  Mitsuba {} {variant} {:.2} us: ours / Mitsuba {variant} {:.2}x (time per \
                     path sample, Mitsuba's over ours: above 1, ours is faster); the image \
                     means agree, z = {z:.2}",
                    render.version,
                    theirs * 1e6,
                    theirs / per_sample
                );
            }
            Err(e) => println!("  ours / Mitsuba {variant}: skipped, {e}"),
        }
    }
}
// ANCHOR_END: against_mitsuba

/// Samples per pixel of the variance analysis.
const VARIANCE_SPP: u32 = 256;

// ANCHOR: variance_analysis
/// Where the variance is: sigma^2 of one sample in every pixel for (a), NEE and MIS,
/// summed by what the camera sees first, and the speed-up each region allows. Time
/// to a given error is proportional to sigma^2 times the time per sample, so MIS
/// gains (sigma^2_a / sigma^2_MIS) x (time_a / time_MIS) where both are measured.
fn variance_analysis() {
    let Staged { scene, camera } =
        path_tracing::cornell(WIDTH, HEIGHT).expect("the Cornell box");
    let methods = [
        ("(a) cosine (smallpt)", Sampling::Cosine),
        ("(b1) NEE", Sampling::NextEvent),
        ("(b2) MIS", Sampling::Mis),
    ];
    let measured: Vec<_> = methods
        .iter()
        .map(|&(name, sampling)| {
            let v = pixel_variance(
                &scene,
                &camera,
                &settings(sampling),
                VARIANCE_SPP,
                SEED,
            )
            .expect("variance");
            (name, v)
        })
        .collect();
    let first = &measured[0].1;
    println!(
        "\nVariance of one sample per pixel ({VARIANCE_SPP} spp each, seed {SEED}), by what the \
         pixel's centre ray meets first:"
    );
    // Each method's numbers once: mean, diffuse, mirror/glass, lamp or nothing, the
    // top 1 %'s share (percent), mean without caustics.
    let numbers: Vec<[f64; 6]> = measured
        .iter()
        .map(|(_, v)| {
            let part = |seen| v.mean_in(&scene, seen);
            [
                v.mean(),
                part(Seen::Diffuse),
                part(Seen::Specular),
                part(Seen::LampOrNothing),
                100.0 * v.top_share(0.01),
                v.mean_without_caustics(),
            ]
        })
        .collect();
    // Methods as columns: the table stays four columns wide, narrow enough for a phone.
    let names: Vec<_> = measured.iter().map(|(name, _)| *name).collect();
    println!("| one sample's $\\sigma^2$ | {} |", names.join(" | "));
    println!("|---|{}", "---:|".repeat(names.len()));
    let share = |seen| 100.0 * first.pixels_seeing(&scene, seen);
    let labels = [
        "mean over the image".to_string(),
        format!("from diffuse pixels ({:.0}%)", share(Seen::Diffuse)),
        format!("from mirror/glass pixels ({:.0}%)", share(Seen::Specular)),
        "from the lamp or nothing".to_string(),
        "share in the top 1% of pixels".to_string(),
        "mean without caustics".to_string(),
    ];
    for (i, label) in labels.iter().enumerate() {
        let cells: Vec<_> = numbers
            .iter()
            .map(|n| match i {
                4 => format!("{:.0}%", n[i]),
                _ => format!("{:.4}", n[i]),
            })
            .collect();
        println!("| {label} | {} |", cells.join(" | "));
    }
    let means: Vec<_> = numbers.iter().map(|n| (n[0], n[1], n[2], n[5])).collect();
    let (a, mis) = (means[0], means[2]);
    println!(
        "sigma^2 ratio (a) / MIS: whole image {:.1}x, diffuse pixels {:.1}x, mirror/glass pixels {:.1}x",
        a.0 / mis.0,
        a.1 / mis.1,
        a.2 / mis.2
    );
    let caustics = mis.0 - mis.3;
    println!(
        "caustics (light reaching a diffuse surface through mirror or glass) are {:.0}% of MIS's \
         sigma^2; no light-sampling strategy finds them, so sigma^2 cannot fall below about \
         {caustics:.3}: (a)'s sigma^2 is at most {:.1}x that, the ceiling of any such strategy \
         at equal samples, divided by its extra time per sample at equal time",
        100.0 * caustics / mis.0,
        a.0 / caustics
    );
    println!(
        "(the three 'from' rows add up to the mean; 'without caustics' leaves their light out)"
    );
}
// ANCHOR_END: variance_analysis
