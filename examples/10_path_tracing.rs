//! Lesson 10: Monte Carlo path tracing, an estimator of Kajiya's rendering equation
//! (Lecture 2).
//!
//! smallpt's Cornell box rendered progressively at 1, 4, 16 and 64 samples per pixel,
//! each image compared with a reference of many more samples: the error (RMSE)
//! falls as 1/sqrt(N). A second table compares the four ways of sampling at the same
//! sample count.
//!
//!     cargo run --release --example 10_path_tracing
//!     cargo run --release --example 10_path_tracing -- --sampling cosine --spp 256 --jitter
//!     cargo run --release --example 10_path_tracing -- --scene two-lights --aperture 0.2

use std::process::ExitCode;
use std::time::Instant;

use clap::{Parser, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use render_lessons::Result;
use render_lessons::error::Error;
use render_lessons::framebuffer::Framebuffer;
use render_lessons::lesson::{self, Output, parse_finite};
use render_lessons::pathtrace::pfm::save_pfm;
use render_lessons::pathtrace::progressive::rmse;
use render_lessons::pathtrace::scenes;
use render_lessons::pathtrace::{
    Accumulator, LensCamera, PixelSampling, Sampling, Scene, Settings, SphereSampling,
};
use render_lessons::report::{Table, num};

/// The sampling strategies, as typed after `--sampling`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SamplingArg {
    /// Uniform directions over the hemisphere.
    Uniform,
    /// Cosine-weighted directions.
    Cosine,
    /// Cosine directions plus one light sample per bounce (next event estimation).
    Nee,
    /// Both, weighted by the power heuristic (multiple importance sampling).
    Mis,
}

impl SamplingArg {
    /// All four, worst first.
    pub const ALL: [SamplingArg; 4] = [
        SamplingArg::Uniform,
        SamplingArg::Cosine,
        SamplingArg::Nee,
        SamplingArg::Mis,
    ];

    fn sampling(self) -> Sampling {
        match self {
            SamplingArg::Uniform => Sampling::UniformHemisphere,
            SamplingArg::Cosine => Sampling::Cosine,
            SamplingArg::Nee => Sampling::NextEvent,
            SamplingArg::Mis => Sampling::Mis,
        }
    }

    fn name(self) -> &'static str {
        match self {
            SamplingArg::Uniform => "uniform hemisphere",
            SamplingArg::Cosine => "cosine",
            SamplingArg::Nee => "next event",
            SamplingArg::Mis => "MIS",
        }
    }
}

/// The scenes, as typed after `--scene`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SceneArg {
    /// smallpt's Cornell box, walls as planes, a square ceiling light.
    Cornell,
    /// A floor under a small and a large spherical light.
    TwoLights,
    /// Inside a glowing sphere of albedo 0.5 (STABILITY S16).
    Furnace,
    /// A grey sphere in a white environment (STABILITY S17).
    GreyFurnace,
}

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(
    about = "Lesson 10: Monte Carlo path tracing, progressive, with four sampling strategies"
)]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Image width in pixels.
    #[arg(long, default_value_t = 160)]
    pub width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 120)]
    pub height: u32,
    /// The largest sample count of the ladder 1, 4, 16, ... (powers of 4 up to it).
    #[arg(long, default_value_t = 64)]
    pub spp: u32,
    /// Samples per pixel of the reference image the errors are measured against.
    #[arg(long, default_value_t = 512)]
    pub reference_spp: u32,
    /// How directions are chosen at diffuse surfaces.
    #[arg(long, value_enum, default_value_t = SamplingArg::Mis)]
    pub sampling: SamplingArg,
    /// The scene.
    #[arg(long, value_enum, default_value_t = SceneArg::Cornell)]
    pub scene: SceneArg,
    /// Seed of the random streams (one per pixel). The images depend on it, not on
    /// the thread count.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Worker threads (default: every core).
    #[arg(long)]
    pub threads: Option<usize>,
    /// The most bounces a path may take.
    #[arg(long, default_value_t = 8)]
    pub max_depth: u32,
    /// Russian roulette on (the default; the last of --rr and --no-rr wins).
    #[arg(long = "rr", overrides_with = "no_rr")]
    pub rr: bool,
    /// Russian roulette off: every path runs to --max-depth unless it escapes.
    #[arg(long = "no-rr", overrides_with = "rr")]
    pub no_rr: bool,
    /// Jittered (stratified) pixel samples instead of independent ones; every
    /// sample count of the ladder is then a square, as it must be.
    #[arg(long)]
    pub jitter: bool,
    /// Lens radius of the thin-lens camera (0: pinhole).
    #[arg(long, default_value = "0", value_parser = parse_finite)]
    pub aperture: f32,
    /// Distance of the plane in focus (only used with an aperture); the default is
    /// about the distance of the Cornell box's glass sphere from the camera.
    #[arg(long, default_value = "220", value_parser = parse_finite)]
    pub focus: f32,
    #[command(flatten)]
    pub output: Output,
}

