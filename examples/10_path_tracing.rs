//! Lesson 10: Monte Carlo path tracing, an estimator of Kajiya's rendering equation
//! (Lecture 2).
//!
//! smallpt's Cornell box rendered progressively at 1, 4, 16 and 64 samples per pixel,
//! each image compared with a reference of many more samples: the error (RMSE)
//! falls as 1/sqrt(N). A second table compares the four ways of sampling at the same
//! sample count. The estimator itself is `radiance` in src/pathtrace/estimator.rs.
//!
//!     cargo run --release --example 10_path_tracing
//!     cargo run --release --example 10_path_tracing -- --sampling cosine --spp 256 --jitter
//!     cargo run --release --example 10_path_tracing -- --scene two-lights --aperture 0.2

use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use indicatif::ProgressBar;
use render_lessons::Result;
use render_lessons::camera::Camera;
use render_lessons::course::ladder_figure::ladder_figure;
use render_lessons::course::lesson::{self, Output, parse_finite};
use render_lessons::course::report::{Table, num};
use render_lessons::error::positive;
use render_lessons::pathtrace::convergence::{Part, Renders, Study, ladder};
use render_lessons::pathtrace::pfm::save_pfm;
use render_lessons::pathtrace::progressive::rmse;
use render_lessons::pathtrace::scenes::SceneName;
use render_lessons::pathtrace::{Passes, PixelSampling, Sampling, Settings};
use render_lessons::scene::Scene;

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 10: Monte Carlo path tracing, four sampling strategies")]
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
    #[arg(long, value_enum, default_value_t = Sampling::Mis)]
    pub sampling: Sampling,
    /// The scene.
    #[arg(long, value_enum, default_value_t = SceneName::Cornell)]
    pub scene: SceneName,
    /// Seed of the random streams (one per pixel); the images do not depend on --threads.
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
    /// Jittered (stratified) pixel samples; every sample count must then be a square.
    #[arg(long)]
    pub jitter: bool,
    /// Lens radius of the thin-lens camera (0: pinhole).
    #[arg(long, default_value = "0", value_parser = parse_finite)]
    pub aperture: f32,
    /// Distance of the plane in focus (default: about that of the Cornell box's glass sphere).
    #[arg(long, default_value = "220", value_parser = parse_finite)]
    pub focus: f32,
    #[command(flatten)]
    pub output: Output,
}

// ANCHOR: numbers
/// The lesson's tables for the `scene`: error against the reference as samples grow,
/// and the four strategies side by side. Independent of timing and thread count.
pub fn numbers(scene: SceneName, study: &Study, renders: &Renders) -> String {
    let r = &renders.reference;
    let jitter = study.passes.pixels == PixelSampling::Jittered;
    let mut ladder = Table::new(
        &format!(
            "{scene:?} scene, {} x {}, {} sampling{}: RMSE against a {}-sample MIS reference",
            r.width(),
            r.height(),
            study.settings.sampling.name(),
            if jitter { ", jittered" } else { "" },
            study.reference_spp
        ),
        &["spp", "RMSE", "RMSE x sqrt(spp)", "mean"],
    );
    for (spp, image) in &renders.ladder {
        let e = rmse(image, r);
        let scaled = e * f64::from(*spp).sqrt();
        let mean = num(image.mean(), 5);
        ladder.row(vec![spp.to_string(), num(e, 5), num(scaled, 4), mean]);
    }
    let top = study.ladder.last().copied().unwrap_or(0);
    let title = format!("The four strategies at {top} spp");
    let mut strategies = Table::new(&title, &["sampling", "RMSE", "mean"]);
    for (s, image) in &renders.strategies {
        let e = rmse(image, r);
        strategies.row(vec![s.name().to_string(), num(e, 5), num(image.mean(), 5)]);
    }
    format!(
        "{ladder}\n{strategies}\nreference mean {}; samples dropped as NaN or infinite: {}\n",
        num(r.mean(), 5),
        renders.non_finite
    )
}
// ANCHOR_END: numbers

// ANCHOR: setup
/// What the flags ask for: the scene, its camera (a thin lens when `--aperture` is
/// not 0) and the study to run on them.
pub fn setup(args: &Args) -> Result<(Scene, Camera, Study)> {
    // At most 11 rungs, 3 strategies, the reference and two f64 accumulators.
    let threads = lesson::budget(args.width, args.height, args.threads, 20)?;
    let (scene, pinhole) = args.scene.build(args.width, args.height)?;
    positive("focus", args.focus)?; // checked even when no lens uses it
    let camera = match args.aperture {
        0.0 => pinhole,
        aperture => pinhole.with_lens(aperture, args.focus)?,
    };
    let study = Study {
        settings: Settings {
            sampling: args.sampling,
            max_depth: Some(args.max_depth),
            russian_roulette: !args.no_rr,
            ..Settings::default()
        },
        ladder: ladder(args.spp)?,
        passes: Passes {
            pixels: PixelSampling::jittered(args.jitter),
            seed: args.seed,
            threads,
        },
        reference_spp: args.reference_spp,
    };
    Ok((scene, camera, study))
}
// ANCHOR_END: setup

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| {
        let start = Instant::now();
        // ANCHOR: render
        let (scene, camera, study) = setup(&args)?;
        let bar = ProgressBar::new(study.samples());
        let (out, top) = (&args.output, study.ladder.last().copied().unwrap_or(0));
        let mut reference_spp = 0;
        lesson::stop_on_ctrl_c();
        // Each image is written the moment it is finished (Ctrl-C keeps them), the
        // reference after every pass: watch it sharpen.
        let renders = study.render(&scene, &camera, |part, pass| {
            bar.inc(u64::from(pass.added));
            let (image, spp) = (&pass.image, pass.samples);
            match part {
                Part::Ladder if spp == top => {
                    out.image(&format!("10_{spp}spp.png"), image)?;
                    out.image(&format!("10_{}.png", args.sampling.flag()), image)?
                }
                Part::Ladder => out.image(&format!("10_{spp}spp.png"), image)?,
                Part::Strategy(s) => out.image(&format!("10_{}.png", s.flag()), image)?,
                Part::Reference => {
                    image.save_png(&out.file("10_reference.png"))?;
                    reference_spp = spp;
                }
            }
            lesson::check_interrupt()
        });
        // ANCHOR_END: render
        bar.finish_and_clear();
        let renders = renders.inspect_err(|_| {
            if reference_spp > 0 && reference_spp < args.reference_spp {
                eprintln!("10_reference.png is partial: {reference_spp} samples per pixel");
            }
        })?;
        let seconds = start.elapsed().as_secs_f64();
        lesson::print(&numbers(args.scene, &study, &renders));
        lesson::print(&format!("rendered in {seconds:.1} s\n"));
        lesson::wrote(&out.file("10_reference.png"));
        out.diagram("10_convergence.png", &ladder_figure(&renders.ladder)?)?;
        let pfm = out.file("10_reference.pfm");
        save_pfm(&pfm, &renders.reference)?;
        lesson::wrote(&pfm);
        Ok(())
    })
}