// ANCHOR: setup
/// The chosen scene and its camera, with the chosen lens.
pub fn scene(args: &Args) -> Result<(Scene, LensCamera)> {
    let (w, h) = (args.width, args.height);
    let (scene, camera) = match args.scene {
        SceneArg::Cornell => scenes::cornell(w, h)?,
        SceneArg::TwoLights => scenes::two_lights(w, h)?,
        SceneArg::Furnace => scenes::interior_furnace(w, h)?,
        SceneArg::GreyFurnace => scenes::grey_furnace(w, h, glam::Vec3::ZERO)?,
    };
    let camera = if args.aperture == 0.0 {
        camera
    } else {
        camera.with_lens(args.aperture, args.focus)?
    };
    Ok((scene, camera))
}

/// The estimator's settings for `sampling` and the flags.
pub fn settings(args: &Args, sampling: SamplingArg) -> Settings {
    Settings {
        sampling: sampling.sampling(),
        sphere_lights: SphereSampling::Cone,
        max_depth: Some(args.max_depth),
        russian_roulette: !args.no_rr,
        ..Settings::default()
    }
}
// ANCHOR_END: setup

fn pixel_sampling(args: &Args) -> PixelSampling {
    if args.jitter {
        PixelSampling::Jittered
    } else {
        PixelSampling::Independent
    }
}

/// 1, 4, 16, ... up to `spp` (`spp` itself last if it is not a power of 4).
pub fn ladder(spp: u32) -> Result<Vec<u32>> {
    if spp == 0 {
        return Err(Error::TooFew {
            param: "spp",
            value: 0,
            min: 1,
        });
    }
    let mut steps: Vec<u32> = std::iter::successors(Some(1u32), |n| n.checked_mul(4))
        .take_while(|&n| n <= spp)
        .collect();
    if steps.last() != Some(&spp) {
        steps.push(spp);
    }
    Ok(steps)
}

/// The images of one progressive render and how they were made.
pub struct Renders {
    /// (samples per pixel, image) for each rung of the ladder, with the chosen sampling.
    pub ladder: Vec<(u32, Framebuffer)>,
    /// (strategy, image at the ladder's largest count) for every strategy.
    pub strategies: Vec<(SamplingArg, Framebuffer)>,
    /// The reference: MIS at `reference_spp`.
    pub reference: Framebuffer,
    /// Samples that came out NaN or infinite (and were dropped): should be 0.
    pub non_finite: u64,
}

// ANCHOR: progressive
/// Renders `total` samples per pixel with `sampling` in passes, calling `each` with the
/// image after every pass that ends on one of `stops`.
fn progressive(
    args: &Args,
    sampling: SamplingArg,
    seed: u64,
    stops: &[u32],
    bar: &ProgressBar,
    mut each: impl FnMut(u32, Framebuffer) -> Result<()>,
) -> Result<u64> {
    let (scene, camera) = scene(args)?;
    let settings = settings(args, sampling);
    let mut acc = Accumulator::new(&camera, seed);
    for &stop in stops {
        let spp = stop - acc.samples();
        let pixels = pixel_sampling(args);
        let image = acc.render_pass(&scene, &camera, &settings, pixels, spp, args.threads)?;
        bar.inc(u64::from(spp));
        each(stop, image)?;
    }
    Ok(acc.non_finite())
}
// ANCHOR_END: progressive

/// Pass boundaries for the reference: 16 samples at a time, so its file can be
/// rewritten (atomically) as it sharpens.
fn reference_stops(spp: u32) -> Vec<u32> {
    let mut stops: Vec<u32> = (1..=spp / 16).map(|i| i * 16).collect();
    if stops.last() != Some(&spp) {
        stops.push(spp);
    }
    stops
}

/// Every image of the lesson. The ladder is one progressive render (passes of 1, 3,
/// 12, 48 samples); with `--jitter` each rung is rendered afresh instead, because
/// jittered passes need a square number of samples (1, 4, 16, 64 are; 3, 12, 48 are
/// not). The reference is rendered in passes of 16 with its own seed, its PNG
/// rewritten (atomically) after each.
pub fn render_all(args: &Args, bar: &ProgressBar) -> Result<Renders> {
    let steps = ladder(args.spp)?;
    if args.reference_spp == 0 {
        return Err(Error::TooFew {
            param: "reference-spp",
            value: 0,
            min: 1,
        });
    }
    let mut ladder_images = Vec::new();
    let passes: Vec<&[u32]> = if args.jitter {
        steps.chunks(1).collect()
    } else {
        vec![&steps]
    };
    let mut non_finite = 0;
    for stops in passes {
        non_finite += progressive(args, args.sampling, args.seed, stops, bar, |n, img| {
            ladder_images.push((n, img));
            Ok(())
        })?;
    }
    let mut strategies = Vec::new();
    for s in SamplingArg::ALL {
        if s == args.sampling {
            let last = ladder_images.last().map(|(_, img)| img.clone());
            strategies.extend(last.map(|img| (s, img)));
            continue;
        }
        non_finite += progressive(args, s, args.seed, &[args.spp], bar, |_, img| {
            strategies.push((s, img));
            Ok(())
        })?;
    }
    let mut reference = None;
    let reference_seed = args.seed.wrapping_add(0x9e37_79b9);
    let stops = reference_stops(args.reference_spp);
    non_finite += progressive(
        args,
        SamplingArg::Mis,
        reference_seed,
        &stops,
        bar,
        |_, img| {
            img.save_png(&args.output.file("10_reference.png"))?;
            reference = Some(img);
            Ok(())
        },
    )?;
    Ok(Renders {
        ladder: ladder_images,
        strategies,
        reference: reference.ok_or(Error::TooFew {
            param: "reference-spp",
            value: 0,
            min: 1,
        })?,
        non_finite,
    })
}

/// The total number of samples per pixel [`render_all`] takes, for the progress bar.
pub fn total_samples(args: &Args) -> u64 {
    let ladder = if args.jitter {
        ladder(args.spp).map_or(0, |l| l.iter().map(|&n| u64::from(n)).sum())
    } else {
        u64::from(args.spp)
    };
    ladder + 3 * u64::from(args.spp) + u64::from(args.reference_spp)
}

// ANCHOR: numbers
/// The lesson's tables: error against the reference as samples grow, and the four
/// strategies side by side. Independent of timing and thread count.
pub fn numbers(args: &Args, renders: &Renders) -> Result<String> {
    let mut ladder = Table::new(
        &format!(
            "{:?} scene, {} x {}, {} sampling{}: RMSE against a {}-sample MIS reference",
            args.scene,
            args.width,
            args.height,
            args.sampling.name(),
            if args.jitter { ", jittered" } else { "" },
            args.reference_spp
        ),
        &["spp", "RMSE", "RMSE x sqrt(spp)", "mean"],
    );
    for (spp, image) in &renders.ladder {
        let e = rmse(image, &renders.reference);
        ladder.row(vec![
            spp.to_string(),
            num(e, 5),
            num(e * f64::from(*spp).sqrt(), 4),
            num(mean(image), 5),
        ]);
    }
    let mut strategies = Table::new(
        &format!("The four strategies at {} spp", args.spp),
        &["sampling", "RMSE", "mean"],
    );
    for (s, image) in &renders.strategies {
        strategies.row(vec![
            s.name().to_string(),
            num(rmse(image, &renders.reference), 5),
            num(mean(image), 5),
        ]);
    }
    Ok(format!(
        "{ladder}\n{strategies}\nreference mean {}; samples dropped as NaN or infinite: {}\n",
        num(mean(&renders.reference), 5),
        renders.non_finite
    ))
}
// ANCHOR_END: numbers

/// The mean of all channels of all pixels.
pub fn mean(image: &Framebuffer) -> f64 {
    let mut sum = 0.0;
    for y in 0..image.height() {
        for x in 0..image.width() {
            let c = image.get(x, y).unwrap_or_default().as_dvec3();
            sum += c.x + c.y + c.z;
        }
    }
    sum / (3.0 * f64::from(image.width()) * f64::from(image.height()))
}

fn progress_bar(total: u64) -> ProgressBar {
    let bar = ProgressBar::new(total);
    if let Ok(style) =
        ProgressStyle::with_template("{bar:40} {pos}/{len} samples per pixel, {eta} left")
    {
        bar.set_style(style);
    }
    bar
}

fn main() -> ExitCode {
    let args = Args::parse();
    lesson::run(|| {
        let start = Instant::now();
        let bar = progress_bar(total_samples(&args));
        let renders = render_all(&args, &bar)?;
        bar.finish_and_clear();
        let seconds = start.elapsed().as_secs_f64();
        lesson::print(&numbers(&args, &renders)?);
        lesson::print(&format!("rendered in {seconds:.1} s\n"));
        for (spp, image) in &renders.ladder {
            args.output.image(&format!("10_{spp}spp.png"), image)?;
        }
        for (s, image) in &renders.strategies {
            args.output
                .image(&format!("10_{:?}.png", s).to_lowercase(), image)?;
        }
        args.output.image("10_reference.png", &renders.reference)?;
        let pfm = args.output.file("10_reference.pfm");
        save_pfm(&pfm, &renders.reference)?;
        lesson::wrote(&pfm);
        Ok(())
    })
}
